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
// between the angles theta_a and theta_b of the segment's ends, density
// D / ((theta_b - theta_a) (D^2 + (t - delta)^2)). Only the spread theta_b - theta_a is
// kept, from one atan2 of the two ends' tangents (tan(b - a) from tan a and tan b), and a
// draw phi = u (theta_b - theta_a) past theta_a becomes, by the tangent of a sum with
// tan(theta_a) = -delta / D,
//   t = tan(phi) (delta^2 + D^2) / (D + delta tan(phi)).
// One arc tangent fewer per point than the angles themselves, and no difference of two
// angles near pi / 2 (a light far behind the ray's start), which loses the spread's digits.
#include <glint/core/ray.h>
#include <glint/math/arctangent.h>

#include <cmath>
#include <optional>

namespace glint {

struct Equiangular {
    float delta = 0.0f;      ///< parameter of the ray's point closest to the light point
    float D = 0.0f;          ///< the light point's distance from the ray's line (> 0)
    float spread = 0.0f;     ///< theta_b - theta_a, the angle the segment subtends (0, pi)
    float distance2 = 0.0f;  ///< delta^2 + D^2: the light point's squared distance from the start

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
        e.distance2 = e.delta * e.delta + e.D * e.D;
        // tan(theta_a) = -delta / D and tan(theta_b) = (t_end - delta) / D, so that
        // tan(theta_b - theta_a) = t_end D / (D^2 - delta (t_end - delta)); towards an
        // infinite end, D / -delta.
        e.spread = std::isinf(t_end)
                       ? atan2_finite(e.D, -e.delta)
                       : atan2_finite(t_end * e.D, e.D * e.D - e.delta * (t_end - e.delta));
        if (!(e.spread > 0.0f)) return std::nullopt;
        return e;
    }

    /// A distance for u in [0, 1); within [0, t_end] up to rounding (the caller clamps).
    /// At the far end of an infinite segment rounding can carry the angle past pi/2, where
    /// the formula turns negative: that comes out infinite, which clamping makes t_end.
    float sample(float u) const {
        const float tan_phi = std::tan(u * spread);
        const float t = tan_phi * distance2 / (D + delta * tan_phi);
        return t < 0.0f ? kInfinity : t;
    }

    /// The density of sample() at t (inside the segment).
    float pdf(float t) const {
        const float offset = t - delta;
        return D / (spread * (D * D + offset * offset));
    }
};

}  // namespace glint
