#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/material/material.h>

namespace glint {
namespace {

// A shadow ray meets at most this many interfaces; beyond, it counts as blocked (a guard
// against a ray trapped between coincident surfaces).
constexpr int kMaxInterfaceCrossings = 256;

// Takes on the transmittance of the legs of `ray` between the interfaces it crosses
// (`passed`, in order) up to t_end, each in its medium (`medium` becomes the last leg's):
// `T`, and `pass` as `passing` below, are multiplied leg by leg. False once T is black.
bool take_legs(const Scene& scene, const Ray& ray, const PassedSurfaces& passed, float t_end,
               const Medium*& medium, Rng& draws, Spectrum& T, Spectrum& pass) {
    return walk_legs(scene, ray, passed, t_end, medium, [&](const Ray& leg, float length) {
        const Spectrum factor = medium->transmittance(leg, length, draws);
        T *= factor;
        if (samples_distances(*medium)) pass *= factor;
        return !T.is_black();
    });
}

}  // namespace

Spectrum transmittance_through_interfaces(const Scene& scene, const Scene::ShadowRay& shadow,
                                          const Medium* medium, Rng* rng, Spectrum* passing) {
    Rng fixed_stream;
    Rng& draws = rng ? *rng : fixed_stream;
    Spectrum T(1.0f), pass(1.0f);
    PassedSurfaces passed;
    // Where Embree skips every interface, one any-hit traversal finds what blocks the ray
    // or else all it crosses: an opaque surface ends it early, as for any shadow ray.
    if (scene.interfaces_skippable()) {
        const Ray ray{shadow.origin, shadow.direction, 0.0f, kShadowRayEnd, shadow.time};
        if (const std::optional<bool> blocked = scene.accel().occluded_passing(ray, passed)) {
            if (*blocked) return Spectrum(0.0f);
            if (take_legs(scene, ray, passed, kShadowRayEnd, medium, draws, T, pass) && passing)
                *passing = pass;
            return T;
        }
    }
    Vec3 origin = shadow.origin;
    const Vec3 target = shadow.origin + shadow.direction;
    SurfaceInteraction si;
    for (int crossings = 0; crossings <= kMaxInterfaceCrossings;) {
        // Each trace reaches the target at t = 1 and stops short of it, as the first did.
        // It goes past the interfaces Embree can skip (Scene::intersect_surface_passing),
        // which split it into legs, each in its own medium.
        const Ray ray{origin, target - origin, 0.0f, kShadowRayEnd, shadow.time};
        const bool hit = scene.intersect_surface_passing(ray, si, passed);
        if (hit && !si.material->is_interface()) return Spectrum(0.0f);
        const bool through =
            take_legs(scene, ray, passed, hit ? si.t : kShadowRayEnd, medium, draws, T, pass);
        if (!through) return T;
        crossings += passed.count + 1;
        if (!hit) {
            if (passing) *passing = pass;
            return T;
        }
        medium = medium_beyond(si, ray.direction, medium);
        origin = offset_ray_origin(si.p, si.ng, ray.direction);
    }
    return Spectrum(0.0f);
}

void transmittance_packet(const Scene& scene, const PerLane<Scene::ShadowRay>& shadows,
                          const PerLane<const Medium*>& media, const PerLane<Rng*>& rngs,
                          uint32_t active, PerLane<Spectrum>& T) {
    PerLane<Vec3> origins, directions;
    PerLane<float> times;
    for_each_lane(active, [&](int lane) {
        origins[lane] = shadows[lane].origin;
        directions[lane] = shadows[lane].direction;
        times[lane] = shadows[lane].time;
    });
    // As transmittance() per lane: Embree's occlusion query alone first where it may tell
    // (no interfaces and no medium; or a medium, and nothing at all in the way).
    uint32_t plain = 0;
    for_each_lane(active, [&](int lane) {
        if (media[lane] || !scene.has_interfaces()) plain |= 1u << lane;
    });
    uint32_t walked = active & ~plain;  // lanes left to transmittance_through_interfaces
    if (plain != 0) {
        const uint32_t blocked = scene.occluded_packet(origins, directions, times, plain, true);
        for_each_lane(plain, [&](int lane) {
            const bool is_blocked = (blocked >> lane) & 1u;
            if (!media[lane]) {
                T[lane] = Spectrum(is_blocked ? 0.0f : 1.0f);
            } else if (is_blocked) {
                walked |= 1u << lane;
            } else {
                Rng fixed_stream;
                const Ray ray{origins[lane], directions[lane], 0.0f, kShadowRayEnd, times[lane]};
                T[lane] = media[lane]->transmittance(ray, kShadowRayEnd,
                                                     rngs[lane] ? *rngs[lane] : fixed_stream);
            }
        });
    }
    if (walked == 0) return;
    // transmittance_through_interfaces()'s any-hit traversal, for the lanes together.
    uint32_t alone = walked;
    if (scene.interfaces_skippable()) {
        PerLane<PassedSurfaces> passed;
        uint32_t overflowed = 0;
        const uint32_t blocked = scene.accel().occluded_packet_passing(
            origins, directions, times, kShadowRayEnd, walked, passed, overflowed, true);
        alone = overflowed;
        for_each_lane(walked & ~overflowed, [&](int lane) {
            if ((blocked >> lane) & 1u) {
                T[lane] = Spectrum(0.0f);
                return;
            }
            Rng fixed_stream;
            Spectrum lane_T(1.0f), pass(1.0f);
            const Medium* medium = media[lane];
            const Ray ray{origins[lane], directions[lane], 0.0f, kShadowRayEnd, times[lane]};
            take_legs(scene, ray, passed[lane], kShadowRayEnd, medium,
                      rngs[lane] ? *rngs[lane] : fixed_stream, lane_T, pass);
            T[lane] = lane_T;
        });
    }
    for_each_lane(alone, [&](int lane) {
        T[lane] = transmittance_through_interfaces(scene, shadows[lane], media[lane], rngs[lane]);
    });
}

}  // namespace glint
