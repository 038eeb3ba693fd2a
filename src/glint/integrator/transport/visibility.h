#pragma once
// Visibility as transmittance: the fraction of light that gets from a point to a target,
// a Spectrum (0 or 1 today). Shadow rays pass through surfaces that only bound media
// (Material::is_interface), taking on the transmittance of the medium of each segment, and
// stop at every other surface. A scene without such surfaces asks Embree's occlusion query
// alone, as a boolean visibility did, so it loses no time (Scene::has_interfaces).
#include <glint/scene/scene.h>

namespace glint {

/// The transmittance along `shadow` (Scene::shadow_ray: reaching its target at t = 1,
/// traced to kShadowRayEnd) through interface surfaces, starting in `medium` (null: vacuum)
/// and taking on the medium beyond each interface that bounds one; 0 when a surface that is
/// not an interface stands in the way. Media without a closed form draw from `rng` (a fixed
/// stream when null). `passing`, when not null, receives per channel the probability that
/// volpath's delta tracking crosses the same way without a collision (the transmittance of
/// the media it samples, those that scatter or emit; 1 elsewhere), for its MIS weights.
Spectrum transmittance_through_interfaces(const Scene& scene, const Scene::ShadowRay& shadow,
                                          const Medium* medium = nullptr, Rng* rng = nullptr,
                                          Spectrum* passing = nullptr);

/// Whether volpath samples distances in `medium` (delta tracking) rather than multiplying
/// by its transmittance: where it scatters or emits.
inline bool samples_distances(const Medium& medium) {
    return medium.scatters() || medium.emits();
}

/// The transmittance of a shadow ray that starts in `medium`: Embree's occlusion query alone
/// where neither an interface nor a medium can change the answer from 0 or 1.
/// Media without a closed form draw from `rng`: pass the walk's own stream wherever one
/// exists (with null, every shadow ray draws the same fixed stream, and the same tentative
/// collisions along every ray bias an image's sum over many rays in a heterogeneous medium).
[[gnu::always_inline]] inline Spectrum transmittance(const Scene& scene,
                                                     const Scene::ShadowRay& shadow,
                                                     const Medium* medium = nullptr,
                                                     Rng* rng = nullptr) {
    if (!scene.has_interfaces() && !medium) {
        const bool blocked = scene.accel().occluded(shadow.origin, shadow.direction, 0.0f,
                                                    kShadowRayEnd, shadow.time);
        return Spectrum(blocked ? 0.0f : 1.0f);
    }
    // Nothing at all in the way: one medium along the whole ray, and Embree's cheaper
    // occlusion query tells. The walk below would find no surface and draw the same.
    if (medium && !scene.accel().occluded(shadow.origin, shadow.direction, 0.0f, kShadowRayEnd,
                                          shadow.time)) {
        Rng fixed_stream;
        const Ray ray{shadow.origin, shadow.direction, 0.0f, kShadowRayEnd, shadow.time};
        return medium->transmittance(ray, kShadowRayEnd, rng ? *rng : fixed_stream);
    }
    return transmittance_through_interfaces(scene, shadow, medium, rng);
}

/// transmittance() for the shadow rays of the lanes set in `active`, traced as packets
/// (coherent ones: from neighbouring pixels towards one light): lane i's in T[i], the same
/// value transmittance(scene, shadows[i], media[i], rngs[i]) gives, drawing the same.
void transmittance_packet(const Scene& scene, const PerLane<Scene::ShadowRay>& shadows,
                          const PerLane<const Medium*>& media, const PerLane<Rng*>& rngs,
                          uint32_t active, PerLane<Spectrum>& T);

/// The transmittance from `si` (its origin offset as spawn_ray's) to just short of `target`.
[[gnu::always_inline]] inline Spectrum transmittance(const Scene& scene,
                                                     const SurfaceInteraction& si,
                                                     const Vec3& target,
                                                     const Medium* medium = nullptr,
                                                     Rng* rng = nullptr) {
    return transmittance(scene, Scene::shadow_ray(si, target), medium, rng);
}

/// The transmittance from `origin` (already off any surface) to just short of `target`.
inline Spectrum transmittance(const Scene& scene, const Vec3& origin, const Vec3& target,
                              const Medium* medium = nullptr) {
    return transmittance(scene, Scene::ShadowRay{origin, target - origin}, medium);
}

}  // namespace glint
