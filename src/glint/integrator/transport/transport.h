#pragma once
// The transport layer: the steps of a light path that every integrator shares, written
// once. A camera path, a photon, a light-tracing particle and (later) the subpaths of the
// bidirectional methods are all the same chain of these steps:
//
//   segment_transmittance   what the medium a segment ran through lets pass (Beer-Lambert
//                           inside an absorbing dielectric today; participating media here)
//   transmittance           what a shadow ray lets pass (visibility.h)
//   emitted_radiance        emission seen at a hit
//   sample_light_arrival /  next-event estimation: one light sample, or one light chosen for
//   sample_direct_light     the point (light tree) and sampled, in one documented order of
//                           sample draws
//   sample_scattering       BSDF sampling of the next direction, with the check that the
//                           direction agrees with the geometric surface
//   follow_specular_chain   a ray through mirrors and glass to the first surface that is not
//                           purely specular
//
// The steps a path takes at every bounce are inline, since hot loops call them per bounce.
// Integrators keep what is theirs: how paths end (roulette), how strategies are weighted
// (MIS), what is stored (photons, visible points) and how rays are batched (packets).
#include <glint/core/arena.h>
#include <glint/core/sampler.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/material/bsdf.h>
#include <glint/scene/scene.h>

#include <array>
#include <optional>

namespace glint {

/// The power heuristic (Veach 1997, beta = 2): the weight of a strategy that chose a sample
/// with density pdf_a against another that would have chosen it with density pdf_b.
inline float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

/// The fraction of light that survives the segment `ray` travelled to reach `si`: the
/// transmittance of the medium the segment ran through, which the hit's MediumInterface
/// names (the side the ray arrived from); 1 in vacuum. Only the insides of closed shapes
/// hold media today (an absorbing dielectric's Beer-Lambert interior), so a front-face hit
/// arrived through vacuum and costs nothing. Every integrator multiplies its throughput by
/// this at every hit, camera and light paths alike.
inline Spectrum segment_transmittance(const Ray& ray, const SurfaceInteraction& si) {
    if (si.front_face) return Spectrum(1.0f);
    const Medium* medium = si.material->medium_interface().arriving(false);
    if (!medium) return Spectrum(1.0f);
    // Walks that do not sample media (all but volpath) meet only media with a closed-form
    // transmittance (absorbing glass, homogeneous media), which draw nothing from the Rng;
    // a medium that must estimate gets a fixed stream, correlated but unbiased per segment.
    Rng closed_form;
    return medium->transmittance(ray, si.t, closed_form);
}

/// Radiance the surface at `si` emits back along the ray that found it (zero when it is not
/// a light).
inline Spectrum emitted_radiance(const SurfaceInteraction& si) {
    return si.area_light ? si.area_light->le(si, si.wo) : Spectrum(0.0f);
}

/// One light sample as it arrives at a surface point, before a shadow ray decides whether
/// it gets there.
struct LightArrival {
    LightSample light;      ///< direction, radiance, solid-angle pdf and the point to trace to
    Spectrum f_cos;         ///< the BSDF towards the light times |cos theta_i|
    float bsdf_pdf = 0.0f;  ///< density with which BSDF sampling picks that direction (for MIS)
};

/// The BSDF at `si` towards a light sample: f |cos theta_i| into `f_cos`, and the density
/// with which BSDF sampling picks that direction into `bsdf_pdf`. False when f_cos is black.
[[gnu::always_inline]] inline bool bsdf_towards_light(const LightSample& ls,
                                                      const SurfaceInteraction& si,
                                                      const Bsdf& bsdf, const Vec3& wo_local,
                                                      Spectrum& f_cos, float& bsdf_pdf) {
    const Vec3 wi_local = si.to_local(ls.wi);
    f_cos = bsdf.eval_pdf(wo_local, wi_local, bsdf_pdf) * abs_cos_theta(wi_local);
    return !f_cos.is_black();
}

/// Samples `light` from `si` with (u, u_select) (see Light::sample_li) and evaluates the
/// BSDF towards it; nullopt when the sample carries nothing.
inline std::optional<LightArrival> sample_light_arrival(const Light& light,
                                                        const SurfaceInteraction& si,
                                                        const Bsdf& bsdf, const Vec3& wo_local,
                                                        const Vec2& u, float u_select) {
    const std::optional<LightSample> ls = light.sample_li(si.p, u, u_select);
    if (!ls || ls->L.is_black()) return std::nullopt;
    LightArrival arrival{*ls, Spectrum(0.0f), 0.0f};
    if (!bsdf_towards_light(*ls, si, bsdf, wo_local, arrival.f_cos, arrival.bsdf_pdf))
        return std::nullopt;
    return arrival;
}

/// How a direct-light sample is weighted against BSDF sampling's chance of finding the same
/// light.
enum class LightWeighting {
    kNone,  ///< light sampling alone estimates direct light
    kMis,   ///< the power heuristic against the BSDF's density (delta lights: weight 1)
};

/// A point on a light as next-event estimation samples it: the light chosen (see
/// LightChoice), then Light::sample_li's point on it, with the densities of both
/// (choice.pmf, sample->pdf). Next-event estimation and bdpt's s = 1 strategy both start
/// from it.
struct LightPoint {
    LightSampler::Choice choice;
    std::optional<LightSample> sample;  ///< empty when no light was chosen or it gave no point
};

/// Which distribution chooses the light of a light point.
enum class LightChoice {
    /// The scene's distribution for the receiving point (the light tree unless the scene
    /// asks for light_sampler = "power"); MIS asks LightSampler::pmf(p, light).
    kForPoint,
    /// Power alone, as light paths start: bdpt (and vcm, mlt) weigh the s = 1 light point
    /// against light subpaths that began there, so both must choose lights alike.
    kByPower,
};

/// Chooses a light with `u_light` and samples a point on it as seen from `p` (shading normal
/// `n`, zero for a point without a surface) with (u, u_select). Both members are built in
/// place (no copy of the light's sample: a copy right after the light's stores stalls the
/// CPU, see sample_scattering).
[[gnu::always_inline]] inline LightPoint sample_light_point(
    const Scene& scene, const Vec3& p, const Vec3& n, const Vec2& u, float u_light, float u_select,
    LightChoice rule = LightChoice::kForPoint) {
    const LightSampler& lights = scene.light_sampler();
    const LightSampler::Choice choice =
        rule == LightChoice::kForPoint ? lights.sample(p, n, u_light) : lights.sample(u_light);
    if (!choice.light) return LightPoint{choice, std::nullopt};
    return LightPoint{choice, LightSampler::sample_li(choice, p, u, u_select)};
}

/// A direct-light estimate at a surface point, valid if nothing blocks the way to `target`.
struct DirectLight {
    Spectrum contribution;  ///< f L |cos| / (pmf pdf), times the MIS weight
    Vec3 target;            ///< the point on the light; transmittance(scene, si, target) decides
};

/// The second half of sample_direct_light: the estimate from the light point it drew (for
/// callers that draw several points before evaluating any, so that the lights' chains of
/// square roots and divisions overlap).
[[gnu::always_inline]] inline std::optional<DirectLight> direct_light_from(
    const LightPoint& point, const SurfaceInteraction& si, const Bsdf& bsdf, const Vec3& wo_local,
    LightWeighting weighting) {
    // The light's sample is read where the light wrote it, never copied as a whole: a copy
    // right after the light's stores stalls the CPU (see sample_scattering).
    const std::optional<LightSample>& ls = point.sample;
    if (!ls || ls->L.is_black()) return std::nullopt;
    const LightSampler::Choice& choice = point.choice;
    Spectrum f_cos;
    float bsdf_pdf;
    if (!bsdf_towards_light(*ls, si, bsdf, wo_local, f_cos, bsdf_pdf)) return std::nullopt;
    const float light_pdf = choice.pmf * ls->pdf;
    // Made in place in the optional (from a temporary, the copy read it back at once and
    // waited for its stores).
    if (ls->is_delta || weighting == LightWeighting::kNone)
        return std::optional<DirectLight>(std::in_place, f_cos * ls->L / light_pdf, ls->p);
    const float weight = power_heuristic(light_pdf, bsdf_pdf);
    return std::optional<DirectLight>(std::in_place, f_cos * ls->L * (weight / light_pdf), ls->p);
}

/// The light point sample_direct_light draws, with its draws.
template <typename SamplerType = Sampler>
[[gnu::always_inline]] inline LightPoint draw_direct_light_point(const Scene& scene,
                                                                 const SurfaceInteraction& si,
                                                                 SamplerType& sampler) {
    // 2D first: the Sobol sampler hands out a 2D value and two 1D values per index shuffle.
    const Vec2 u = sampler.get_2d();
    const float u_light = sampler.get_1d();
    const float u_select = sampler.get_1d();
    return sample_light_point(scene, si.p, si.shading.n(), u, u_light, u_select);
}

/// Next-event estimation, the one estimator of direct light that every integrator uses: a
/// light chosen for the point (LightChoice::kForPoint), a point on it, the BSDF towards it. The
/// sample draws are, in this order: a 2D value for the point on the light, a 1D value choosing the
/// light, a 1D value choosing a part of it (triangle or side) -- three values that a Sobol
/// sampler serves from one group. They are drawn even when the estimate turns out empty, so
/// later draws do not depend on it. nullopt when the sample contributes nothing; the caller
/// traces the shadow ray (the path tracer traces several paths' together). `SamplerType` is
/// Sampler, or a final sampler class where the caller knows which one it has (its draws are
/// then direct calls, inlined).
template <typename SamplerType = Sampler>
[[gnu::always_inline]] inline std::optional<DirectLight> sample_direct_light(
    const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf, const Vec3& wo_local,
    SamplerType& sampler, LightWeighting weighting) {
    const LightPoint point = draw_direct_light_point(scene, si, sampler);
    return direct_light_from(point, si, bsdf, wo_local, weighting);
}

/// sample_direct_light, with its shadow ray traced (and counted): the direct light arriving
/// at `si` towards si.wo.
Spectrum estimate_direct_light(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                               Sampler& sampler, LightWeighting weighting, RayCounter& counter);

/// A direction chosen by BSDF sampling, in world space, with the sample that chose it.
struct Scattering {
    BsdfSample sample;  ///< in the local shading frame
    Vec3 wi;            ///< the same direction in world space
    Spectrum weight;    ///< f |cos theta_i| / pdf: the factor the throughput takes
};

/// sample_scattering's work, into `out`: false when the path ends there.
inline bool scatter_into(const SurfaceInteraction& si, const Bsdf& bsdf, const Vec3& wo_local,
                         const Vec2& u, float u_lobe, TransportMode mode, Scattering& out) {
    BsdfSample& bs = out.sample;
    // The geometric normal matters only to importance (the shading-normal correction).
    const bool sampled = mode == TransportMode::kRadiance
                             ? bsdf.sample(wo_local, u, u_lobe, bs)
                             : bsdf.sample(wo_local, u, u_lobe, bs, mode, si.to_local(si.ng));
    if (!sampled || bs.pdf <= 0.0f || bs.f.is_black()) return false;
    out.wi = si.to_world(bs.wi);
    const bool geometric_transmission = glm::dot(out.wi, si.ng) * glm::dot(si.wo, si.ng) < 0.0f;
    if (geometric_transmission != bs.is_transmission()) return false;
    out.weight = bs.f * (abs_cos_theta(bs.wi) / bs.pdf);
    return true;
}

/// Samples the BSDF at `si` with (u, u_lobe), carrying `mode` (radiance for camera paths,
/// importance for light paths; see bsdf.h). nullopt when the BSDF absorbs, and when the
/// sampled direction disagrees with the geometric surface (a shading normal can send a
/// "reflected" direction through the surface or the reverse): such paths would leak light
/// through surfaces, and are ended instead.
inline std::optional<Scattering> sample_scattering(const SurfaceInteraction& si, const Bsdf& bsdf,
                                                   const Vec3& wo_local, const Vec2& u,
                                                   float u_lobe,
                                                   TransportMode mode = TransportMode::kRadiance) {
    // One named result, returned on every path, so that it is the caller's storage (NRVO)
    // and the BSDF writes its sample straight there: copying a freshly written sample as a
    // whole reads it back in wider pieces than it was stored, which stalls the CPU.
    std::optional<Scattering> result;
    if (!scatter_into(si, bsdf, wo_local, u, u_lobe, mode, result.emplace())) result.reset();
    return result;
}

/// Turns `ray`, the ray that reached `si`, into the ray leaving it along a sampled
/// direction, in place: after a delta lobe it carries the incoming differentials on
/// (spawn_specular_ray), otherwise it has none.
inline void continue_ray(Ray& ray, SurfaceInteraction& si, const Scattering& scattering) {
    const BsdfSample& bs = scattering.sample;
    if (bs.is_delta())
        ray = spawn_specular_ray(si, ray, scattering.wi, bs.is_transmission(), bs.eta);
    else
        respawn_ray(ray, si, scattering.wi);
}

/// Where a ray that follows specular bounces (mirrors, smooth glass) ends.
struct SpecularChain {
    std::optional<SurfaceInteraction> hit;  ///< the first surface that is not purely specular
    HitRecord record;                       ///< Embree's record of `hit` (valid when hit is set)
    const Bsdf* bsdf = nullptr;             ///< its BSDF (null when `hit` is empty)
    Spectrum beta{1.0f};     ///< throughput from the chain's start to `hit` (or to the escape)
    Spectrum emitted{0.0f};  ///< emission seen at the chain's surfaces, `hit`'s included, times
                             ///< the throughput that reached each
    Ray ray;                 ///< the last ray traced; where an escaped chain left the scene
    bool escaped = false;    ///< the chain left the scene (the caller decides what it sees there)
};

/// Follows `ray` with throughput `beta` through delta BSDFs, sampling one lobe at each (a
/// 2D and a 1D draw, as BSDF sampling always takes), for at most `max_segments` rays. The
/// chain ends at the first surface whose BSDF is not purely delta, when it escapes, when a
/// surface without a BSDF (an emitter) or an absorbing sample ends it, or at the limit.
/// `aov`, when not null, receives the features of the first hit (or the miss).
SpecularChain follow_specular_chain(const Scene& scene, Ray ray, Spectrum beta, Sampler& sampler,
                                    Arena& arena, RayCounter& counter, int max_segments,
                                    AovSample* aov);

}  // namespace glint
