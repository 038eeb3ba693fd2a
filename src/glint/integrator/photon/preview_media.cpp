#include <glint/core/rng.h>
#include <glint/core/secondary_wavelengths.h>
#include <glint/integrator/photon/pass_sampler.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/photon/preview_media.h>
#include <glint/integrator/transport/light_path_start.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/math/frame.h>
#include <glint/medium/delta_tracking.h>
#include <glint/medium/equiangular.h>
#include <glint/medium/henyey_greenstein.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <type_traits>

namespace glint {
namespace {

// Interfaces a camera path or photon may cross in a row before it is given up (a ray caught
// between coincident surfaces).
constexpr int kMaxCrossings = 256;

// The photons a chunk of the batch found: on surfaces (the caustics) and in media.
struct MediaPhotonChunk {
    std::vector<Photon> surface;
    std::vector<VolumePhoton> volume;
};

int choose_channel(float u) {
    const int channels = Spectrum::active_values();
    return std::min(static_cast<int>(u * static_cast<float>(channels)), channels - 1);
}

// The radiance a homogeneous `medium` emits along [0, t_end) of `ray` towards its origin:
// the integral of the transmittance times the source sigma_a Le, per channel
// source (1 - exp(-sigma_t d)) / sigma_t. (Only homogeneous media emit: grid media and
// clouds have no emission parameter.)
Spectrum glow_along(const Ray& ray, float t_end, const Medium& medium) {
    const MediumPoint point = medium.at(ray.origin);
    const bool unbounded = std::isinf(t_end);
    // A channel that emits absorbs, so sigma_t > 0 wherever the source is not 0.
    return map(point.sigma_a * point.emission, point.sigma_a + point.sigma_s,
               [&](float source, float sigma_t) {
                   if (!(sigma_t > 0.0f)) return 0.0f;
                   const float covered = unbounded ? 1.0f : -std::expm1(-sigma_t * t_end);
                   return source * covered / sigma_t;
               });
}

// Distances on [0, t_end) of a homogeneous medium in proportion to the extinction times the
// transmittance, one channel's (t_end may be infinite): the strategy the mean of the
// channels' densities weighs. A channel without extinction draws uniformly on a finite
// segment and nothing on an infinite one.
class TruncatedExponential {
public:
    TruncatedExponential(const Spectrum& sigma_t, float t_end)
        : m_sigma_t(sigma_t), m_t_end(t_end), m_grey(sigma_t.is_constant()) {}

    std::optional<float> sample(int channel, float u) const {
        const float sigma = m_sigma_t.value(channel);
        if (sigma > 0.0f) return -std::log1p(-u * covered(sigma)) / sigma;
        if (std::isinf(m_t_end)) return std::nullopt;
        return u * m_t_end;
    }

    // The density at t (the channels' mean), and the transmittance to t per channel.
    float pdf(float t, Spectrum& transmittance) const {
        transmittance = attenuation(m_sigma_t, t);
        if (m_grey) return channel_pdf(m_sigma_t.value(0), transmittance.value(0));
        const int channels = Spectrum::active_values();
        float sum = 0.0f;
        for (int c = 0; c < channels; ++c)
            sum += channel_pdf(m_sigma_t.value(c), transmittance.value(c));
        return sum / static_cast<float>(channels);
    }

private:
    // The share of the exponential's draws that fall before t_end.
    float covered(float sigma) const {
        return std::isinf(m_t_end) ? 1.0f : -std::expm1(-sigma * m_t_end);
    }
    float channel_pdf(float sigma, float transmittance) const {
        if (sigma > 0.0f) return sigma * transmittance / covered(sigma);
        return std::isinf(m_t_end) ? 0.0f : 1.0f / m_t_end;
    }

    Spectrum m_sigma_t;
    float m_t_end;
    bool m_grey;  // every channel's the same: one density for all
};

// Equiangular sampling of `ray`'s segment [0, t_end) towards the centre of a light that the
// light sampler picks for the segment's middle (its start when the segment is infinite);
// nullopt for lights at infinity and where the centre lies on the ray's line. The pick is
// made before the distance and the distance's density is the chosen light's, so the
// one-sample MIS of the two strategies is unbiased for every pick. `centres` holds each
// light's centre by Light::index.
std::optional<Equiangular> equiangular_towards_light(
    const Scene& scene, const std::vector<std::optional<Vec3>>& centres, const Ray& ray,
    float t_end, float u_anchor) {
    const Vec3 anchor = std::isinf(t_end) ? ray.origin : ray.at(0.5f * t_end);
    const LightSampler::Choice choice = scene.light_sampler().sample(anchor, Vec3(0.0f), u_anchor);
    if (!choice.light) return std::nullopt;
    const size_t index = static_cast<size_t>(choice.light->index());
    if (index >= centres.size() || !centres[index]) return std::nullopt;
    return Equiangular::towards(ray, *centres[index], t_end);
}

}  // namespace

// The batch of caustic photons in a scene with media: as trace_photons' PhotonTracer, but
// each photon carries the medium it travels through (from the one round its light), samples
// distances there by delta tracking on a hero channel, and crosses interfaces. A photon that
// reached a medium through mirrors and glass and scatters there is a volume photon; one that
// reaches its first non-specular surface through them is a caustic photon; either way it
// ends there (the preview keeps caustic light alone). Powers are divided by the mean of the
// photon's r_u, as the light tracer's splats are.
void PreviewIntegrator::trace_photons_in_media(const Scene& scene, const PhotonEmitter& emitter,
                                               uint64_t first, uint64_t count, uint64_t seed,
                                               int max_bounces, std::vector<Photon>& surface,
                                               std::vector<VolumePhoton>& volume,
                                               uint64_t& rays) const {
    constexpr uint64_t kChunk = 2048;
    const uint64_t chunks = (count + kChunk - 1) / kChunk;
    std::vector<MediaPhotonChunk> found(chunks);
    std::atomic<uint64_t> total_rays{0};
    const WavelengthContext* wavelengths = m_settings.spectral ? &m_pass_wavelengths : nullptr;
    const int set = m_photon_passes;
    tbb::parallel_for(uint64_t{0}, chunks, [&](uint64_t chunk) {
        std::optional<WavelengthScope> scope;
        if (wavelengths != nullptr) scope.emplace(*wavelengths);
        Arena arena;
        PassedSurfaces passed;  // each traversal's crossings (one record per chunk, not photon)
        uint64_t chunk_rays = 0;
        MediaPhotonChunk& sink = found[chunk];
        const uint64_t end = std::min(count, (chunk + 1) * kChunk);
        for (uint64_t i = chunk * kChunk; i < end; ++i) {
            std::optional<SecondaryWavelengthsScope> terminated;
            if (wavelengths != nullptr) terminated.emplace();
            Rng rng(hash_combine(mix_bits(seed ^ 0x5bd1e995u), first + i));
            LightPathSamples u_start;
            u_start.u_light = rng.next_float();
            u_start.u_position = Vec2(rng.next_float(), rng.next_float());
            u_start.u_direction = Vec2(rng.next_float(), rng.next_float());
            u_start.u_select = rng.next_float();
            if (scene.camera().time_sampled())
                u_start.time = scene.camera().time_of_sample(rng.next_float());
            const std::optional<LightPathStart> start = start_light_path(scene, u_start, emitter);
            if (!start || start->beta.is_black()) continue;
            const int index = start->light->index();
            const Medium* medium =
                index >= 0 && static_cast<size_t>(index) < m_media->light_start.size()
                    ? m_media->light_start[static_cast<size_t>(index)]
                    : nullptr;
            const int hero = choose_channel(rng.next_float());
            Spectrum beta = start->beta, r_u(1.0f);
            Ray ray = start->emission.ray;
            bool specular_only = true;
            int bounces = 0, crossings = 0;
            SurfaceInteraction si;
            while (bounces <= max_bounces && crossings <= kMaxCrossings) {
                arena.reset();
                ++chunk_rays;
                // One traversal past the interfaces it can skip (the fog box's face before
                // the floor took a traversal of its own), then the legs between them.
                const bool hit = scene.intersect_surface_passing(ray, si, passed);
                crossings += passed.count;
                bool ended = false;  // absorbed, or scattered in a leg
                walk_legs(scene, ray, passed, hit ? si.t : kInfinity, medium,
                          [&](const Ray& leg, float length) {
                              Spectrum weight;
                              float t_scatter = 0.0f, sigma_t = 0.0f;
                              const SegmentEnd segment = through_medium(
                                  *medium, leg, length, hero, rng, weight, r_u, t_scatter, sigma_t);
                              beta *= weight;
                              if (segment == SegmentEnd::kAbsorbed) {
                                  ended = true;
                              } else if (segment == SegmentEnd::kScattered) {
                                  const float mean = r_u.average();
                                  if (specular_only && bounces > 0 && mean > 0.0f) {
                                      sink.volume.push_back(
                                          {leg.at(t_scatter), -glm::normalize(leg.direction),
                                           beta / mean, medium->phase_asymmetry(), set});
                                  }
                                  ended = true;
                              }
                              return !ended;
                          });
                if (ended || !hit) break;
                if (si.material->is_interface()) {
                    medium = medium_beyond(si, ray.direction, medium);
                    ray = spawn_ray(si, ray.direction);
                    ++crossings;
                    continue;
                }
                const Bsdf* bsdf = shade(scene, ray, si, arena);
                if (!bsdf) break;
                const Vec3 wi = -glm::normalize(ray.direction);
                if (!bsdf->is_delta()) {
                    const float mean = r_u.average();
                    if (specular_only && bounces > 0 && mean > 0.0f)
                        sink.surface.push_back({si.p, wi, beta / mean});
                    break;
                }
                if (bounces == max_bounces) break;
                const Vec2 u(rng.next_float(), rng.next_float());
                const std::optional<Scattering> scattering = sample_scattering(
                    si, *bsdf, si.to_local(wi), u, rng.next_float(), TransportMode::kImportance);
                if (!scattering) break;
                const BsdfSample& bs = scattering->sample;
                const Spectrum next = beta * bs.f * (abs_cos_theta(bs.wi) / bs.pdf);
                float survive;
                if (!survives_power_roulette(
                        next.max_value() / beta.max_value(), [&] { return rng.next_float(); },
                        survive))
                    break;
                beta = next / survive;
                medium = medium_beyond(si, scattering->wi, medium);
                continue_ray(ray, si, *scattering);
                ++bounces;
            }
        }
        total_rays += chunk_rays;
    });
    rays += total_rays.load();
    for (MediaPhotonChunk& chunk : found) {
        surface.insert(surface.end(), chunk.surface.begin(), chunk.surface.end());
        volume.insert(volume.end(), chunk.volume.begin(), chunk.volume.end());
    }
}

// Light scattered towards the camera at a point along `ray` (unit direction) in `medium`
// before parameter t_end, straight from a light: one point on the segment and one light
// sample there. In a homogeneous medium the point comes from one of two strategies, mixed by
// one-sample MIS (their densities' mean): in proportion to the extinction times the
// transmittance (one channel's, chosen uniformly, weighted over all channels so that colour
// noise stays bounded in chromatic fog), or equiangular towards a light (equiangular.h),
// which follows the 1 / r^2 glow round a small light that the first leaves noisy. In any
// other medium the point is uniform on the segment (which must then be finite), with the
// transmittance estimated.
Spectrum PreviewIntegrator::in_scattering(const Scene& scene, const Ray& ray, float t_end,
                                          const Medium& medium, Sampler& sampler, Rng& rng,
                                          RayCounter& counter) const {
    const float u_channel = sampler.get_1d();
    const float u_distance = sampler.get_1d();
    const Vec2 u_light = sampler.get_2d();
    const float u_choose = sampler.get_1d();
    const float u_select = sampler.get_1d();
    const float u_strategy = sampler.get_1d();
    const float u_anchor = sampler.get_1d();
    if (scene.light_sampler().empty()) return Spectrum(0.0f);
    float t;
    Spectrum weight;  // transmittance to t times sigma_s there, over the density of t
    if (medium.is_homogeneous()) {
        const MediumPoint point = medium.at(ray.origin);
        const std::optional<Equiangular> equiangular =
            equiangular_towards_light(scene, m_light_centres, ray, t_end, u_anchor);
        const TruncatedExponential exponential(point.sigma_a + point.sigma_s, t_end);
        if (equiangular && u_strategy < 0.5f) {
            t = std::min(std::max(equiangular->sample(u_distance), 0.0f), t_end);
        } else if (const std::optional<float> drawn =
                       exponential.sample(choose_channel(u_channel), u_distance)) {
            t = *drawn;
        } else {
            return Spectrum(0.0f);
        }
        if (!(t < t_end)) return Spectrum(0.0f);
        Spectrum transmittance_to_t;
        const float exponential_pdf = exponential.pdf(t, transmittance_to_t);
        const float pdf =
            equiangular ? 0.5f * (exponential_pdf + equiangular->pdf(t)) : exponential_pdf;
        if (!(pdf > 0.0f)) return Spectrum(0.0f);
        weight = transmittance_to_t * point.sigma_s / pdf;
    } else {
        if (std::isinf(t_end)) return Spectrum(0.0f);
        t = u_distance * t_end;
        weight = medium.transmittance(ray, t, rng) * medium.at(ray.at(t)).sigma_s * t_end;
    }
    if (weight.is_black()) return Spectrum(0.0f);
    const Vec3 p = ray.at(t);
    const LightPoint light = sample_light_point(scene, p, Vec3(0.0f), u_light, u_choose, u_select);
    const std::optional<LightSample>& ls = light.sample;
    if (!ls || ls->L.is_black() || !(ls->pdf > 0.0f) || !(light.choice.pmf > 0.0f))
        return Spectrum(0.0f);
    const float phase = HenyeyGreenstein(medium.phase_asymmetry()).eval(-ray.direction, ls->wi);
    ++counter.rays;
    const Spectrum T =
        transmittance(scene, Scene::ShadowRay{p, ls->p - p, ray.time}, &medium, &rng);
    return weight * T * ls->L * (phase / (light.choice.pmf * ls->pdf));
}

// camera_sample() in a scene with media that scatter: the camera path carries its medium
// through interfaces, mirrors and glass to the first surface that is not purely specular,
// and on every segment through a scattering medium gathers single scattering
// (in_scattering) and takes on the transmittance; the primary ray, up to the first surface
// that is not an interface, gathers the volume photons. Direct light at the surface sees
// the media its shadow ray crosses. The draws come from a PassSampler: their number varies.
// `camera_ray` comes with a unit direction, as Camera::generate_ray makes them.
Spectrum PreviewIntegrator::camera_sample_in_media(const Scene& scene, Vec2i pixel,
                                                   const Ray& camera_ray, Sampler& sampler,
                                                   Arena& arena, RayCounter& counter,
                                                   HashGrid::Cache& cache, DeferredLeg* deferred,
                                                   const FirstTraversal& first,
                                                   AwaitedLight* awaited) const {
    Rng rng(stream_seed(sampler.get_1d()));
    if (deferred) deferred->medium = nullptr;
    // The primary ray's line for the volume photons (not a copy of the Ray: its
    // differentials are not needed).
    const Vec3 primary_origin = camera_ray.origin, primary_direction = camera_ray.direction;
    // The path's current ray: the camera's, until the path spawns one (not copied: the copy
    // of a Ray just written by the caller stalled the loads that followed).
    Ray spawned;
    const Ray* ray = &camera_ray;
    float primary_reach = 0.0f;  // along the primary ray, to the surface being tested
    bool on_primary = true;
    const Medium* medium = m_media->camera;
    Spectrum L(0.0f), beta(1.0f);
    // The first traversal's records, which later traversals overwrite (records of its own
    // were some 500 bytes of stack to initialise per pixel).
    SurfaceInteraction& si = *first.si;
    PassedSurfaces& passed = *first.passed;
    bool first_traced = true;
    for (int segment = 0, crossings = 0; segment < kMaxCameraSegments;) {
        ++counter.rays;
        // One traversal past the interfaces it can skip: they split the ray into legs, each
        // in the medium the last one leads into. The first is traced already (`first`).
        const bool hit =
            first_traced ? first.hit : scene.intersect_surface_passing(*ray, si, passed);
        first_traced = false;
        const float t_end = hit ? si.t : kInfinity;
        // The light each leg gathers in its medium, and its transmittance.
        walk_legs(scene, *ray, passed, t_end, medium, [&](const Ray& leg, float length) {
            if (medium->scatters()) {
                if (on_primary && deferred && !deferred->medium) {
                    // The primary ray's first leg in fog: render_media_pass estimates it.
                    deferred->origin = leg.origin;
                    deferred->direction = leg.direction;
                    deferred->time = leg.time;
                    deferred->length = length;
                    deferred->start =
                        primary_reach + glm::dot(leg.origin - ray->origin, ray->direction);
                    deferred->medium = medium;
                    deferred->beta = beta;
                } else {
                    L += beta * in_scattering(scene, leg, length, *medium, sampler, rng, counter);
                }
            }
            if (medium->emits() && medium->is_homogeneous())
                L += beta * glow_along(leg, length, *medium);
            beta *= medium->transmittance(leg, std::isinf(length) ? 1e30f : length, rng);
            return true;
        });
        crossings += passed.count;
        if (hit && on_primary) primary_reach += si.t;
        const bool interface = hit && si.material->is_interface();
        if (on_primary && !interface) {
            L += m_volume_view.estimate(pixel, primary_origin, primary_direction,
                                        hit ? primary_reach : kInfinity);
            on_primary = false;
        }
        if (!hit) return L + beta * scene.escaped_radiance(ray->direction);
        if (beta.is_black()) return L;
        if (interface) {
            medium = medium_beyond(si, ray->direction, medium);
            spawned = spawn_ray(si, ray->direction);
            ray = &spawned;
            if (++crossings > kMaxCrossings) return L;
            continue;
        }
        L += beta * emitted_radiance(si);
        const Bsdf* bsdf = shade(scene, *ray, si, arena);
        if (!bsdf) return L;
        if (bsdf->is_delta()) {
            const std::optional<Scattering> scattering = sample_scattering(
                si, *bsdf, si.to_local(si.wo), sampler.get_2d(), sampler.get_1d());
            if (!scattering) return L;
            beta *= scattering->weight;
            medium = medium_beyond(si, scattering->wi, medium);
            spawned =
                spawn_specular_ray(si, *ray, scattering->wi, scattering->sample.is_transmission(),
                                   scattering->sample.eta);
            spawned.direction = glm::normalize(spawned.direction);
            ray = &spawned;
            ++segment;
            continue;
        }
        // The first surface that is not purely specular: direct light through the media.
        if (awaited) {
            awaited->waiting = true;
            awaited->medium = medium;
            awaited->rng = rng;
            awaited->L = L;
            awaited->beta = beta;
            awaited->si = &si;
            awaited->bsdf = bsdf;
            return Spectrum(0.0f);
        }
        Spectrum direct(0.0f);
        if (const std::optional<DirectLight> light = sample_direct_light(
                scene, si, *bsdf, si.to_local(si.wo), sampler, LightWeighting::kNone)) {
            ++counter.rays;
            const Vec3 towards = light->target - si.p;
            direct = light->contribution * transmittance(scene, si, light->target,
                                                         medium_beyond(si, towards, medium), &rng);
        }
        return L +
               beta * indirect_estimate(scene, si, *bsdf, direct, sampler, arena, counter, cache);
    }
    return L;
}

// In two loops: every lane's light point first, so that the lights' chains of square
// roots and divisions overlap from lane to lane, then the BSDF towards each. Each lane draws
// what sample_direct_light draws, in the same order.
uint32_t PreviewIntegrator::sample_awaited_lights(const Scene& scene, uint32_t waiting,
                                                  PerLane<AwaitedLight>& awaited,
                                                  PerLane<PassSampler>& samplers,
                                                  RayCounter& counter) const {
    // Room for the points, left uninitialised (value-initialising eight of them cleared
    // them with a slow `rep stos` each block); each is made in place, so that the light's
    // sample is read where the light wrote it.
    union PointSlot {
        PointSlot() {}
        LightPoint point;
    };
    static_assert(std::is_trivially_destructible_v<LightPoint>);
    PerLane<PointSlot> slots;
    PerLane<const LightPoint*> points{};
    for_each_lane(waiting, [&](int lane) {
        points[lane] = new (&slots[lane].point)
            LightPoint(draw_direct_light_point(scene, *awaited[lane].si, samplers[lane]));
    });
    uint32_t shadowed = 0;
    for_each_lane(waiting, [&](int lane) {
        AwaitedLight& at = awaited[lane];
        const SurfaceInteraction& si = *at.si;
        const std::optional<DirectLight> light = direct_light_from(
            *points[lane], si, *at.bsdf, si.to_local(si.wo), LightWeighting::kNone);
        if (!light) {
            at.contribution = Spectrum(0.0f);
            return;
        }
        ++counter.rays;
        // Made in place (a copy of the returned ray read it back at once, and waited).
        new (&at.shadow) Scene::ShadowRay(Scene::shadow_ray(si, light->target));
        at.shadow_medium = medium_beyond(si, light->target - si.p, at.medium);
        at.contribution = light->contribution;
        shadowed |= 1u << lane;
    });
    return shadowed;
}

Spectrum PreviewIntegrator::finish_awaited(const Scene& scene, const AwaitedLight& awaited,
                                           const Spectrum& transmittance, Sampler& sampler,
                                           Arena& arena, RayCounter& counter,
                                           HashGrid::Cache& cache) const {
    const Spectrum direct = awaited.contribution * transmittance;
    return awaited.L + awaited.beta * indirect_estimate(scene, *awaited.si, *awaited.bsdf, direct,
                                                        sampler, arena, counter, cache);
}

// A pass in media, in three sweeps over the film, each pixel's work depending only on (seed,
// pixel, pass) and the photons (the same image for any threads): the camera samples, whose
// primary legs in fog are only recorded when preview_fog_interleave is on
// (interleaved_fog.h); the legs' single scattering, in the pixels InterleavedFog picks; and
// each pixel's light, its own plus what its neighbours estimated for it, into the film.
// With interleaving off no leg is recorded and the last two sweeps add nothing.
void PreviewIntegrator::render_media_pass(const Scene& scene, Film& film, int pass,
                                          uint64_t& rays) {
    const int w = film.width(), h = film.height();
    const WavelengthContext* wavelengths = m_settings.spectral ? &m_pass_wavelengths : nullptr;
    m_fog.reset(Vec2i(w, h), pass);
    m_rest.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
    std::atomic<uint64_t> counted{0};
    // Rows in parallel, with the pass's wavelengths and a path state per pixel.
    const auto sweep = [&](auto&& pixel_work) {
        tbb::parallel_for(tbb::blocked_range<int>(0, h, 4),
                          [&](const tbb::blocked_range<int>& rows) {
                              std::optional<WavelengthScope> scope;
                              if (wavelengths != nullptr) scope.emplace(*wavelengths);
                              RayCounter counter;
                              pixel_work(rows, counter);
                              counted += counter.rays;
                          });
    };
    sweep([&](const tbb::blocked_range<int>& rows, RayCounter& counter) {
        Arena arena;
        HashGrid::Cache cache;
        // The camera rays of blocks of 4 x 2 pixels go through their first traversal as one
        // coherent packet (to the first surface, past the interfaces), and each path then
        // goes on alone: the same draws, hits and light as one ray at a time.
        PerLane<PassSampler> samplers;
        for (PassSampler& sampler : samplers) sampler.set_seed(m_settings.seed);
        PerLane<Ray> rays;
        PerLane<SurfaceInteraction> surfaces;
        PerLane<PassedSurfaces> passed;
        PerLane<AwaitedLight> awaited;
        for (int y0 = rows.begin(); y0 < rows.end(); y0 += kBlockHeight) {
            for (int x0 = 0; x0 < w; x0 += kBlockWidth) {
                uint32_t active = 0;
                PerLane<const Ray*> ray_of{};
                PerLane<SurfaceInteraction*> si_of{};
                for (int lane = 0; lane < kPacketWidth; ++lane) {
                    const int x = x0 + lane % kBlockWidth, y = y0 + lane / kBlockWidth;
                    if (x >= w || y >= rows.end()) continue;
                    // Made in place (a copy read the new ray back at once, and waited for
                    // the camera's stores to complete).
                    new (&rays[lane]) Ray(
                        pass_camera_ray(scene, samplers[lane], film.origin() + Vec2i(x, y), pass));
                    ray_of[lane] = &rays[lane];
                    si_of[lane] = &surfaces[lane];
                    active |= 1u << lane;
                }
                const uint32_t hit =
                    scene.intersect_surface_packet_passing(ray_of, active, si_of, passed, true);
                // The lanes' BSDFs live until their shadow rays are traced, after the loop.
                arena.reset();
                uint32_t waiting = 0;
                for_each_lane(active, [&](int lane) {
                    const int x = x0 + lane % kBlockWidth, y = y0 + lane / kBlockWidth;
                    std::optional<SecondaryWavelengthsScope> terminated;
                    if (wavelengths != nullptr) terminated.emplace();
                    PixelRest& rest = m_rest[static_cast<size_t>(y) * static_cast<size_t>(w) +
                                             static_cast<size_t>(x)];
                    DeferredLeg& leg = m_fog.leg(x, y);
                    leg.medium = nullptr;
                    const FirstTraversal first{((hit >> lane) & 1u) != 0, &surfaces[lane],
                                               &passed[lane]};
                    // Spectral paths keep their wavelengths' state (a thread's): they trace
                    // their shadow rays alone, at once.
                    AwaitedLight* awaits = wavelengths == nullptr ? &awaited[lane] : nullptr;
                    if (awaits) awaits->waiting = false;
                    rest.L = camera_sample_in_media(
                        scene, film.origin() + Vec2i(x, y), rays[lane], samplers[lane], arena,
                        counter, cache, m_preview.fog_interleave ? &leg : nullptr, first, awaits);
                    if (awaits && awaits->waiting) waiting |= 1u << lane;
                    rest.hero_only = wavelengths != nullptr && secondary_wavelengths_terminated();
                });
                // The legs' keys, read once their stores have long completed (read at once,
                // they waited for them).
                for_each_lane(active, [&](int lane) {
                    m_fog.finish_leg(x0 + lane % kBlockWidth, y0 + lane / kBlockWidth);
                });
                if (waiting == 0) continue;
                // The direct light's samples in a row, their shadow rays (towards one light
                // from neighbouring surfaces) as packets; then each path finishes as it
                // would have alone.
                PerLane<Scene::ShadowRay> shadows;
                PerLane<const Medium*> shadow_media{};
                PerLane<Rng*> streams{};
                const uint32_t shadowed =
                    sample_awaited_lights(scene, waiting, awaited, samplers, counter);
                // Gathered once all are sampled (read back at once, a sample waited for its
                // stores to complete).
                for_each_lane(shadowed, [&](int lane) {
                    shadows[lane] = awaited[lane].shadow;
                    shadow_media[lane] = awaited[lane].shadow_medium;
                    streams[lane] = &awaited[lane].rng;
                });
                PerLane<Spectrum> transmittances;
                transmittance_packet(scene, shadows, shadow_media, streams, shadowed,
                                     transmittances);
                for_each_lane(waiting & ~shadowed,
                              [&](int lane) { transmittances[lane] = Spectrum(1.0f); });
                for_each_lane(waiting, [&](int lane) {
                    const int x = x0 + lane % kBlockWidth, y = y0 + lane / kBlockWidth;
                    m_rest[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)]
                        .L = finish_awaited(scene, awaited[lane], transmittances[lane],
                                            samplers[lane], arena, counter, cache);
                });
            }
        }
    });
    sweep([&](const tbb::blocked_range<int>& rows, RayCounter& counter) {
        // Its own stream: the camera sample's draws are spent.
        PassSampler sampler;
        sampler.set_seed(mix_bits(m_settings.seed ^ 0x666f67ull));
        // A row's estimating pixels are listed first, so that each one's leg (a cache line
        // of its own, written a sweep earlier and long evicted) is fetched a few estimates
        // ahead: read when needed, the wait for it was a fifth of this sweep.
        constexpr int kAhead = 4;
        std::vector<int> estimating(static_cast<size_t>(w));
        for (int y = rows.begin(); y < rows.end(); ++y) {
            int count = 0;
            for (int x = 0; x < w; ++x)
                if (m_fog.estimates(x, y)) estimating[static_cast<size_t>(count++)] = x;
            for (int k = 0; k < std::min(kAhead, count); ++k)
                __builtin_prefetch(&m_fog.leg(estimating[static_cast<size_t>(k)], y));
            for (int k = 0; k < count; ++k) {
                if (k + kAhead < count)
                    __builtin_prefetch(&m_fog.leg(estimating[static_cast<size_t>(k + kAhead)], y));
                const int x = estimating[static_cast<size_t>(k)];
                const DeferredLeg& leg = m_fog.leg(x, y);
                sampler.start_pixel_sample(film.origin() + Vec2i(x, y), pass);
                Rng rng(stream_seed(sampler.get_1d()));
                // The leg lies before any dispersive glass on its path.
                std::optional<SecondaryWavelengthsScope> fresh;
                if (wavelengths != nullptr) fresh.emplace();
                m_fog.set_estimate(x, y,
                                   leg.beta * in_scattering(scene, leg.ray(), leg.length,
                                                            *leg.medium, sampler, rng, counter));
            }
        }
    });
    sweep([&](const tbb::blocked_range<int>& rows, RayCounter&) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < w; ++x) {
                const PixelRest& rest = m_rest[static_cast<size_t>(y) * static_cast<size_t>(w) +
                                               static_cast<size_t>(x)];
                // The film reads a path that went through a dispersive event at its hero
                // alone, its single scattering with it, as when the two are added in one walk.
                std::optional<SecondaryWavelengthsScope> state;
                if (wavelengths != nullptr) {
                    state.emplace();
                    if (rest.hero_only) terminate_secondary_wavelengths();
                }
                film.add_sample(film.origin() + Vec2i(x, y), rest.L + m_fog.reconstruct(x, y), 1.0f,
                                nullptr);
            }
        }
    });
    rays += counted.load();
}

}  // namespace glint
