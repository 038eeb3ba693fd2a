#pragma once
// The closed-form check of single scattering that the media tests of volpath, the light
// tracer and bdpt share: a point light in an infinite homogeneous medium the camera stands in.
#include <glint/camera/camera.h>
#include <glint/medium/henyey_greenstein.h>

#include <cmath>

namespace glint::test {

/// The mean over a film of film_size x film_size pixels of the light a point light (intensity
/// I at `light`) scatters once towards the camera, the camera and the light in an infinite
/// medium of scattering sigma_s, extinction sigma_t and Henyey-Greenstein asymmetry g:
///   L(ray) = int_0^inf exp(-sigma_t t) sigma_s p(theta(t)) I exp(-sigma_t r(t)) / r(t)^2 dt,
/// r(t) the distance from the ray's point at t to the light. By the midpoint rule over
/// rays_per_side^2 rays across the film (through the lens's centre) and `steps` along each,
/// to 40 mean free paths.
inline double single_scattering_film_mean(const Camera& camera, int film_size, double sigma_s,
                                          double sigma_t, float g, float intensity,
                                          const Vec3& light, int rays_per_side, int steps) {
    const HenyeyGreenstein phase(g);
    const double t_end = 40.0 / sigma_t, dt = t_end / steps;
    const float spacing = static_cast<float>(film_size) / static_cast<float>(rays_per_side);
    double total = 0.0;
    for (int j = 0; j < rays_per_side; ++j) {
        for (int i = 0; i < rays_per_side; ++i) {
            const Vec2 film((static_cast<float>(i) + 0.5f) * spacing,
                            (static_cast<float>(j) + 0.5f) * spacing);
            const Ray ray = camera.generate_ray(film, Vec2(0.5f));
            const Vec3 d = glm::normalize(ray.direction);
            double sum = 0.0;
            for (int k = 0; k < steps; ++k) {
                const double t = (k + 0.5) * dt;
                const Vec3 p = ray.origin + static_cast<float>(t) * d;
                const Vec3 to_light = light - p;
                const double r = glm::length(to_light);
                const double p_phase = phase.eval(-d, to_light / static_cast<float>(r));
                sum += std::exp(-sigma_t * (t + r)) * sigma_s * p_phase * intensity / (r * r);
            }
            total += sum * dt;
        }
    }
    return total / (static_cast<double>(rays_per_side) * rays_per_side);
}

}  // namespace glint::test
