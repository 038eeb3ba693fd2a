#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/material/material.h>

namespace glint {
namespace {

// A shadow ray meets at most this many interfaces; beyond, it counts as blocked (a guard
// against a ray trapped between coincident surfaces).
constexpr int kMaxInterfaceCrossings = 256;

}  // namespace

Spectrum transmittance_through_interfaces(const Scene& scene, const Scene::ShadowRay& shadow,
                                          const Medium* medium, Rng* rng, Spectrum* passing) {
    Rng fixed_stream;
    Rng& draws = rng ? *rng : fixed_stream;
    Spectrum T(1.0f), pass(1.0f);
    const auto take_leg = [&](const Ray& leg, float length) {
        const Spectrum factor = medium->transmittance(leg, length, draws);
        T *= factor;
        if (samples_distances(*medium)) pass *= factor;
        return !T.is_black();
    };
    PassedSurfaces passed;
    // Where Embree skips every interface, one any-hit traversal finds what blocks the ray
    // or else all it crosses: an opaque surface ends it early, as for any shadow ray.
    if (scene.interfaces_skippable()) {
        const Ray ray{shadow.origin, shadow.direction, 0.0f, kShadowRayEnd, shadow.time};
        if (const std::optional<bool> blocked = scene.accel().occluded_passing(ray, passed)) {
            if (*blocked) return Spectrum(0.0f);
            if (walk_legs(scene, ray, passed, kShadowRayEnd, medium, take_leg) && passing)
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
            walk_legs(scene, ray, passed, hit ? si.t : kShadowRayEnd, medium, take_leg);
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

}  // namespace glint
