#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/core/sampler.h>
#include <glint/integrator/path/whitted.h>
#include <glint/integrator/photon/photon.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>
#include <glint/material/material.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <vector>

namespace glint {
namespace {

constexpr int kDefaultMaxDepth = 10;
// Whitted recurses once per mirror or glass bounce (and branches at glass): a hard maximum
// keeps the recursion off the stack's end.
constexpr int kMaxWhittedDepth = 64;

float fract(float x) {
    return x - std::floor(x);
}

struct ShadowSample {
    Spectrum contribution;  // unoccluded f L cos / pdf
    Vec3 target;
    int visible = -1;  // -1 unknown, 0 blocked, 1 clear
};

// Indices of the samples farthest out along the four diagonals of a plane facing `p`
// (-1 where there is no sample with a contribution).
std::array<int, 4> extreme_samples(const std::vector<ShadowSample>& samples, const Vec3& p) {
    Vec3 centroid(0.0f);
    int used = 0;
    for (const ShadowSample& s : samples) {
        if (s.contribution.is_black()) continue;
        centroid += s.target;
        ++used;
    }
    std::array<int, 4> best = {-1, -1, -1, -1};
    if (used == 0) return best;
    centroid /= static_cast<float>(used);
    const Frame frame = Frame::from_normal(glm::normalize(centroid - p));
    std::array<float, 4> best_score;
    best_score.fill(-kInfinity);
    for (int k = 0; k < static_cast<int>(samples.size()); ++k) {
        if (samples[k].contribution.is_black()) continue;
        const Vec3 d = samples[k].target - centroid;
        const float a = glm::dot(d, frame.s()), b = glm::dot(d, frame.t());
        const float scores[4] = {a + b, a - b, -a + b, -a - b};
        for (int q = 0; q < 4; ++q) {
            if (scores[q] > best_score[q]) {
                best_score[q] = scores[q];
                best[q] = k;
            }
        }
    }
    return best;
}

}  // namespace

WhittedSettings WhittedSettings::read(const Params& p) {
    WhittedSettings s;
    const Rgb ambient = p.get_rgb("ambient", s.ambient.rgb());
    s.shadow_samples = p.get_int("shadow_samples", s.shadow_samples);
    s.penumbra_shortcut = p.get_bool("penumbra_shortcut", s.penumbra_shortcut);
    s.caustics = p.get_bool("caustics", s.caustics);
    s.caustic = CausticSettings::read(p);
    if (ambient.min_value() < 0.0f) p.fail_at("ambient", "'ambient' must not be negative");
    s.ambient = SceneColor(ambient, RgbRole::illuminant);
    if (s.shadow_samples < 1 || s.shadow_samples > 64)
        p.fail_at("shadow_samples", "'shadow_samples' must be in [1, 64]");
    return s;
}

std::unique_ptr<Integrator> WhittedIntegrator::create(const RenderSettings& settings,
                                                      const Params& params) {
    const WhittedSettings whitted = WhittedSettings::read(params);
    const bool photons_view =
        std::find(settings.debug.begin(), settings.debug.end(), "photons") != settings.debug.end();
    if (photons_view && !whitted.caustics) {
        throw Error(
            fmt::format("{}: the photons view with integrator 'whitted' needs caustics = true "
                        "(the view shows its caustic map)",
                        settings.where_of("debug")));
    }
    return std::make_unique<WhittedIntegrator>(settings, whitted);
}

WhittedIntegrator::WhittedIntegrator(const RenderSettings& settings, const WhittedSettings& whitted)
    : TileIntegrator(settings),
      m_whitted(whitted),
      m_max_depth(settings.max_depth >= 0 ? settings.max_depth : kDefaultMaxDepth) {}

uint64_t WhittedIntegrator::prepare(const Scene& scene) {
    // Checked here, not in create(), which also runs to learn which keys whitted reads.
    if (m_max_depth > kMaxWhittedDepth) {
        throw Error(
            fmt::format("{}: whitted follows mirrors and glass by recursion: 'max_depth' "
                        "must be at most {}, got {}",
                        m_settings.where_of("max_depth"), kMaxWhittedDepth, m_max_depth));
    }
    uint64_t photon_rays = 0;
    if (m_whitted.caustics) {
        m_sets = photon_wavelength_sets(m_settings, m_whitted.caustic);
        m_caustics = build_caustic_map(scene, m_settings, m_whitted.caustic, m_sets, photon_rays);
        m_caustic_radius2 = photon_search_radius2(scene, m_whitted.caustic);
    }
    return photon_rays;
}

RenderStats WhittedIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    RenderStats stats = TileIntegrator::render(scene, film, progress);
    if (m_whitted.caustics)
        stats.notes.push_back(fmt::format("caustic map: {} photons", m_caustics.size()));
    for (const std::string& view : m_settings.debug) {
        if (view != "photons" || !m_whitted.caustics) continue;
        // The debug view, as the photon integrator's: what the caustic map alone says at
        // each diffuse hit seen directly or through mirrors and glass.
        add_luminance_view(scene, film, m_show_photons, "photons.Y", stats);
    }
    return stats;
}

Spectrum WhittedIntegrator::li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                               RayCounter& counter, AovSample* aov) const {
    int budget = kWhittedRayBudget;
    return trace(ray, scene, sampler, arena, counter, aov, 0, budget);
}

Spectrum WhittedIntegrator::trace(const Ray& ray, const Scene& scene, Sampler& sampler,
                                  Arena& arena, RayCounter& counter, AovSample* aov, int depth,
                                  int& budget) const {
    ++counter.rays;
    --budget;
    std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    if (!hit) {
        const Spectrum escaped = scene.escaped_radiance(ray.direction);
        if (aov) *aov = AovSample{escaped, Vec3(0.0f), kInfinity};
        return escaped;
    }
    SurfaceInteraction& si = *hit;
    const Bsdf* bsdf = shade(scene, ray, si, arena);
    if (aov) *aov = AovSample{si.material->albedo(si), si.shading.n(), si.t};

    Spectrum L = m_show_photons ? Spectrum(0.0f) : emitted_radiance(si);
    // Like the path tracer's max_depth: scattering at vertex `depth` is computed only below
    // the limit, so both integrators mean the same by it (and agree where both are exact).
    if (bsdf && depth < m_max_depth) {
        const Vec3 wo_local = si.to_local(si.wo);
        if (!bsdf->is_delta() && m_show_photons) {
            L += radiance_estimate(m_caustics, si, *bsdf, m_whitted.caustic.photon_neighbours,
                                   m_caustic_radius2, m_sets);
        } else if (!bsdf->is_delta()) {
            L += direct(scene, si, *bsdf, sampler, counter);
            L += m_whitted.ambient.spectrum() * si.material->albedo(si);
            if (m_caustics.size() > 0) {
                L += radiance_estimate(m_caustics, si, *bsdf, m_whitted.caustic.photon_neighbours,
                                       m_caustic_radius2, m_sets);
            }
        } else {
            // Follow every delta lobe (reflection, refraction) with its exact weight, in the
            // order the BSDF gives them. Inside closed glass every hit branches in two, and
            // the tree would grow as 2^max_depth: once the camera sample's ray budget is
            // spent, only the strongest lobe is followed, so what is left costs at most
            // max_depth rays per pending branch. The lobes given up carry the smallest
            // weights of the deepest part of the tree; the image loses that light (a small
            // bias) instead of hanging. Ordinary scenes never reach the budget: their
            // images are unchanged by it.
            const auto lobes = bsdf->delta_lobes(wo_local);
            const bool branch = budget > 0;
            int strongest = 0;
            if (!branch) {
                float best = -1.0f;
                for (int k = 0; k < lobes.count; ++k) {
                    const float w =
                        (lobes.lobes[k].f * abs_cos_theta(lobes.lobes[k].wi)).max_value();
                    if (w > best) {
                        best = w;
                        strongest = k;
                    }
                }
            }
            for (int k = 0; k < lobes.count; ++k) {
                if (!branch && k != strongest) continue;
                const BsdfSample& lobe = lobes.lobes[k];
                const Vec3 wi = si.to_world(lobe.wi);
                const Spectrum weight = lobe.f * abs_cos_theta(lobe.wi);
                const Ray next = spawn_specular_ray(si, ray, wi, lobe.is_transmission(), lobe.eta);
                L += weight *
                     trace(next, scene, sampler, arena, counter, nullptr, depth + 1, budget);
            }
        }
    }
    // Light arriving from inside an absorbing medium was attenuated along this segment.
    L *= segment_transmittance(ray, si);
    return L;
}

Spectrum WhittedIntegrator::direct(const Scene& scene, const SurfaceInteraction& si,
                                   const Bsdf& bsdf, Sampler& sampler, RayCounter& counter) const {
    const Vec3 wo_local = si.to_local(si.wo);
    Spectrum L(0.0f);
    for (const auto& light : scene.lights()) {
        // One random rotation of the stratified pattern per light and hit.
        const Vec2 rotation = sampler.get_2d();
        if (!light->is_delta()) {
            L += area_light_direct(scene, *light, si, bsdf, wo_local, rotation, counter);
            continue;
        }
        const std::optional<LightArrival> arrival =
            sample_light_arrival(*light, si, bsdf, wo_local, rotation, 0.0f);
        if (!arrival) continue;
        const LightSample& ls = arrival->light;
        ++counter.rays;
        const Spectrum visible = transmittance(scene, si, ls.p);
        if (!visible.is_black()) L += arrival->f_cos * ls.L / ls.pdf * visible;
    }
    return L;
}

Spectrum WhittedIntegrator::area_light_direct(const Scene& scene, const Light& light,
                                              const SurfaceInteraction& si, const Bsdf& bsdf,
                                              const Vec3& wo_local, const Vec2& rotation,
                                              RayCounter& counter) const {
    const int n = m_whitted.shadow_samples;
    const int count = n * n;
    thread_local std::vector<ShadowSample> samples;
    samples.assign(count, ShadowSample{});
    for (int k = 0; k < count; ++k) {
        const Vec2 u(fract((k % n + 0.5f) / n + rotation.x),
                     fract((k / n + 0.5f) / n + rotation.y));
        const float u_select = fract((k + 0.5f) / count + rotation.x * rotation.y);
        const std::optional<LightArrival> arrival =
            sample_light_arrival(light, si, bsdf, wo_local, u, u_select);
        if (!arrival) continue;
        samples[k].contribution = arrival->f_cos * arrival->light.L / arrival->light.pdf;
        samples[k].target = arrival->light.p;
    }
    auto visible = [&](int k) {
        if (samples[k].visible < 0) {
            ++counter.rays;
            // 0 or 1: interfaces carry no media yet (media would weight the sample instead).
            samples[k].visible = transmittance(scene, si, samples[k].target).is_black() ? 0 : 1;
        }
        return samples[k].visible == 1;
    };

    bool assume_all_visible = false;
    if (m_whitted.penumbra_shortcut && n > 1 && !light.is_infinite()) {
        // Test the four samples at the extremes of the light as seen from the point: for a
        // convex light and occluder, all four blocked means the whole light is hidden and
        // all four clear means no edge crosses it. (An environment surrounds the point:
        // it has no extremes.)
        int tested = 0, clear = 0;
        for (int k : extreme_samples(samples, si.p)) {
            if (k < 0) continue;
            ++tested;
            clear += visible(k);
        }
        if (tested > 0 && clear == 0) return Spectrum(0.0f);  // umbra
        assume_all_visible = tested == 4 && clear == 4;       // fully lit
    }
    Spectrum sum(0.0f);
    for (int k = 0; k < count; ++k) {
        if (samples[k].contribution.is_black()) continue;
        if (assume_all_visible || visible(k)) sum += samples[k].contribution;
    }
    return sum / static_cast<float>(count);
}

}  // namespace glint
