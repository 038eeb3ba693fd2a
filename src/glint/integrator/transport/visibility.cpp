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
    Vec3 origin = shadow.origin;
    const Vec3 target = shadow.origin + shadow.direction;
    SurfaceInteraction si;
    PassedSurfaces passed;
    for (int crossings = 0; crossings <= kMaxInterfaceCrossings;) {
        // Each trace reaches the target at t = 1 and stops short of it, as the first did.
        // It goes past the interfaces Embree can skip (Scene::intersect_surface_passing),
        // which split it into legs, each in its own medium.
        const Ray ray{origin, target - origin, 0.0f, kShadowRayEnd, shadow.time};
        const bool hit = scene.intersect_surface_passing(ray, si, passed);
        if (hit && !si.material->is_interface()) return Spectrum(0.0f);
        const bool through = walk_legs(scene, ray, passed, hit ? si.t : kShadowRayEnd, medium,
                                       [&](const Ray& leg, float length) {
                                           const Spectrum factor =
                                               medium->transmittance(leg, length, draws);
                                           T *= factor;
                                           if (samples_distances(*medium)) pass *= factor;
                                           return !T.is_black();
                                       });
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
