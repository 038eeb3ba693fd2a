#include <glint/core/sampler.h>
#include <glint/integrator/path.h>
#include <glint/integrator/shading.h>
#include <glint/material/material.h>

namespace glint {
namespace {

float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// Direct light at `si` from one light chosen by power, weighted against BSDF sampling, as
// it arrives if nothing blocks the way to `target`; nullopt when it contributes nothing.
// The caller traces the shadow ray (several paths' together).
struct DirectSample {
    Spectrum contribution;
    Vec3 target;
};
std::optional<DirectSample> sample_direct(const Scene& scene, const SurfaceInteraction& si,
                                          const Bsdf& bsdf, const Vec3& wo_local, Sampler& sampler,
                                          bool use_mis) {
    // 2D first: the Sobol sampler hands out a 2D value and two 1D values per index shuffle.
    const Vec2 u = sampler.get_2d();
    const float u_light = sampler.get_1d();
    const float u_select = sampler.get_1d();
    const LightSampler::Choice choice = scene.light_sampler().sample(u_light);
    if (!choice.light) return std::nullopt;
    const std::optional<LightSample> ls = choice.light->sample_li(si.p, u, u_select);
    if (!ls || ls->L.is_black()) return std::nullopt;
    const Vec3 wi_local = si.to_local(ls->wi);
    float bsdf_pdf = 0.0f;
    const Spectrum f = bsdf.eval_pdf(wo_local, wi_local, bsdf_pdf) * abs_cos_theta(wi_local);
    if (f.is_black()) return std::nullopt;
    const float light_pdf = choice.pmf * ls->pdf;
    if (ls->is_delta || !use_mis) return DirectSample{f * ls->L / light_pdf, ls->p};
    const float weight = power_heuristic(light_pdf, bsdf_pdf);
    return DirectSample{f * ls->L * (weight / light_pdf), ls->p};
}

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

void record_aov(AovSample* aov, const SurfaceInteraction& si, const Material* material) {
    aov->albedo = material ? material->albedo(si) : Spectrum(0.0f);
    aov->normal = si.shading.n();
    aov->depth = si.t;
}

}  // namespace

// One path of a packet, between the steps of PathIntegrator::li_packet.
struct PathIntegrator::Path {
    Spectrum L{0.0f};
    Spectrum beta{1.0f};
    Ray ray;
    bool specular_bounce = true;  // the camera "samples" its ray like a delta lobe
    float bsdf_pdf = 0.0f;
    Vec3 previous_point{0.0f};  // where the last BSDF sample was taken, for MIS
    float eta_scale = 1.0f;
    SurfaceInteraction si;  // each bounce's hit, written over the last one's
    const Bsdf* bsdf = nullptr;
    Vec3 wo_local{0.0f};
    Spectrum direct{0.0f};  // light sampling's contribution, if its shadow ray gets through
    Sampler* sampler = nullptr;
    AovSample* aov = nullptr;
};

Spectrum PathIntegrator::li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                            RayCounter& counter, AovSample* aov) const {
    CameraPacket packet;
    packet.count = 1;
    packet.rays[0] = ray;
    packet.samplers[0] = &sampler;
    packet.aovs[0] = aov;
    PerLane<Spectrum> radiance;
    li_packet(packet, scene, arena, counter, radiance);
    return radiance[0];
}

// The paths of a packet (samples of one pixel) advance together, one bounce at a time, so
// that each bounce's rays and then its shadow rays are traced as one Embree packet: the
// camera rays of a pixel, and the shadow rays from where they land, are coherent, which
// Embree's packet kernels turn into fewer instructions per ray; deeper bounces still share
// the call. Each path draws its own samples in the order a lone path would, so every lane
// gets what li() gives it (tests/integrator/test_path.cpp).
void PathIntegrator::li_packet(const CameraPacket& packet, const Scene& scene, Arena& arena,
                               RayCounter& counter, PerLane<Spectrum>& radiance) const {
    PerLane<Path> paths;
    for (int lane = 0; lane < packet.count; ++lane) {
        paths[lane].ray = packet.rays[lane];
        paths[lane].sampler = packet.samplers[lane];
        paths[lane].aov = packet.aovs[lane];
    }
    uint32_t active = (1u << packet.count) - 1;
    for (int depth = 0; active != 0; ++depth) {
        // A pixel's camera rays, and the shadow rays from where they land, run together.
        const bool coherent = depth == 0;
        const uint32_t hit = trace_paths(scene, paths, active, coherent, counter);
        for_each_lane(active & ~hit, [&](int lane) { escape(scene, paths[lane], depth); });
        active &= hit;

        PerLane<Vec3> shadow_origins, shadow_directions;
        uint32_t shadowed = 0;
        for_each_lane(active, [&](int lane) {
            Path& path = paths[lane];
            if (!scatter_at_hit(scene, path, depth, arena)) {
                active &= ~(1u << lane);
                return;
            }
            if (const std::optional<Vec3> target = sample_light(scene, path)) {
                const Scene::ShadowRay shadow = Scene::shadow_ray(path.si, *target);
                shadow_origins[lane] = shadow.origin;
                shadow_directions[lane] = shadow.direction;
                shadowed |= 1u << lane;
                ++counter.rays;
            }
        });
        if (shadowed != 0) {
            const uint32_t blocked =
                scene.occluded_packet(shadow_origins, shadow_directions, shadowed, coherent);
            for_each_lane(shadowed & ~blocked, [&](int lane) {
                paths[lane].L += paths[lane].beta * paths[lane].direct;
            });
        }

        for_each_lane(active, [&](int lane) {
            if (!continue_path(paths[lane], depth)) active &= ~(1u << lane);
        });
    }
    for (int lane = 0; lane < packet.count; ++lane) radiance[lane] = paths[lane].L;
}

// Closest hits of the active paths' rays, as one packet; returns the paths that hit.
uint32_t PathIntegrator::trace_paths(const Scene& scene, PerLane<Path>& paths, uint32_t active,
                                     bool coherent, RayCounter& counter) {
    PerLane<const Ray*> rays{};
    PerLane<SurfaceInteraction*> interactions{};
    for_each_lane(active, [&](int lane) {
        ++counter.rays;
        rays[lane] = &paths[lane].ray;
        interactions[lane] = &paths[lane].si;
    });
    return scene.intersect_packet(rays, active, interactions, coherent);
}

// A path whose ray left the scene: it gathers the background or the environment light.
void PathIntegrator::escape(const Scene& scene, Path& path, int depth) const {
    const Ray& ray = path.ray;
    const Spectrum escaped = scene.escaped_radiance(ray.direction);
    if (path.aov && depth == 0) *path.aov = AovSample{escaped, Vec3(0.0f), kInfinity};
    if (const Light* environment = scene.environment()) {
        path.L += path.beta * escaped *
                  bsdf_emission_weight(m_strategy, path.specular_bounce, path.bsdf_pdf, [&] {
                      return scene.light_sampler().pmf(*environment) *
                             environment->pdf_li_escaped(ray.direction);
                  });
    } else {
        path.L += path.beta * escaped;  // a constant background is no light: nothing samples it
    }
}

// At the path's new hit: emission found by BSDF sampling, absorption on the way, and the
// BSDF there. False when the path ends at this hit.
[[gnu::always_inline]] inline bool PathIntegrator::scatter_at_hit(const Scene& scene, Path& path,
                                                                  int depth, Arena& arena) const {
    SurfaceInteraction& si = path.si;
    // Emission reached by BSDF sampling; light sampling already counted the rest of it.
    if (si.area_light) {
        const Spectrum Le = si.area_light->le(si, si.wo);
        if (!Le.is_black()) {
            path.L += path.beta * Le *
                      bsdf_emission_weight(m_strategy, path.specular_bounce, path.bsdf_pdf, [&] {
                          return scene.light_sampler().pmf(*si.area_light) *
                                 si.area_light->pdf_li(path.previous_point, si);
                      });
        }
    }

    // Beer-Lambert absorption along the segment just travelled inside a medium.
    if (!si.front_face) {
        const Spectrum sigma = si.material->interior_absorption();
        if (!sigma.is_black()) path.beta *= exp(sigma * (-si.t * glm::length(path.ray.direction)));
    }

    path.bsdf = shade(scene, path.ray, si, arena);
    if (path.aov && depth == 0) record_aov(path.aov, si, si.material);
    if (!path.bsdf) return false;
    if (m_settings.max_depth >= 0 && depth >= m_settings.max_depth) return false;
    path.wo_local = si.to_local(si.wo);
    return true;
}

// Next-event estimation at the path's hit: sets path.direct and returns the point whose
// visibility decides it, or nullopt when there is nothing to trace.
[[gnu::always_inline]] inline std::optional<Vec3> PathIntegrator::sample_light(const Scene& scene,
                                                                               Path& path) const {
    if (path.bsdf->is_delta() || scene.light_sampler().empty() ||
        m_strategy == DirectLighting::kBsdfOnly) {
        return std::nullopt;
    }
    const std::optional<DirectSample> direct =
        sample_direct(scene, path.si, *path.bsdf, path.wo_local, *path.sampler,
                      m_strategy == DirectLighting::kMis);
    if (!direct) return std::nullopt;
    path.direct = direct->contribution;
    return direct->target;
}

// BSDF sampling for the next bounce, and Russian roulette. False when the path ends.
[[gnu::always_inline]] inline bool PathIntegrator::continue_path(Path& path, int depth) const {
    SurfaceInteraction& si = path.si;
    Sampler& sampler = *path.sampler;
    const Vec2 u = sampler.get_2d();
    const float u_lobe = sampler.get_1d();
    const std::optional<BsdfSample> bs = path.bsdf->sample(path.wo_local, u, u_lobe);
    if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) return false;
    const Vec3 wi = si.to_world(bs->wi);
    // A shading normal can send light through the geometric surface; refuse it.
    const bool geometric_transmission = glm::dot(wi, si.ng) * glm::dot(si.wo, si.ng) < 0.0f;
    if (geometric_transmission != bs->is_transmission()) return false;
    path.beta *= bs->f * (abs_cos_theta(bs->wi) / bs->pdf);
    path.specular_bounce = bs->is_delta();
    path.bsdf_pdf = bs->pdf;
    if (bs->is_transmission()) path.eta_scale *= bs->eta * bs->eta;
    path.previous_point = si.p;
    if (bs->is_delta()) {
        path.ray = spawn_specular_ray(si, path.ray, wi, bs->is_transmission(), bs->eta);
    } else {
        respawn_ray(path.ray, si, wi);
    }

    // Russian roulette on the throughput without the radiance scaling of refraction,
    // which would otherwise kill paths that are about to leave the glass.
    const float rr_throughput = (path.beta * path.eta_scale).max_value();
    if (depth >= 2 && rr_throughput < 1.0f) {
        const float q = std::max(0.0f, 1.0f - rr_throughput);
        if (sampler.get_1d() < q) return false;
        path.beta /= 1.0f - q;
    }
    return !path.beta.is_black();
}

}  // namespace glint
