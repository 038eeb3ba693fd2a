#include <glint/core/sampler.h>
#include <glint/core/sobol_sampler.h>
#include <glint/integrator/path/path.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>
#include <glint/material/material.h>

#include <typeinfo>

namespace glint {
namespace {

// Weight of emission that BSDF sampling reached (an area light hit or an escaped ray into
// an environment light), against light sampling's chance of finding the same light there:
// counted fully after a specular bounce, which light sampling cannot follow, and by the
// BSDF-only strategy; not at all by the light-only one, which already counted it.
template <typename LightPdf>
float bsdf_emission_weight(DirectLighting strategy, bool specular_bounce, float bsdf_pdf,
                           const LightPdf& light_pdf) {
    if (specular_bounce || strategy == DirectLighting::kBsdfOnly) return 1.0f;
    if (strategy == DirectLighting::kLightOnly) return 0.0f;
    return power_heuristic(bsdf_pdf, light_pdf());
}

// The features of a hit reached from the camera through delta bounces only (`depth` of
// them). The depth stays the first hit's: it is what the non-local means filter compares.
// Past a delta surface the features stay open for the next hit, seen in it or through it;
// the delta surface's albedo (a mirror's tint, a glass's 1) tints the next one's, and the
// Fresnel blend of reflection and refraction comes from averaging the pixel's samples.
template <typename PathState>
void record_aov(PathState& path, const SurfaceInteraction& si, const Bsdf* bsdf, int depth) {
    const Spectrum albedo = si.material ? si.material->albedo(si) : Spectrum(0.0f);
    path.aov->albedo = path.aov_tint * albedo;
    path.aov->normal = si.shading.n();
    if (depth == 0) path.aov->depth = si.t;
    path.aov_open = bsdf && bsdf->is_delta();
    path.aov_tint *= albedo;
}

// The direct light of a path whose shadow ray a surface blocked, in a scene where that
// surface may only bound media: what the interfaces on the way let through.
template <typename PathState>
void add_direct_through_interfaces(const Scene& scene, const Scene::ShadowRay& shadow,
                                   PathState& path) {
    const Spectrum visible = transmittance_through_interfaces(scene, shadow);
    if (!visible.is_black()) path.L += path.beta * path.direct * visible;
}

}  // namespace

Spectrum PathIntegrator::li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                            RayCounter& counter, AovSample* aov) const {
    PathState path;
    path.start(ray, sampler, aov);
    for (int depth = 0;; ++depth) {
        ++counter.rays;
        if (!scene.intersect(path.ray, path.si)) {
            escape(scene, path, depth);
            break;
        }
        if (!scatter_at_hit(scene, path, depth, arena)) break;
        if (const std::optional<Vec3> target = sample_light<Sampler>(scene, path)) {
            ++counter.rays;
            if (!scene.has_interfaces()) {
                if (!scene.occluded(path.si, *target)) path.L += path.beta * path.direct;
            } else {
                add_direct_through_interfaces(scene, Scene::shadow_ray(path.si, *target), path);
            }
        }
        if (!continue_path<Sampler>(path, depth)) break;
    }
    return path.L;
}

// A path whose ray left the scene: it gathers the background or the environment light.
void PathIntegrator::escape(const Scene& scene, PathState& path, int depth) const {
    const Ray& ray = path.ray;
    const Spectrum escaped = scene.escaped_radiance(ray.direction);
    if (path.aov_open) {
        *path.aov = AovSample{path.aov_tint * escaped, Vec3(0.0f),
                              depth == 0 ? kInfinity : path.aov->depth};
        path.aov_open = false;
    }
    if (const Light* environment = scene.environment()) {
        path.L += path.beta * escaped *
                  bsdf_emission_weight(m_strategy, path.specular_bounce, path.bsdf_pdf, [&] {
                      return scene.light_sampler().pmf(path.previous_point, path.previous_normal,
                                                       *environment) *
                             environment->pdf_li_escaped(ray.direction);
                  });
    } else {
        path.L += path.beta * escaped;  // a constant background is no light: nothing samples it
    }
}

// At the path's new hit: emission found by BSDF sampling, absorption on the way, and the
// BSDF there. False when the path ends at this hit.
[[gnu::always_inline]] inline bool PathIntegrator::scatter_at_hit(const Scene& scene,
                                                                  PathState& path, int depth,
                                                                  Arena& arena) const {
    SurfaceInteraction& si = path.si;
    path.beta *= segment_transmittance(path.ray, si);
    // Emission reached by BSDF sampling; light sampling already counted the rest of it.
    if (si.area_light) {
        const Spectrum Le = emitted_radiance(si);
        if (!Le.is_black()) {
            path.L += path.beta * Le *
                      bsdf_emission_weight(m_strategy, path.specular_bounce, path.bsdf_pdf, [&] {
                          return scene.light_sampler().pdf_li(path.previous_point,
                                                              path.previous_normal, si);
                      });
        }
    }

    path.bsdf = shade(scene, path.ray, si, arena);
    if (path.aov_open) record_aov(path, si, path.bsdf, depth);
    if (!path.bsdf) return false;
    if (depth >= m_settings.depth_limit()) return false;
    path.wo_local = si.to_local(si.wo);
    return true;
}

// Next-event estimation at the path's hit: sets path.direct and returns the point whose
// visibility decides it, or nullopt when there is nothing to trace.
template <typename SamplerType>
[[gnu::always_inline]] inline std::optional<Vec3> PathIntegrator::sample_light(
    const Scene& scene, PathState& path) const {
    if (path.bsdf->is_delta() || scene.light_sampler().empty() ||
        m_strategy == DirectLighting::kBsdfOnly) {
        return std::nullopt;
    }
    const std::optional<DirectLight> direct = sample_direct_light(
        scene, path.si, *path.bsdf, path.wo_local, static_cast<SamplerType&>(*path.sampler),
        m_strategy == DirectLighting::kMis ? LightWeighting::kMis : LightWeighting::kNone);
    if (!direct) return std::nullopt;
    path.direct = direct->contribution;
    return direct->target;
}

// BSDF sampling for the next bounce, and Russian roulette. False when the path ends.
template <typename SamplerType>
[[gnu::always_inline]] inline bool PathIntegrator::continue_path(PathState& path, int depth) const {
    SurfaceInteraction& si = path.si;
    auto& sampler = static_cast<SamplerType&>(*path.sampler);
    const Vec2 u = sampler.get_2d();
    const float u_lobe = sampler.get_1d();
    const std::optional<Scattering> scattering =
        sample_scattering(si, *path.bsdf, path.wo_local, u, u_lobe);
    if (!scattering) return false;
    const BsdfSample& bs = scattering->sample;
    path.beta *= scattering->weight;
    path.specular_bounce = bs.is_delta();
    path.bsdf_pdf = bs.pdf;
    if (bs.is_transmission()) path.eta_scale *= bs.eta * bs.eta;
    path.previous_point = si.p;
    path.previous_normal = si.shading.n();
    continue_ray(path.ray, si, *scattering);

    // Russian roulette on the throughput without the radiance scaling of refraction,
    // which would otherwise kill paths that are about to leave the glass.
    float survival;
    if (!survives_path_roulette(
            depth, (path.beta * path.eta_scale).max_value(), [&] { return sampler.get_1d(); },
            survival))
        return false;
    if (survival < 1.0f) path.beta /= survival;
    return !path.beta.is_black();
}

// The packet form. A pixel's samples advance together, one bounce at a time, so that each
// bounce's closest-hit rays and then its shadow rays are traced as one Embree packet: the
// camera rays of a pixel, and the shadow rays from where they land, are coherent, which
// Embree's packet kernels turn into fewer instructions per ray; deeper bounces still share
// the call. Each path takes the steps li() takes and draws its samples in the same order,
// so every sample gets what li() gives it, bit for bit.

// A thread's samplers, one per lane; lane 0's is the Worker's own.
struct PathIntegrator::PacketWorker : Worker {
    PerLane<std::unique_ptr<Sampler>> lane_samplers;
};

std::unique_ptr<TileIntegrator::Worker> PathIntegrator::make_worker(
    const Sampler& prototype) const {
    auto worker = std::make_unique<PacketWorker>();
    worker->sampler = prototype.clone();
    for (int lane = 1; lane < kPacketWidth; ++lane)
        worker->lane_samplers[lane] = worker->sampler->clone_for_lane();
    return worker;
}

TileIntegrator::PixelMoments PathIntegrator::render_pixel(const Scene& scene, Film& film,
                                                          Vec2i pixel, Worker& worker, int first,
                                                          int count) const {
    // A thread follows one path at a time in spectral mode (its wavelengths are the thread's
    // while it lives): the plain loop of li().
    if (m_settings.spectral)
        return TileIntegrator::render_pixel(scene, film, pixel, worker, first, count);
    auto& packet_worker = static_cast<PacketWorker&>(worker);
    auto lane_sampler = [&](int lane) -> Sampler& {
        return lane == 0 ? *worker.sampler : *packet_worker.lane_samplers[lane];
    };
    PixelMoments moments;
    PerLane<PathState> paths;
    PerLane<FilterSample> filter_samples;
    PerLane<AovSample> aovs;
    for (int packet_first = first; packet_first < first + count; packet_first += kPacketWidth) {
        const int lanes = std::min(kPacketWidth, first + count - packet_first);
        for (int lane = 0; lane < lanes; ++lane) {
            Sampler& sampler = lane_sampler(lane);
            const CameraSample sample =
                start_camera_sample(scene, pixel, packet_first + lane, sampler);
            filter_samples[lane] = sample.filter;
            aovs[lane] = AovSample{};
            paths[lane].start(sample.ray, sampler, film.has_aovs() ? &aovs[lane] : nullptr);
        }
        worker.arena.reset();
        trace_packet(scene, paths, lanes, worker.arena, worker.counter);
        for (int lane = 0; lane < lanes; ++lane) {
            record_sample(film, pixel, packet_first + lane, paths[lane].L,
                          filter_samples[lane].weight, paths[lane].aov, moments);
        }
    }
    return moments;
}

// li() for paths[0, count), bounce by bounce; each path's radiance ends in its L. The lanes'
// samplers are clones of one sampler, so lane 0's type is every lane's.
void PathIntegrator::trace_packet(const Scene& scene, PerLane<PathState>& paths, int count,
                                  Arena& arena, RayCounter& counter) const {
    if (typeid(*paths[0].sampler) == typeid(SobolSampler))
        trace_packet_with<SobolSampler>(scene, paths, count, arena, counter);
    else
        trace_packet_with<Sampler>(scene, paths, count, arena, counter);
}

// The lanes' steps are always inlined: GCC would otherwise call the two big lambdas per
// lane, passing the paths through memory, which measured about 5 % slower in all.
#define GLINT_INLINE_LAMBDA __attribute__((always_inline))

template <typename SamplerType>
void PathIntegrator::trace_packet_with(const Scene& scene, PerLane<PathState>& paths, int count,
                                       Arena& arena, RayCounter& counter) const {
    uint32_t active = (1u << count) - 1;
    for (int depth = 0; active != 0; ++depth) {
        // A pixel's camera rays, and the shadow rays from where they land, run together.
        const bool coherent = depth == 0;
        PerLane<const Ray*> rays{};
        PerLane<SurfaceInteraction*> interactions{};
        for_each_lane(active, [&](int lane) {
            ++counter.rays;
            rays[lane] = &paths[lane].ray;
            interactions[lane] = &paths[lane].si;
        });
        const uint32_t hit = scene.intersect_packet(rays, active, interactions, coherent);
        for_each_lane(active & ~hit, [&](int lane) { escape(scene, paths[lane], depth); });
        active &= hit;

        PerLane<Vec3> shadow_origins, shadow_directions;
        PerLane<float> shadow_times;
        uint32_t shadowed = 0;
        for_each_lane(active, [&](int lane) GLINT_INLINE_LAMBDA {
            PathState& path = paths[lane];
            if (!scatter_at_hit(scene, path, depth, arena)) {
                active &= ~(1u << lane);
                return;
            }
            if (const std::optional<Vec3> target = sample_light<SamplerType>(scene, path)) {
                const Scene::ShadowRay shadow = Scene::shadow_ray(path.si, *target);
                shadow_origins[lane] = shadow.origin;
                shadow_directions[lane] = shadow.direction;
                shadow_times[lane] = shadow.time;
                shadowed |= 1u << lane;
                ++counter.rays;
            }
        });
        if (shadowed != 0) {
            const uint32_t blocked = scene.occluded_packet(shadow_origins, shadow_directions,
                                                           shadow_times, shadowed, coherent);
            for_each_lane(shadowed & ~blocked, [&](int lane) {
                paths[lane].L += paths[lane].beta * paths[lane].direct;
            });
            // A lane blocked only by surfaces that bound media sees the light after all.
            if (scene.has_interfaces()) {
                for_each_lane(blocked, [&](int lane) {
                    add_direct_through_interfaces(
                        scene,
                        Scene::ShadowRay{shadow_origins[lane], shadow_directions[lane],
                                         shadow_times[lane]},
                        paths[lane]);
                });
            }
        }

        for_each_lane(active, [&](int lane) GLINT_INLINE_LAMBDA {
            if (!continue_path<SamplerType>(paths[lane], depth)) active &= ~(1u << lane);
        });
    }
}

#undef GLINT_INLINE_LAMBDA

}  // namespace glint
