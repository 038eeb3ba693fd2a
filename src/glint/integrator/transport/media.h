#pragma once
// Which medium a ray travels through, by the rules every walk that meets media shares:
//
//   medium_beyond      the medium a ray leaving a surface enters
//   medium_containing  the medium around a point, found by a probe ray: where a light path
//                      starts (a light names no medium of its own)
//   walk_media         the media a render's walks start in: the camera's, each light's
//   through_medium     one segment of a walk through a medium by delta tracking: where it
//                      scatters, or what reaches the segment's end
//   walk_legs          the legs of a ray between the interfaces one traversal passed
//
// Media fill closed shapes (glint.interface, glass with an interior): a surface that names
// media switches the ray to the medium on the side it goes to; any other surface leaves the
// ray in the medium it was in.
#include <glint/core/interaction.h>
#include <glint/core/medium.h>
#include <glint/core/rng.h>
#include <glint/material/material.h>
#include <glint/scene/scene.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

namespace glint {

/// The medium a ray leaving `si` along `direction` enters: the surface's interior or
/// exterior where it bounds media, `current` where it bounds none.
inline const Medium* medium_beyond(const SurfaceInteraction& si, const Vec3& direction,
                                   const Medium* current) {
    const MediumInterface media = si.material->medium_interface();
    return media.is_transition() ? media.leaving(glm::dot(direction, si.ng) > 0.0f) : current;
}

/// A seed for a path's random stream (delta and ratio tracking, whose number of draws varies
/// from path to path) from one sampler draw, so that the stream is the pixel sample's as
/// every other draw is (the same for any thread count).
inline uint64_t stream_seed(float u) {
    return mix_bits(std::bit_cast<uint32_t>(u) + 0x5eedULL);
}

/// The legs of `traced` between the interfaces one traversal passed (`passed`, from
/// Scene::intersect_surface_passing), up to t_end (kInfinity: the ray left the scene). For
/// each leg in a medium, in order, calls leg(leg_ray, length), with `medium` that leg's and
/// leg_ray `traced` from where the leg starts; past each crossing `medium` becomes the one
/// beyond it. Stops where `leg` returns false (the walk scattered or ended in that leg) and
/// returns false; true once the last leg is walked.
template <typename Leg>
bool walk_legs(const Scene& scene, const Ray& traced, const PassedSurfaces& passed, float t_end,
               const Medium*& medium, Leg&& leg) {
    float t_start = 0.0f;
    for (int i = 0; i <= passed.count; ++i) {
        const float t_leg_end = i < passed.count ? passed.hits[i].t : t_end;
        if (medium) {
            // Field by field, not a copy of `traced` and then a new origin: the callers read
            // the leg's vectors at once, and loads that straddle the copy's wide stores and
            // the origin's narrow ones wait for both to complete (2 % of the preview in fog).
            Ray leg_ray;
            leg_ray.origin = traced.at(t_start);
            leg_ray.direction = traced.direction;
            leg_ray.t_min = traced.t_min;
            leg_ray.t_max = traced.t_max;
            leg_ray.time = traced.time;
            leg_ray.has_differentials = traced.has_differentials;
            leg_ray.differentials = traced.differentials;
            if (!leg(leg_ray, t_leg_end - t_start)) return false;
        }
        if (i == passed.count) break;
        const Scene::Crossing crossing = scene.passed_crossing(traced, passed.hits[i]);
        const MediumInterface media = crossing.material->medium_interface();
        if (media.is_transition()) medium = media.leaving(crossing.along_normal);
        t_start = t_leg_end;
    }
    return true;
}

/// The medium that contains `p`: the side a probe ray from p arrives at on the first surface
/// that bounds media. A probe that meets none leaves p outside every closed medium, where
/// the camera's `medium` is when the camera is outside them too (an unbounded atmosphere, as
/// the foggy Cornell box's), and vacuum otherwise.
const Medium* medium_containing(const Scene& scene, const Vec3& p);

/// The participating media a render's walks start in, found once per render (walk_media).
struct WalkMedia {
    const Medium* camera = nullptr;  ///< the medium the lens is in
    /// The medium around each light, by Light::index (medium_containing at a point it
    /// emits from).
    std::vector<const Medium*> light_start;
};
/// The scene's media for walks that sample them; nullopt when no medium a walk can be in
/// (the camera's, or one a surface bounds) scatters or emits: absorbing glass alone is taken
/// at each hit, as without media, and the walks draw nothing more.
std::optional<WalkMedia> walk_media(const Scene& scene);

/// How a walk's segment through a medium ended.
enum class SegmentEnd { kReached, kScattered, kAbsorbed };

/// The segment of `ray` through `medium` up to t_hit (kInfinity: the ray left the scene) by
/// delta tracking on channel `hero`, drawing from `rng`, as volpath's. `weight` receives the
/// factor of the throughput to the segment's end or to its scattering point, at parameter
/// `t_scatter`, where the extinction (mean over channels) is `sigma_t`. `r_u`, the walk's
/// ratios of the channels' densities (volpath's), takes the same factor where distances are
/// sampled; a medium that only absorbs is not sampled: its transmittance is the weight, the
/// same whatever the hero, and leaves r_u as it is.
///
/// With `emission` (a walk from the camera through a medium that emits), it receives the
/// radiance the medium emits along the segment towards the ray's origin, collected at every
/// tentative collision as volpath does, over the walk's channels: the caller multiplies by
/// the throughput at the segment's start.
SegmentEnd through_medium(const Medium& medium, const Ray& ray, float t_hit, int hero, Rng& rng,
                          Spectrum& weight, Spectrum& r_u, float& t_scatter, float& sigma_t,
                          Spectrum* emission = nullptr);

}  // namespace glint
