#include <glint/core/cancel.h>
#include <glint/core/progress.h>
#include <glint/integrator/radiosity/radiosity_solver.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/scene/scene.h>

#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace glint {
namespace {

using Sides = std::array<Spectrum, 2>;

// How bright a radiosity is, for choosing the next shooter, stopping, and splitting elements:
// its luminance in RGB mode; in spectral mode (one solve per set of wavelengths) the mean of
// its wavelengths' values, which needs no colour matching per patch and per shot.
float brightness(const Spectrum& s) {
    return spectral_mode_active() ? s.average() : s.luminance();
}

// The solve's state: the mesh and what the current shot gives each vertex.
class Solver {
public:
    Solver(const Scene& scene, RadiosityMesh& mesh, const RadiositySettings& settings,
           uint64_t seed)
        : m_scene(scene), m_mesh(mesh), m_settings(settings), m_seed(seed) {
        m_element_size = settings.element_size > 0.0f
                             ? settings.element_size
                             : radiosity_patch_size(scene, settings) / 8.0f;
    }

    // Every light that no patch stands for shoots once: the irradiance at each vertex from
    // `samples` points of Light::sample_li (one for delta lights), with shadow rays.
    int shoot_lights() {
        int shot = 0;
        for (const auto& light : m_scene.lights()) {
            const bool meshed = std::find(m_mesh.meshed_lights.begin(), m_mesh.meshed_lights.end(),
                                          light.get()) != m_mesh.meshed_lights.end();
            // Environment light is left to the display pass (see docs/integrators.md).
            if (meshed || (light->is_infinite() && !light->is_delta())) continue;
            const int samples = light->is_delta() ? 1 : m_settings.shooter_samples;
            shoot([&](const RadiosityVertex& x, Rng& rng, Sides& delta, Sides& direct,
                      uint64_t& rays) {
                Sides irradiance{Spectrum(0.0f), Spectrum(0.0f)};
                for (int k = 0; k < samples; ++k) {
                    const Vec2 u((static_cast<float>(k) + rng.next_float()) / samples,
                                 rng.next_float());
                    const float u_select = rng.next_float();
                    const std::optional<LightSample> ls = light->sample_li(x.p, u, u_select);
                    if (!ls || ls->L.is_black() || !(ls->pdf > 0.0f)) continue;
                    const float c = glm::dot(x.n, ls->wi);
                    if (c == 0.0f) continue;
                    const int side = c > 0.0f ? 0 : 1;
                    const Vec3 from = offset_ray_origin(x.p, side ? -x.n : x.n, ls->wi);
                    ++rays;
                    const Spectrum visible = transmittance(m_scene, from, ls->p);
                    if (visible.is_black()) continue;
                    irradiance[side] += ls->L * (std::abs(c) / ls->pdf) * visible;
                }
                for (int s = 0; s < 2; ++s) {
                    delta[s] = x.rho * irradiance[s] / static_cast<float>(samples);
                    direct[s] = delta[s];
                }
            });
            ++shot;
        }
        return shot;
    }

    // The unshot power of every patch side (luminance times area), summed.
    double unshot_power() const {
        double sum = 0.0;
        for (const RadiosityPatch& p : m_mesh.patches)
            sum += (brightness(p.unshot[0]) + brightness(p.unshot[1])) * p.triangle.area;
        return sum;
    }

    // Progressive refinement's step: the patch side with the most unshot power shoots it
    // all. False when nothing is left to shoot.
    bool shoot_next() {
        double best = 0.0;
        size_t best_patch = 0;
        int best_side = 0;
        for (size_t i = 0; i < m_mesh.patches.size(); ++i) {
            for (int s = 0; s < 2; ++s) {
                const double power =
                    brightness(m_mesh.patches[i].unshot[s]) * m_mesh.patches[i].triangle.area;
                if (power > best) {
                    best = power;
                    best_patch = i;
                    best_side = s;
                }
            }
        }
        if (!(best > 0.0)) return false;
        RadiosityPatch& patch = m_mesh.patches[best_patch];
        const Spectrum unshot = patch.unshot[best_side];
        const Spectrum emission = patch.unshot_emission[best_side];
        patch.unshot[best_side] = patch.unshot_emission[best_side] = Spectrum(0.0f);
        ShootingTriangle source = patch.triangle;
        if (best_side == 1) source.n = -source.n;
        const Vec3 centroid = (source.a + source.b + source.c) / 3.0f;
        const int samples = m_settings.shooter_samples;
        shoot([&](const RadiosityVertex& x, Rng& rng, Sides& delta, Sides& direct, uint64_t& rays) {
            const int side = glm::dot(x.n, centroid - x.p) >= 0.0f ? 0 : 1;
            const double f = point_to_triangle_form_factor(x.p, side ? -x.n : x.n, source, samples,
                                                           rng, &m_scene, rays);
            if (!(f > 0.0)) return;
            delta[side] = x.rho * unshot * static_cast<float>(f);
            direct[side] = x.rho * emission * static_cast<float>(f);
        });
        return true;
    }

    // Cohen et al.'s ambient term: the unshot radiosity, averaged over the surfaces, times
    // the interreflection factor 1 / (1 - mean reflectance) it would still gather.
    Spectrum ambient() const {
        double area = 0.0;
        Spectrum rho_area(0.0f), unshot_area(0.0f);
        for (const RadiosityPatch& p : m_mesh.patches) {
            area += p.triangle.area;
            rho_area += p.rho * p.triangle.area;
            unshot_area += (p.unshot[0] + p.unshot[1]) * p.triangle.area;
        }
        if (!(area > 0.0)) return Spectrum(0.0f);
        return map(rho_area, unshot_area, [area](float rho_a, float unshot_a) {
            const double rho = std::min(0.999, rho_a / area);
            return static_cast<float>(unshot_a / area / (1.0 - rho));
        });
    }

    uint64_t rays() const { return m_rays.load(); }

private:
    // One shot: `receive(vertex, rng, delta, direct, rays)` says what a vertex gets (per
    // side; `direct` the part that is emission). Elements whose vertices the shot changes
    // unevenly split, and their new vertices receive the shot too; then the shot is added
    // to the vertices and, as element averages, to the patches' unshot radiosity.
    template <typename Receive>
    void shoot(Receive&& receive) {
        const uint64_t shot = m_shot++;
        m_delta.assign(m_mesh.vertices.size(), Sides{Spectrum(0.0f), Spectrum(0.0f)});
        m_direct.assign(m_mesh.vertices.size(), Sides{Spectrum(0.0f), Spectrum(0.0f)});
        compute(receive, shot, 0, m_mesh.vertices.size());

        std::vector<uint32_t> candidates;
        for (uint32_t e = 0; e < m_mesh.elements.size(); ++e)
            if (m_mesh.elements[e].first_child < 0) candidates.push_back(e);
        while (!candidates.empty()) {
            std::vector<uint32_t> children;
            const size_t first_vertex = m_mesh.vertices.size();
            for (uint32_t e : candidates) {
                if (m_mesh.elements.size() + 4 > static_cast<size_t>(m_settings.max_elements))
                    break;
                if (!needs_split(e)) continue;
                const uint32_t first = m_mesh.split(e);
                for (uint32_t c = first; c < first + 4; ++c) children.push_back(c);
            }
            m_delta.resize(m_mesh.vertices.size(), Sides{Spectrum(0.0f), Spectrum(0.0f)});
            m_direct.resize(m_mesh.vertices.size(), Sides{Spectrum(0.0f), Spectrum(0.0f)});
            compute(receive, shot, first_vertex, m_mesh.vertices.size());
            candidates = std::move(children);
        }

        for (size_t v = 0; v < m_mesh.vertices.size(); ++v) {
            for (int s = 0; s < 2; ++s) {
                m_mesh.vertices[v].b[s] += m_delta[v][s];
                m_mesh.vertices[v].b_direct[s] += m_direct[v][s];
            }
        }
        for (const RadiosityElement& e : m_mesh.elements) {
            if (e.first_child >= 0) continue;
            RadiosityPatch& patch = m_mesh.patches[e.patch];
            if (!(patch.triangle.area > 0.0f)) continue;
            const float weight = e.area / (3.0f * patch.triangle.area);
            for (int s = 0; s < 2; ++s) {
                patch.unshot[s] +=
                    (m_delta[e.v[0]][s] + m_delta[e.v[1]][s] + m_delta[e.v[2]][s]) * weight;
            }
        }
    }

    template <typename Receive>
    void compute(Receive& receive, uint64_t shot, size_t begin, size_t end) {
        if (begin >= end) return;
        // Spectral mode: the solve's wavelengths are the calling thread's; the workers take
        // them on.
        const WavelengthContext* wavelengths = detail::t_active_wavelengths;
        tbb::parallel_for(tbb::blocked_range<size_t>(begin, end, 64),
                          [&](const tbb::blocked_range<size_t>& range) {
                              std::optional<WavelengthScope> scope;
                              if (wavelengths != nullptr) scope.emplace(*wavelengths);
                              uint64_t rays = 0;
                              for (size_t v = range.begin(); v < range.end(); ++v) {
                                  Rng rng(hash_combine(hash_combine(m_seed, shot), v));
                                  receive(m_mesh.vertices[v], rng, m_delta[v], m_direct[v], rays);
                              }
                              m_rays.fetch_add(rays, std::memory_order_relaxed);
                          });
    }

    // Whether the current shot changes the luminance across leaf `e` by more than the
    // subdivision threshold times the largest radiosity at its vertices, on either side,
    // and the element is still coarser than twice the smallest element size.
    bool needs_split(uint32_t e) const {
        const RadiosityElement& element = m_mesh.elements[e];
        if (element.first_child >= 0) return false;
        for (int s = 0; s < 2; ++s) {
            float lo = kInfinity, hi = -kInfinity, top = 0.0f;
            for (uint32_t v : element.v) {
                const float d = brightness(m_delta[v][s]);
                lo = std::min(lo, d);
                hi = std::max(hi, d);
                top = std::max(top, brightness(m_mesh.vertices[v].b[s] + m_delta[v][s]));
            }
            if (hi - lo > m_settings.subdivide * top && top > 0.0f &&
                m_mesh.longest_edge(e) >= 2.0f * m_element_size)
                return true;
        }
        return false;
    }

    const Scene& m_scene;
    RadiosityMesh& m_mesh;
    const RadiositySettings& m_settings;
    uint64_t m_seed;
    float m_element_size = 0.0f;
    uint64_t m_shot = 0;
    std::vector<Sides> m_delta, m_direct;
    std::atomic<uint64_t> m_rays{0};
};

}  // namespace

RadiositySettings RadiositySettings::read(const Params& p) {
    RadiositySettings s;
    s.patch_size = p.get_float("radiosity_patch_size", s.patch_size);
    s.element_size = p.get_float("radiosity_element_size", s.element_size);
    s.subdivide = p.get_float("radiosity_subdivide", s.subdivide);
    s.shooter_samples = p.get_int("radiosity_samples", s.shooter_samples);
    s.unshot = p.get_float("radiosity_unshot", s.unshot);
    s.max_shots = p.get_int("radiosity_max_shots", s.max_shots);
    s.max_elements = p.get_int("radiosity_max_elements", s.max_elements);
    s.ambient = p.get_bool("radiosity_ambient", s.ambient);
    if (!(s.patch_size >= 0.0f) || !std::isfinite(s.patch_size))
        p.fail_at("radiosity_patch_size", "'radiosity_patch_size' must be >= 0 (0: automatic)");
    if (!(s.element_size >= 0.0f) || !std::isfinite(s.element_size))
        p.fail_at("radiosity_element_size", "'radiosity_element_size' must be >= 0 (0: automatic)");
    if (!(s.subdivide >= 0.0f && s.subdivide <= 1.0f))
        p.fail_at("radiosity_subdivide", "'radiosity_subdivide' must be in [0, 1]");
    if (s.shooter_samples < 1 || s.shooter_samples > 4096)
        p.fail_at("radiosity_samples", "'radiosity_samples' must be in [1, 4096]");
    if (!(s.unshot >= 0.0f && s.unshot < 1.0f))
        p.fail_at("radiosity_unshot", "'radiosity_unshot' must be in [0, 1)");
    if (s.max_shots < 0) p.fail_at("radiosity_max_shots", "'radiosity_max_shots' must be >= 0");
    if (s.max_elements < 1)
        p.fail_at("radiosity_max_elements", "'radiosity_max_elements' must be >= 1");
    return s;
}

float radiosity_patch_size(const Scene& scene, const RadiositySettings& settings) {
    if (settings.patch_size > 0.0f) return settings.patch_size;
    const Bounds3& bounds = scene.stats().bounds;
    const float diagonal = bounds.is_empty() ? 1.0f : glm::length(bounds.extent());
    return std::max(diagonal, 1e-6f) / 6.0f;
}

RadiositySolveStats solve_radiosity(const Scene& scene, RadiosityMesh& mesh,
                                    const RadiositySettings& settings, uint64_t seed,
                                    Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    RadiositySolveStats stats;
    Solver solver(scene, mesh, settings, seed);
    stats.light_shots = solver.shoot_lights();
    const double reference = solver.unshot_power();
    double unshot = reference;
    // Progress in percent of the way, on a log scale, from all the light unshot to the
    // stopping fraction.
    const double goal = std::log(std::max(1e-6, static_cast<double>(settings.unshot)));
    uint64_t shown = 0;
    while (reference > 0.0 && stats.shots < settings.max_shots &&
           unshot > settings.unshot * reference) {
        throw_if_cancelled();  // one shot can take long in a big scene; SIGINT stops it here
        if (!solver.shoot_next()) break;
        ++stats.shots;
        unshot = solver.unshot_power();
        const double done =
            std::clamp(std::log(std::max(unshot / reference, 1e-300)) / goal, 0.0, 1.0);
        const uint64_t percent = static_cast<uint64_t>(100.0 * done);
        if (percent > shown) {
            progress.advance(percent - shown);
            shown = percent;
        }
    }
    if (shown < 100) progress.advance(100 - shown);
    mesh.ambient = settings.ambient ? solver.ambient() : Spectrum(0.0f);
    stats.rays = solver.rays();
    stats.unshot_fraction = reference > 0.0 ? unshot / reference : 0.0;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace glint
