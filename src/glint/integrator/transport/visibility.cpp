#include <glint/integrator/transport/visibility.h>
#include <glint/material/material.h>

namespace glint {

Spectrum transmittance_through_interfaces(const Scene& scene, const Scene::ShadowRay& shadow,
                                          const Medium* medium) {
    const Ray ray{shadow.origin, shadow.direction, 0.0f, kShadowRayEnd};
    // Scene::intersect passes through interfaces: what it finds blocks the way. The ray
    // keeps the medium it started in, since no interface carries media yet; once they do,
    // this walk stops at each one and takes on the medium beyond it.
    SurfaceInteraction si;
    if (scene.intersect(ray, si)) return Spectrum(0.0f);
    Rng closed_form;  // see segment_transmittance
    return medium ? medium->transmittance(ray, kShadowRayEnd, closed_form) : Spectrum(1.0f);
}

}  // namespace glint
