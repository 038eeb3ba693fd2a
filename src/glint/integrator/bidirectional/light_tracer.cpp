#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/core/rng.h>
#include <glint/integrator/bidirectional/light_tracer.h>
#include <glint/integrator/transport/camera_connection.h>
#include <glint/integrator/transport/light_path_start.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/spectral_model.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/math/warp.h>
#include <glint/medium/delta_tracking.h>
#include <glint/medium/henyey_greenstein.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace glint {
namespace {

// Paths per chunk: the unit of parallel work and of the fixed order in which splats reach
// the film.
constexpr uint64_t kChunkPaths = 4096;
// Chunks traced in parallel before their splats are added to the film, in chunk order:
// bounds the splats held in memory at once, independently of the thread count.
constexpr uint64_t kChunksPerBatch = 64;
// A hard cap on a light path's scattering events, for where roulette never ends a path
// (inside a closed lossless mirror every scattering weight is 1).
constexpr int kMaxBounces = 1024;

}  // namespace

// What one chunk of paths produces: its splats, the rays it traced, and the random numbers
// of the path being traced.
struct LightTracer::Chunk {
    std::vector<Splat> splats;
    uint64_t rays = 0;
    Arena arena;
    Rng rng;

    Vec2 next_2d() {
        const float x = rng.next_float();
        return Vec2(x, rng.next_float());
    }
};

// The state of one light path between vertices. In media, distances are sampled for one
// channel, the hero; r_u holds the densities with which every channel would have sampled the
// same path over the hero's (volpath's r_u), and what the path splats is divided by their
// mean: the balance heuristic over the choice of hero.
struct LightTracer::Particle {
    Ray ray;
    Spectrum beta;
    Spectrum r_u{1.0f};
    const Medium* medium = nullptr;
    int hero = 0;
    int bounce = 1;  // the scattering vertex the next event makes
    int max_bounces = kMaxBounces;

    Spectrum splat_weight() const { return beta / r_u.average(); }
};

LightTracer::LightTracer(const RenderSettings& settings) : m_settings(settings) {}

std::unique_ptr<Integrator> LightTracer::create(const RenderSettings& settings, const Params&) {
    // Every path splats wherever it lands: there is no pixel to sample more or less.
    refuse_adaptive_sampling(settings, "light");
    return std::make_unique<LightTracer>(settings);
}

RenderStats LightTracer::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    check_camera_motion_joinable(scene, "light", m_settings.where_of("integrator"));
    m_light_media.clear();
    m_with_media = !scene.media().empty();
    if (m_with_media) {
        // Where each light starts its paths, probed once from one point it emits from.
        m_light_media.assign(scene.lights().size(), nullptr);
        for (const std::unique_ptr<Light>& light : scene.lights()) {
            const std::optional<LightEmission> e = light->sample_le(Vec2(0.5f), Vec2(0.5f), 0.5f);
            if (e) m_light_media[light->index()] = medium_containing(scene, e->ray.origin);
        }
    }
    // Glowing media and the lights share the paths by power.
    m_glow.reset();
    m_glow_share = 0.0f;
    if (std::any_of(scene.media().begin(), scene.media().end(),
                    [](const std::unique_ptr<Medium>& m) { return m->emits(); })) {
        m_glow.emplace(scene);
        float light_power = 0.0f;
        for (const std::unique_ptr<Light>& light : scene.lights())
            light_power += light->power().average();
        if (!m_glow->empty()) m_glow_share = m_glow->power() / (m_glow->power() + light_power);
    }
    const uint64_t pixels = static_cast<uint64_t>(film.width()) * film.height();
    const uint64_t paths = pixels * static_cast<uint64_t>(m_settings.spp);
    // Camera::We is normalised over the whole image: a pixel's value is its splats times
    // pixel count / paths (see camera.h).
    film.set_splat_scale(static_cast<double>(pixels) / static_cast<double>(paths));
    RenderStats stats;
    const uint64_t chunks = (paths + kChunkPaths - 1) / kChunkPaths;
    for (uint64_t first = 0; first < chunks; first += kChunksPerBatch) {
        const uint64_t batch = std::min(kChunksPerBatch, chunks - first);
        std::vector<Chunk> results(batch);
        tbb::parallel_for(uint64_t{0}, batch, [&](uint64_t b) {
            const uint64_t chunk = first + b;
            const uint64_t end = std::min(paths, (chunk + 1) * kChunkPaths);
            for (uint64_t index = chunk * kChunkPaths; index < end; ++index)
                trace_path(scene, index, results[b]);
            progress.advance(end - chunk * kChunkPaths);
        });
        for (const Chunk& chunk : results) {
            film.add_splats(chunk.splats);
            stats.rays += chunk.rays;
        }
    }
    stats.samples = paths;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

// One light path: a light chosen by power, a ray from it, then scattering in importance
// mode until roulette, the depth limit or an escape ends it; the light's point and every
// non-specular vertex connect to the camera. Glowing media share the choice with the lights
// by power (start_in_glowing_medium, which takes the same first draws). Draws, from an RNG
// keyed by (seed, index): the light (1D), the ray's origin (2D) and direction (2D), the
// light's part (1D), the lens point of the light's own connection (2D); in a scene with
// media the hero channel (1D); then per vertex the lens point (2D), the BSDF sample (2D +
// 1D) and roulette (1D), and in media the collisions' distances and events.
void LightTracer::trace_path(const Scene& scene, uint64_t index, Chunk& chunk) const {
    chunk.rng.seed(hash_combine(mix_bits(m_settings.seed ^ 0x4c54u), index));
    const PathWavelengths wavelengths(m_settings.spectral,
                                      hash_combine(mix_bits(m_settings.seed ^ 0x4c54u), index));
    chunk.arena.reset();
    LightPathSamples u_start;
    u_start.u_light = chunk.rng.next_float();
    u_start.u_position = chunk.next_2d();
    u_start.u_direction = chunk.next_2d();
    u_start.u_select = chunk.rng.next_float();
    const Vec2 u_light_lens = chunk.next_2d();
    // One time per light path, uniform over the shutter, only when the scene moves (still
    // scenes keep their paths bit for bit); every ray and connection of the path keeps it.
    if (scene.camera().time_sampled())
        u_start.time = scene.camera().time_of_sample(chunk.rng.next_float());
    const bool with_media = m_with_media;
    Particle particle;
    particle.max_bounces = m_settings.max_depth >= 0 ? m_settings.max_depth : kMaxBounces;
    if (u_start.u_light < m_glow_share) {
        // The path starts in a glowing medium; its first draws place it there.
        start_in_glowing_medium(scene, u_start.u_light / m_glow_share,
                                Vec3(u_start.u_position.x, u_start.u_position.y, u_start.u_select),
                                u_start.u_direction, u_light_lens, u_start.time, particle, chunk);
        if (particle.beta.is_black()) return;
    } else {
        // The rest of the light's number chooses among the lights (the same number as without
        // glowing media when there are none).
        float lights_share = 1.0f;
        if (m_glow_share > 0.0f) {
            lights_share = 1.0f - m_glow_share;
            u_start.u_light = std::min((u_start.u_light - m_glow_share) / lights_share,
                                       std::nextafter(1.0f, 0.0f));
        }
        const std::optional<LightPathStart> start = start_light_path(scene, u_start);
        if (!start) return;
        particle.medium = with_media ? m_light_media[start->light->index()] : nullptr;
        connect_light_to_camera(scene, start->emission, *start->light, start->pmf * lights_share,
                                particle.medium, u_light_lens, chunk);
        particle.beta = start->beta / lights_share;
        if (particle.beta.is_black()) return;
        particle.ray = start->emission.ray;
    }
    if (with_media) {
        particle.hero =
            std::min(static_cast<int>(chunk.rng.next_float() * Spectrum::active_values()),
                     Spectrum::active_values() - 1);
    }
    walk(scene, particle, chunk);
}

// A light path's start in a glowing medium (MediumEmitters): the point connects to the lens
// with the light it emits, sigma_a Le, the same in every direction (the emitting point is the
// path's first vertex, as a light's point is); then the particle leaves it in a uniform
// direction carrying 4 pi sigma_a Le over the point's density, and its next scattering is
// its second vertex (volpath counts the emitting point as a vertex too). A point outside the
// chosen medium leaves the particle's power 0.
void LightTracer::start_in_glowing_medium(const Scene& scene, float u_region, const Vec3& u_point,
                                          const Vec2& u_direction, const Vec2& u_lens, float time,
                                          Particle& particle, Chunk& chunk) const {
    particle.beta = Spectrum(0.0f);
    if (particle.max_bounces < 1) return;  // the glow is light after one vertex
    const std::optional<MediumEmitters::Start> start = m_glow->sample(scene, u_region, u_point);
    if (!start) return;
    const Spectrum source = start->source_over_pdf / m_glow_share;
    const std::optional<CameraConnection> connection = connect_glowing_point_to_camera(
        scene, start->p, time, *start->medium, source, u_lens, chunk.rays, &chunk.rng);
    if (connection) chunk.splats.push_back({connection->lens.film, connection->L});
    particle.medium = start->medium;
    particle.beta = source / warp::uniform_sphere_pdf();
    particle.ray =
        Ray{start->p, warp::square_to_uniform_sphere(u_direction), 0.0f, kInfinity, time};
    particle.bounce = 2;
}

// The particle's walk from its first ray: scattering in importance mode until roulette, the
// depth limit or an escape ends it, every non-specular vertex connected to the camera.
void LightTracer::walk(const Scene& scene, Particle& particle, Chunk& chunk) const {
    const bool with_media = m_with_media;
    PassedSurfaces passed;
    for (int crossings = 0; particle.bounce <= particle.max_bounces && crossings < kMaxBounces;) {
        ++chunk.rays;
        SurfaceInteraction si;
        // With media the walk passes the interfaces Embree can skip in one traversal, and
        // stops at the others: they change its medium. The legs between them are segments
        // of their own media.
        passed.count = 0;
        const bool hit = with_media ? scene.intersect_surface_passing(particle.ray, si, passed)
                                    : scene.intersect(particle.ray, si);
        const Ray traced = particle.ray;
        MediumEvent event = MediumEvent::kCrossed;
        walk_legs(scene, traced, passed, hit ? si.t : kInfinity, particle.medium,
                  [&](const Ray& leg, float length) {
                      particle.ray = leg;
                      event = through_medium(scene, particle, length, chunk);
                      return event == MediumEvent::kCrossed;
                  });
        crossings += passed.count;
        if (event == MediumEvent::kEnded) return;
        if (event == MediumEvent::kScattered) continue;
        particle.ray = traced;
        if (!hit) return;
        if (with_media && si.material->is_interface()) {
            // Only the medium changes: the ray goes straight on, and no bounce is counted.
            particle.medium = medium_beyond(si, particle.ray.direction, particle.medium);
            particle.ray = spawn_ray(si, particle.ray.direction);
            ++crossings;
            continue;
        }
        // Without media tracked, absorbing glass is its interior's closed form.
        if (!with_media) particle.beta *= segment_transmittance(particle.ray, si);
        const Bsdf* bsdf = shade(scene, particle.ray, si, chunk.arena);
        if (!bsdf) return;
        const Vec2 u_lens = chunk.next_2d();
        if (!bsdf->is_delta()) connect_to_camera(scene, si, *bsdf, particle, u_lens, chunk);
        if (particle.bounce == particle.max_bounces) return;

        const Vec2 u = chunk.next_2d();
        const float u_lobe = chunk.rng.next_float();
        const std::optional<Scattering> scattering =
            sample_scattering(si, *bsdf, si.to_local(si.wo), u, u_lobe, TransportMode::kImportance);
        if (!scattering) return;
        // Russian roulette keeps a particle's power roughly constant: it survives with the
        // probability its scattering keeps (at most 1 in importance mode, where refraction
        // carries no 1/eta^2).
        float survive;
        if (!survives_power_roulette(
                scattering->weight.max_value(), [&] { return chunk.rng.next_float(); }, survive))
            return;
        particle.beta *= scattering->weight / survive;
        continue_ray(particle.ray, si, *scattering);
        if (with_media)
            particle.medium = medium_beyond(si, particle.ray.direction, particle.medium);
        ++particle.bounce;
    }
}

// The particle's segment through its medium up to t_hit, by delta tracking on its hero
// channel (transport/media.h): absorbed (kEnded), across to t_hit with its throughput and
// ratios carried (kCrossed), or scattered at a collision (kScattered), where the light path
// has a vertex: it connects to the lens there, then the phase function turns the ray
// (exactly sampled, so the throughput keeps its value).
LightTracer::MediumEvent LightTracer::through_medium(const Scene& scene, Particle& particle,
                                                     float t_hit, Chunk& chunk) const {
    const Medium& medium = *particle.medium;
    Spectrum weight;
    float t = 0.0f, sigma_t = 0.0f;
    const SegmentEnd end = glint::through_medium(medium, particle.ray, t_hit, particle.hero,
                                                 chunk.rng, weight, particle.r_u, t, sigma_t);
    particle.beta *= weight;
    if (end == SegmentEnd::kAbsorbed || particle.beta.is_black() || particle.r_u.is_black())
        return MediumEvent::kEnded;
    if (end == SegmentEnd::kReached) return MediumEvent::kCrossed;
    const Vec3 p = particle.ray.at(t);
    const Vec3 wi_arrival = glm::normalize(particle.ray.direction);
    const Vec2 u_lens = chunk.next_2d();
    const std::optional<CameraConnection> connection =
        connect_medium_point_to_camera(scene, p, wi_arrival, particle.ray.time, medium,
                                       particle.splat_weight(), u_lens, chunk.rays, &chunk.rng);
    if (connection) chunk.splats.push_back({connection->lens.film, connection->L});
    if (particle.bounce++ == particle.max_bounces) return MediumEvent::kEnded;
    // The phase function's arguments point away from p: -wi_arrival is where the light came
    // from, and the sample is where it goes.
    const HenyeyGreenstein phase(medium.phase_asymmetry());
    const PhaseSample next = phase.sample(-wi_arrival, chunk.next_2d());
    particle.ray = Ray{p, next.wi, 0.0f, kInfinity, particle.ray.time};
    return MediumEvent::kScattered;
}

// The strategy that sees a non-specular surface lit by the path: the surface point
// connected to a point on the lens, splatted where that connection lands on the film.
void LightTracer::connect_to_camera(const Scene& scene, const SurfaceInteraction& si,
                                    const Bsdf& bsdf, const Particle& particle, const Vec2& u_lens,
                                    Chunk& chunk) const {
    const std::optional<CameraConnection> connection = connect_surface_to_camera(
        scene, si, bsdf, particle.splat_weight(), u_lens, chunk.rays, particle.medium, &chunk.rng);
    if (connection) chunk.splats.push_back({connection->lens.film, connection->L});
}

// The strategy that sees an emitting surface directly: the light's own point connected to
// the lens. Lights without a surface are left out: point and spot lights are invisible to
// the camera in every glint integrator, and lights at infinity have no point to connect.
void LightTracer::connect_light_to_camera(const Scene& scene, const LightEmission& emission,
                                          const Light& light, float light_pmf, const Medium* medium,
                                          const Vec2& u_lens, Chunk& chunk) const {
    const bool has_surface = emission.n != Vec3(0.0f);
    if (!has_surface || light.is_infinite() || !(emission.pdf_pos > 0.0f)) return;
    const std::optional<CameraConnection> connection = connect_light_point_to_camera(
        scene, light, emission.ray.origin, emission.n, emission.ray.time,
        light_pmf * emission.pdf_pos, u_lens, chunk.rays, medium, &chunk.rng);
    if (connection) chunk.splats.push_back({connection->lens.film, connection->L});
}

}  // namespace glint
