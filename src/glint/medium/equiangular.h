#pragma once
// Equiangular sampling of a distance along a ray towards a point light (Kulla and Fajardo
// 2012, "Importance sampling techniques for path tracing in participating media"): t is
// drawn uniformly in the angle it subtends at the light, so its density follows the
// light's 1 / r^2 falloff. Near a small light in thin fog that falloff, not the
// transmittance, is what the in-scattered light varies with, and distances drawn by
// transmittance leave the glow round the light noisy.
//
// Parametrised by the point's projection onto the ray (delta, the parameter of the closest
// approach) and its distance D from the ray's line: t = delta + D tan(theta), theta uniform
// between the angles of the segment's ends, density D / ((theta_b - theta_a) (D^2 +
// (t - delta)^2)).
#include <glint/core/ray.h>

#include <cmath>
#include <optional>

namespace glint {

struct Equiangular {
    float delta = 0.0f;  ///< parameter of the ray's point closest to the light point
    float D = 0.0f;      ///< the light point's distance from the ray's line (> 0)
    float theta_a = 0.0f, theta_b = 0.0f;

    /// Towards `light` along [0, t_end) of `ray` (unit direction; t_end may be infinite);
    /// nullopt where the light lies on the ray's line (no angle to spread over) or the
    /// segment is empty.
    static std::optional<Equiangular> towards(const Ray& ray, const Vec3& light, float t_end) {
        const Vec3 to_light = light - ray.origin;
        Equiangular e;
        e.delta = glm::dot(to_light, ray.direction);
        const Vec3 across = to_light - e.delta * ray.direction;
        e.D = std::sqrt(glm::dot(across, across));
        // Below about 1e-5 of the light's distance the angles round to +-pi/2.
        if (!(e.D > 1e-5f * std::abs(e.delta)) || !(e.D > 0.0f) || !(t_end > 0.0f))
            return std::nullopt;
        e.theta_a = std::atan2(-e.delta, e.D);
        // The float below pi/2: 0.5f * kPi rounds above it, where tan turns negative.
        e.theta_b =
            std::isinf(t_end) ? std::nextafter(0.5f * kPi, 0.0f) : std::atan2(t_end - e.delta, e.D);
        if (!(e.theta_b > e.theta_a)) return std::nullopt;
        return e;
    }

    /// A distance for u in [0, 1); within [0, t_end] up to rounding (the caller clamps).
    float sample(float u) const {
        const float theta = theta_a + u * (theta_b - theta_a);
        return delta + D * std::tan(theta);
    }

    /// The density of sample() at t (inside the segment).
    float pdf(float t) const {
        const float offset = t - delta;
        return D / ((theta_b - theta_a) * (D * D + offset * offset));
    }
};

}  // namespace glint
