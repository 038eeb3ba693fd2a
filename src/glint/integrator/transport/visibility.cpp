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
    SurfaceInteraction si, crossing;
    PassedSurfaces passed;
    // The transmittance of `medium` from t_start to t_end along `ray`.
    const auto through = [&](const Ray& ray, float t_start, float t_end) {
        Ray leg = ray;
        leg.origin = ray.at(t_start);
        const Spectrum factor = medium->transmittance(leg, t_end - t_start, draws);
        T *= factor;
        if (samples_distances(*medium)) pass *= factor;
    };
    for (int crossings = 0; crossings <= kMaxInterfaceCrossings;) {
        // Each trace reaches the target at t = 1 and stops short of it, as the first did.
        // It goes past the interfaces Embree can skip (Scene::intersect_surface_passing),
        // which split it into legs, each in its own medium.
        const Ray ray{origin, target - origin, 0.0f, kShadowRayEnd, shadow.time};
        const bool hit = scene.intersect_surface_passing(ray, si, passed);
        if (hit && !si.material->is_interface()) return Spectrum(0.0f);
        float t_start = 0.0f;
        for (int i = 0; i < passed.count; ++i) {
            if (medium) through(ray, t_start, passed.hits[i].t);
            if (T.is_black()) return T;
            scene.passed_surface(ray, passed.hits[i], crossing);
            const MediumInterface media = crossing.material->medium_interface();
            if (media.is_transition())
                medium = media.leaving(glm::dot(ray.direction, crossing.ng) > 0.0f);
            t_start = passed.hits[i].t;
        }
        crossings += passed.count + 1;
        if (medium) through(ray, t_start, hit ? si.t : kShadowRayEnd);
        if (T.is_black()) return T;
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
