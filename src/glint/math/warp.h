#pragma once
// Warps from the unit square to common domains, each with its density. Every warp here
// has a chi-square test in tests/math/test_warp.cpp.
#include <glint/math/vector.h>

#include <bit>
#include <cstdint>

namespace glint::warp {

// Inline (defined below): BSDF and light sampling call these at every bounce.
inline Vec2 square_to_uniform_disk_concentric(const Vec2& u);

inline Vec3 square_to_cosine_hemisphere(const Vec2& u);
float cosine_hemisphere_pdf(const Vec3& w);

Vec3 square_to_uniform_hemisphere(const Vec2& u);
float uniform_hemisphere_pdf(const Vec3& w);

Vec3 square_to_uniform_sphere(const Vec2& u);
float uniform_sphere_pdf();

// Directions within `cos_theta_max` of +z, uniform in solid angle.
Vec3 square_to_uniform_cone(const Vec2& u, float cos_theta_max);
float uniform_cone_pdf(const Vec3& w, float cos_theta_max);

// Barycentric coordinates (b1, b2) uniform over a triangle. Inline, as above.
inline Vec2 square_to_uniform_triangle(const Vec2& u);

namespace detail {

// c ? a : b through bit masks, so the compiler cannot turn it into a branch.
inline float select(bool c, float a, float b) {
    const uint32_t mask = 0u - static_cast<uint32_t>(c);
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) |
                                (std::bit_cast<uint32_t>(b) & ~mask));
}

// sin and cos of an angle in [-pi/4, pi/4] by their Taylor series to x^9 and x^10 (error
// below 2e-9 there, under float rounding): no range reduction, no call into libm.
inline Vec2 cos_sin_quarter_turn(float a) {
    const float a2 = a * a;
    const float s =
        a *
        (1.0f + a2 * (-1.0f / 6 + a2 * (1.0f / 120 + a2 * (-1.0f / 5040 + a2 * (1.0f / 362880)))));
    const float c =
        1.0f + a2 * (-0.5f + a2 * (1.0f / 24 + a2 * (-1.0f / 720 +
                                                     a2 * (1.0f / 40320 - a2 * (1.0f / 3628800)))));
    return Vec2(c, s);
}

}  // namespace detail

// Shirley-Chiu. Written with selects instead of branches: which axis dominates is a coin
// flip for random input, which a branch predictor cannot learn.
inline Vec2 square_to_uniform_disk_concentric(const Vec2& u) {
    const Vec2 offset = 2.0f * u - Vec2(1.0f);
    if (offset.x == 0.0f && offset.y == 0.0f) return Vec2(0.0f);
    const bool x_major = std::abs(offset.x) > std::abs(offset.y);
    const float r = detail::select(x_major, offset.x, offset.y);
    const float minor = detail::select(x_major, offset.y, offset.x);
    // theta = phi when x dominates, pi/2 - phi otherwise, with phi in [-pi/4, pi/4].
    const Vec2 cs = detail::cos_sin_quarter_turn((kPi / 4.0f) * (minor / r));
    return r * Vec2(detail::select(x_major, cs.x, cs.y), detail::select(x_major, cs.y, cs.x));
}

inline Vec3 square_to_cosine_hemisphere(const Vec2& u) {
    const Vec2 d = square_to_uniform_disk_concentric(u);
    const float z = safe_sqrt(1.0f - d.x * d.x - d.y * d.y);
    return Vec3(d.x, d.y, z);
}

inline Vec2 square_to_uniform_triangle(const Vec2& u) {
    // Heitz 2019: area-preserving, low distortion. Selects rather than a branch on the
    // random comparison.
    const bool lower = u.x < u.y;
    const float half_x = u.x / 2.0f, half_y = u.y / 2.0f;
    const float b0 = detail::select(lower, half_x, u.x - half_y);
    const float b1 = detail::select(lower, u.y - half_x, half_y);
    return Vec2(b0, b1);
}

}  // namespace glint::warp
