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
    for (int crossing = 0; crossing <= kMaxInterfaceCrossings; ++crossing) {
        // Each leg reaches the target at t = 1 and stops short of it, as the first did.
        const Ray ray{origin, target - origin, 0.0f, kShadowRayEnd};
        const bool hit = scene.intersect_surface(ray, si);
        if (hit && !si.material->is_interface()) return Spectrum(0.0f);
        if (medium) {
            const Spectrum leg = medium->transmittance(ray, hit ? si.t : kShadowRayEnd, draws);
            T *= leg;
            if (samples_distances(*medium)) pass *= leg;
            if (T.is_black()) return T;
        }
        if (!hit) {
            if (passing) *passing = pass;
            return T;
        }
        const MediumInterface media = si.material->medium_interface();
        if (media.is_transition()) medium = media.leaving(glm::dot(ray.direction, si.ng) > 0.0f);
        origin = offset_ray_origin(si.p, si.ng, ray.direction);
    }
    return Spectrum(0.0f);
}

}  // namespace glint
