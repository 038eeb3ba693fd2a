#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/core/progress.h>
#include <glint/integrator/radiosity/radiosity.h>
#include <glint/integrator/radiosity/radiosity_cache.h>
#include <glint/integrator/transport/transport.h>
#include <glint/material/material.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>

namespace glint {
namespace {

// How many mirror and glass bounces a camera ray follows when max_depth is -1.
constexpr int kDefaultSpecularSegments = 64;
// Patches a scene may be cut into.
constexpr size_t kMaxPatches = 4000000;

}  // namespace

RadiosityIntegratorSettings RadiosityIntegratorSettings::read(const Params& p) {
    RadiosityIntegratorSettings s;
    s.solve = RadiositySettings::read(p);
    s.hybrid = p.get_bool("hybrid", s.hybrid);
    s.cache = p.get_string("radiosity_cache", s.cache);
    s.caustic = CausticSettings::read(p);
    return s;
}

std::unique_ptr<Integrator> RadiosityIntegrator::create(const RenderSettings& settings,
                                                        const Params& params) {
    return std::make_unique<RadiosityIntegrator>(settings,
                                                 RadiosityIntegratorSettings::read(params));
}

RadiosityIntegrator::RadiosityIntegrator(const RenderSettings& settings,
                                         const RadiosityIntegratorSettings& radiosity)
    : TileIntegrator(settings), m_radiosity(radiosity) {}

// The cache file: named relative to the scene's folder, and inside it (a scene has no other
// file access; --trusted-scene lifts this).
std::string RadiosityIntegrator::cache_path(const Scene& scene) const {
    const std::string& name = m_radiosity.cache;
    if (name.empty()) return name;
    std::filesystem::path path(name);
    if (path.is_relative()) path = std::filesystem::path(scene.directory()) / path;
    if (!scene.trusted() && !is_inside_folder(scene.directory(), path.string())) {
        throw Error(fmt::format(
            "{}: radiosity_cache '{}' lies outside the scene's folder '{}'; a scene may keep "
            "its cache only there (glint render --trusted-scene lifts this)",
            m_settings.where_of("radiosity_cache"), name, scene.directory()));
    }
    return path.string();
}

void RadiosityIntegrator::solve(const Scene& scene, bool quiet) {
    const std::string cache = cache_path(scene);
    m_sets = photon_wavelength_sets(m_settings, m_radiosity.caustic);
    if (m_sets.spectral() && !cache.empty()) {
        throw Error(fmt::format(
            "{}: radiosity_cache keeps one RGB solution, and spectral mode solves once per set "
            "of wavelengths: leave out radiosity_cache or spectral",
            m_settings.where_of("radiosity_cache")));
    }
    const float patch_size = radiosity_patch_size(scene, m_radiosity.solve);
    m_meshes.clear();
    m_solve_stats = {};
    m_loaded = false;
    for (int set = 0; set < m_sets.count(); ++set) {
        // In spectral mode each set's reflectances and emission are read at its wavelengths.
        std::optional<WavelengthScope> wavelengths;
        if (m_sets.spectral()) wavelengths.emplace(m_sets[set]);
        m_meshes.push_back(RadiosityMesh::build(scene, patch_size, kMaxPatches));
        RadiosityMesh& mesh = m_meshes.back();
        std::error_code ec;
        if (!cache.empty() && std::filesystem::symlink_status(cache, ec).type() !=
                                  std::filesystem::file_type::not_found) {
            load_radiosity_cache(mesh, cache);
            m_loaded = true;
            return;
        }
        const std::string label = m_sets.spectral() ? fmt::format("radiosity (wavelengths {}/{})",
                                                                  set + 1, m_sets.count())
                                                    : std::string("radiosity");
        Progress progress(label, 100, quiet, "%");
        const RadiositySolveStats stats =
            solve_radiosity(scene, mesh, m_radiosity.solve, m_settings.seed, progress);
        progress.finish();
        m_solve_stats.shots += stats.shots;
        m_solve_stats.light_shots += stats.light_shots;
        m_solve_stats.rays += stats.rays;
        m_solve_stats.seconds += stats.seconds;
        m_solve_stats.unshot_fraction =
            std::max(m_solve_stats.unshot_fraction, stats.unshot_fraction);
        if (!cache.empty()) save_radiosity_cache(mesh, cache);
    }
}

uint64_t RadiosityIntegrator::prepare(const Scene& scene) {
    solve(scene, m_quiet);
    uint64_t photon_rays = 0;
    if (m_radiosity.hybrid && m_radiosity.caustic.caustic_photons > 0) {
        m_caustics = build_caustic_map(scene, m_settings, m_radiosity.caustic, m_sets, photon_rays);
        m_caustic_radius2 = photon_search_radius2(scene, m_radiosity.caustic);
    }
    return photon_rays;  // the solve's rays are in its note
}

RenderStats RadiosityIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    m_quiet = progress.quiet();
    RenderStats stats = TileIntegrator::render(scene, film, progress);
    size_t leaves = 0;
    const RadiosityMesh& first = mesh();  // the first set's, in spectral mode
    for (const RadiosityElement& e : first.elements) leaves += e.first_child < 0;
    if (m_loaded) {
        stats.notes.push_back(fmt::format("radiosity: loaded from {} ({} patches, {} elements)",
                                          m_radiosity.cache, first.patches.size(), leaves));
    } else {
        const RadiositySolveStats& s = m_solve_stats;
        stats.notes.push_back(fmt::format(
            "radiosity: {} patches, {} elements, {} vertices; {} shots ({:.0f}/s) and {} rays in "
            "{:.2f} s, {:.2f} % unshot; {:.0f} bytes per element",
            first.patches.size(), leaves, first.vertices.size(), s.shots,
            s.seconds > 0.0 ? s.shots / s.seconds : 0.0, s.rays, s.seconds,
            100.0 * s.unshot_fraction, first.bytes_per_element()));
    }
    if (m_radiosity.hybrid)
        stats.notes.push_back(fmt::format("caustic map: {} photons", m_caustics.size()));
    return stats;
}

int RadiosityIntegrator::side_of(const RadiosityLocation& at, const Vec3& direction) const {
    const RadiosityMesh& mesh = path_mesh();
    const Vec3& n = mesh.vertices[mesh.elements[at.element].v[0]].n;
    return glm::dot(n, direction) < 0.0f ? 0 : 1;
}

Spectrum RadiosityIntegrator::mesh_radiance(const RadiosityLocation& at, int side,
                                            bool indirect_only) const {
    const RadiosityMesh& mesh = path_mesh();
    const Spectrum b = mesh.interpolate(at, [&](const RadiosityVertex& v) {
        return indirect_only ? v.b[side] - v.b_direct[side] : v.b[side];
    });
    const Spectrum rho = mesh.interpolate(at, [](const RadiosityVertex& v) { return v.rho; });
    return (b + rho * mesh.ambient) * kInvPi;
}

Spectrum RadiosityIntegrator::gather(const Scene& scene, const SurfaceInteraction& si,
                                     const Bsdf& bsdf, Sampler& sampler,
                                     RayCounter& counter) const {
    const Vec2 u = sampler.get_2d();
    const float u_lobe = sampler.get_1d();
    const std::optional<Scattering> s = sample_scattering(si, bsdf, si.to_local(si.wo), u, u_lobe);
    if (!s) return Spectrum(0.0f);
    const Ray ray = spawn_ray(si, s->wi);
    ++counter.rays;
    SurfaceInteraction hit;
    HitRecord record;
    if (!scene.intersect(ray, hit, record)) {
        // Next-event estimation sees an environment light; the constant background is no
        // light, so only this ray finds it.
        return scene.environment() ? Spectrum(0.0f) : s->weight * scene.background();
    }
    const std::optional<RadiosityLocation> at = path_mesh().locate(record);
    if (!at) return Spectrum(0.0f);
    return s->weight * mesh_radiance(*at, side_of(*at, ray.direction), false);
}

Spectrum RadiosityIntegrator::li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                                 RayCounter& counter, AovSample* aov) const {
    const int segments =
        m_settings.max_depth >= 0 ? m_settings.max_depth + 1 : kDefaultSpecularSegments;
    SpecularChain chain =
        follow_specular_chain(scene, ray, Spectrum(1.0f), sampler, arena, counter, segments, aov);
    Spectrum L = chain.emitted;
    if (chain.escaped) L += chain.beta * scene.escaped_radiance(chain.ray.direction);
    if (!chain.hit) return L;
    const SurfaceInteraction& si = *chain.hit;
    const Bsdf& bsdf = *chain.bsdf;
    const std::optional<RadiosityLocation> at = path_mesh().locate(chain.record);
    if (at && !m_radiosity.hybrid)
        return L + chain.beta * mesh_radiance(*at, side_of(*at, chain.ray.direction), false);

    Spectrum reflected =
        estimate_direct_light(scene, si, bsdf, sampler, LightWeighting::kNone, counter);
    if (at)
        reflected += mesh_radiance(*at, side_of(*at, chain.ray.direction), true);
    else
        reflected += gather(scene, si, bsdf, sampler, counter);
    if (m_caustics.size() > 0) {
        reflected += radiance_estimate(m_caustics, si, bsdf, m_radiosity.caustic.photon_neighbours,
                                       m_caustic_radius2, m_sets);
    }
    return L + chain.beta * reflected;
}

}  // namespace glint
