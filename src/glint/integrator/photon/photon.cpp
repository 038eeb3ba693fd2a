#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/progress.h>
#include <glint/integrator/photon/photon.h>
#include <glint/integrator/photon/photon_tracer.h>
#include <glint/integrator/photon/projection_map.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>

#include <fmt/format.h>

#include <chrono>

namespace glint {
namespace {

constexpr int kMaxSpecularChain = 16;

struct PhotonSink {
    bool caustic_only = false;
    std::vector<Photon> photons;
    void store(const PhotonHit& hit) {
        if (caustic_only && !hit.caustic) return;
        photons.push_back({hit.si->p, hit.wi, hit.power, hit.set});
    }
};

// Concatenates the chunks' photons in chunk order and scales them to the emitted count: the
// count of their own set, when the photons took turns over `sets`.
PhotonMap gather_map(std::vector<PhotonSink> sinks, uint64_t emitted, const WavelengthSets& sets) {
    std::vector<Photon> photons;
    for (PhotonSink& sink : sinks)
        photons.insert(photons.end(), sink.photons.begin(), sink.photons.end());
    const float scale =
        emitted > 0 ? static_cast<float>(sets.count()) / static_cast<float>(emitted) : 0.0f;
    for (Photon& p : photons) p.power *= scale;
    return PhotonMap(std::move(photons));
}

}  // namespace

CausticSettings CausticSettings::read(const Params& p) {
    CausticSettings s;
    s.caustic_photons = p.get_int("caustic_photons", s.caustic_photons);
    s.photon_neighbours = p.get_int("photon_neighbours", s.photon_neighbours);
    s.projection_maps = p.get_bool("projection_maps", s.projection_maps);
    s.photon_radius = p.get_float("photon_radius", s.photon_radius);
    s.wavelength_sets = p.get_int("wavelength_sets", s.wavelength_sets);
    if (s.wavelength_sets < 1 || s.wavelength_sets > 256)
        p.fail_at("wavelength_sets", "'wavelength_sets' must be in [1, 256]");
    if (s.caustic_photons < 0)
        p.fail_at("caustic_photons", "'caustic_photons' must not be negative");
    if (s.photon_neighbours < 1)
        p.fail_at("photon_neighbours", "'photon_neighbours' must be at least 1");
    if (!(s.photon_radius >= 0.0f) || !std::isfinite(s.photon_radius))
        p.fail_at("photon_radius", "'photon_radius' must be a finite number >= 0");
    return s;
}

PhotonSettings PhotonSettings::read(const Params& p) {
    PhotonSettings s;
    s.photons = p.get_int("photons", s.photons);
    s.gather_rays = p.get_int("gather_rays", s.gather_rays);
    s.caustic = CausticSettings::read(p);
    if (s.photons < 1) p.fail_at("photons", "'photons' must be at least 1");
    if (s.gather_rays < 0) p.fail_at("gather_rays", "'gather_rays' must not be negative");
    // Every emitted photon is stored at least once (more with bounces), and held twice while
    // the maps are built (the chunks' lists, then the map): a lower bound on what the maps
    // take, checked before a single photon is traced.
    const uint64_t emitted =
        static_cast<uint64_t>(s.photons) + static_cast<uint64_t>(s.caustic.caustic_photons);
    try {
        check_memory(saturating_product(emitted, 2 * (sizeof(Photon) + 1)),
                     fmt::format("the photon maps ({} photons)", emitted));
    } catch (const Error& e) {
        p.fail_at("photons", e.what());
    }
    return s;
}

WavelengthSets photon_wavelength_sets(const RenderSettings& settings,
                                      const CausticSettings& caustic) {
    if (!settings.spectral) return {};
    return WavelengthSets(caustic.wavelength_sets, settings.seed);
}

PhotonMap build_caustic_map(const Scene& scene, const RenderSettings& settings,
                            const CausticSettings& caustic, const WavelengthSets& sets,
                            uint64_t& rays) {
    const int max_bounces = settings.max_depth >= 0 ? settings.max_depth : 32;
    // Caustic photons from point, spot and area lights go only where specular objects are.
    std::vector<std::optional<ProjectionMap>> projections(scene.lights().size());
    // A projection map aims at where the specular objects stand at one time: in a scene that
    // moves, photons go everywhere (each with its own time) instead.
    if (caustic.projection_maps && !scene.has_motion()) {
        for (size_t i = 0; i < scene.lights().size(); ++i) {
            projections[i] = ProjectionMap::make_if_useful(scene, *scene.lights()[i]);
        }
    }
    PhotonEmitter emitter = [&](const Light& light, const Vec2& u1, const Vec2& u2, float u3) {
        const auto& projection = projections[static_cast<size_t>(light.index())];
        return projection ? projection->sample(light, u1, u2, u3) : light.sample_le(u1, u2, u3);
    };
    PhotonTracer tracer(scene, max_bounces, emitter);
    tracer.use_wavelength_sets(&sets);
    const uint64_t count = static_cast<uint64_t>(caustic.caustic_photons);
    return gather_map(tracer.trace(0, count, settings.seed + 1, rays,
                                   [] {
                                       return PhotonSink{true, {}};
                                   }),
                      count, sets);
}

float photon_search_radius2(const Scene& scene, const CausticSettings& caustic) {
    if (caustic.photon_radius > 0.0f) return sqr(caustic.photon_radius);
    const Bounds3& bounds = scene.stats().bounds;
    const float scene_size = bounds.is_empty() ? 1.0f : glm::length(bounds.extent());
    return sqr(scene_size / 20.0f);
}

std::unique_ptr<Integrator> PhotonIntegrator::create(const RenderSettings& settings,
                                                     const Params& params) {
    return std::make_unique<PhotonIntegrator>(settings, PhotonSettings::read(params));
}

PhotonIntegrator::PhotonIntegrator(const RenderSettings& settings, const PhotonSettings& photon)
    : TileIntegrator(settings), m_photon(photon) {}

uint64_t PhotonIntegrator::build_maps(const Scene& scene) {
    m_max_distance2 = photon_search_radius2(scene, m_photon.caustic);
    const int max_bounces = m_settings.max_depth >= 0 ? m_settings.max_depth : 32;
    uint64_t rays = 0;

    m_sets = photon_wavelength_sets(m_settings, m_photon.caustic);

    PhotonTracer global_tracer(scene, max_bounces);
    global_tracer.use_wavelength_sets(&m_sets);
    const uint64_t global_count = static_cast<uint64_t>(m_photon.photons);
    m_global = gather_map(
        global_tracer.trace(0, global_count, m_settings.seed, rays, [] { return PhotonSink{}; }),
        global_count, m_sets);

    const auto start = std::chrono::steady_clock::now();
    m_caustic = build_caustic_map(scene, m_settings, m_photon.caustic, m_sets, rays);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_caustic_rate =
        seconds > 0.0 ? static_cast<double>(m_photon.caustic.caustic_photons) / seconds : 0.0;
    return rays;
}

RenderStats PhotonIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const uint64_t photon_rays = build_maps(scene);
    const double photon_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RenderStats stats = render_tiles(scene, film, progress);
    stats.rays += photon_rays;
    stats.notes.push_back(
        fmt::format("photon maps: {} global and {} caustic photons stored in {:.2f} s "
                    "({:.2f} M caustic photons emitted/s)",
                    m_global.size(), m_caustic.size(), photon_seconds, m_caustic_rate * 1e-6));

    for (const std::string& view : m_settings.debug) {
        if (view != "photons") continue;
        // The debug view: what the photon maps alone say at each first diffuse hit.
        add_luminance_view(scene, film, m_show_photons, "photons.Y", stats);
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

Spectrum PhotonIntegrator::estimate(const PhotonMap& map, const SurfaceInteraction& si,
                                    const Bsdf& bsdf) const {
    return radiance_estimate(map, si, bsdf, m_photon.caustic.photon_neighbours, m_max_distance2,
                             m_sets);
}

Spectrum PhotonIntegrator::final_gather(const Scene& scene, const SurfaceInteraction& si,
                                        const Bsdf& bsdf, Sampler& sampler, Arena& arena,
                                        RayCounter& counter) const {
    const int n = m_photon.gather_rays;
    if (n == 0) return Spectrum(0.0f);
    const Vec3 wo = si.to_local(si.wo);
    Spectrum sum(0.0f);
    for (int i = 0; i < n; ++i) {
        const Vec2 u = sampler.get_2d();
        const float u_lobe = sampler.get_1d();
        const std::optional<Scattering> scattering = sample_scattering(si, bsdf, wo, u, u_lobe);
        if (!scattering) continue;
        // Through specular surfaces to the first diffuse one; emission seen on the way is
        // direct or caustic light, which the other terms already hold.
        const SpecularChain chain =
            follow_specular_chain(scene, spawn_ray(si, scattering->wi), scattering->weight, sampler,
                                  arena, counter, kMaxSpecularChain, nullptr);
        if (chain.hit) {
            sum += chain.beta * estimate(m_global, *chain.hit, *chain.bsdf);
        } else if (chain.escaped && !scene.environment()) {
            // An environment light seen here is direct or caustic light too; only a
            // constant background, which no light sampling or photon carries, counts.
            sum += chain.beta * scene.background();
        }
    }
    return sum / static_cast<float>(n);
}

Spectrum PhotonIntegrator::li(const Ray& camera_ray, const Scene& scene, Sampler& sampler,
                              Arena& arena, RayCounter& counter, AovSample* aov) const {
    // Every vertex before the first diffuse one is specular: emission seen on the way is not
    // in any map.
    const SpecularChain chain = follow_specular_chain(scene, camera_ray, Spectrum(1.0f), sampler,
                                                      arena, counter, kMaxSpecularChain, aov);
    const Spectrum& L = chain.emitted;
    if (chain.escaped) return L + chain.beta * scene.escaped_radiance(chain.ray.direction);
    if (!chain.hit) return L;
    const SurfaceInteraction& si = *chain.hit;
    const Bsdf& bsdf = *chain.bsdf;
    if (m_show_photons)
        return L + chain.beta * (estimate(m_caustic, si, bsdf) + estimate(m_global, si, bsdf));
    const Spectrum direct =
        estimate_direct_light(scene, si, bsdf, sampler, LightWeighting::kNone, counter);
    const Spectrum caustic = estimate(m_caustic, si, bsdf);
    return L +
           chain.beta * (direct + caustic + final_gather(scene, si, bsdf, sampler, arena, counter));
}

}  // namespace glint
