#include <glint/integrator/transport/visibility.h>
#include <glint/material/material.h>

namespace glint {
namespace {

// Interfaces a shadow ray crosses at most: a bound against surfaces stacked without end
// (coincident copies), where the light is taken as blocked.
constexpr int kMaxInterfaceCrossings = 256;

}  // namespace

Spectrum transmittance_through_interfaces(const Scene& scene, const Scene::ShadowRay& shadow,
                                          const Medium* medium) {
    const Vec3 target = shadow.origin + shadow.direction;
    Ray ray{shadow.origin, shadow.direction, 0.0f, kShadowRayEnd};
    Spectrum beta(1.0f);
    for (int crossing = 0; crossing < kMaxInterfaceCrossings; ++crossing) {
        SurfaceInteraction si;
        if (!scene.intersect(ray, si)) {
            // The last segment, up to the target, runs in the medium the ray is in.
            if (medium) beta *= medium->transmittance(ray, kShadowRayEnd);
            return beta;
        }
        if (!si.material->is_interface()) return Spectrum(0.0f);
        if (medium) beta *= medium->transmittance(ray, si.t);
        if (beta.is_black()) return beta;
        // The ray carries its medium across: into the one on the far side, where the
        // surface separates two.
        const MediumInterface media = si.material->medium_interface();
        if (media.is_transition()) medium = media.leaving(!si.front_face);
        // On from just past the interface, towards the same target.
        const Vec3 origin = offset_ray_origin(si.p, si.ng, ray.direction);
        ray = Ray{origin, target - origin, 0.0f, kShadowRayEnd};
    }
    return Spectrum(0.0f);
}

}  // namespace glint
