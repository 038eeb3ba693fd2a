#include <glint/math/warp.h>

#include <bit>
#include <cstdint>

namespace glint::warp {

namespace {

// c ? a : b through bit masks, so the compiler cannot turn it into a branch.
float select(bool c, float a, float b) {
    const uint32_t mask = 0u - static_cast<uint32_t>(c);
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) |
                                (std::bit_cast<uint32_t>(b) & ~mask));
}

// sin and cos of an angle in [-pi/4, pi/4] by their Taylor series to x^9 and x^10 (error
// below 2e-9 there, under float rounding): no range reduction, no call into libm.
Vec2 cos_sin_quarter_turn(float a) {
    const float a2 = a * a;
    const float s =
        a *
        (1.0f + a2 * (-1.0f / 6 + a2 * (1.0f / 120 + a2 * (-1.0f / 5040 + a2 * (1.0f / 362880)))));
    const float c =
        1.0f + a2 * (-0.5f + a2 * (1.0f / 24 + a2 * (-1.0f / 720 +
                                                     a2 * (1.0f / 40320 - a2 * (1.0f / 3628800)))));
    return Vec2(c, s);
}

}  // namespace

// Shirley-Chiu. Written with selects instead of branches: which axis dominates is a coin
// flip for random input, which a branch predictor cannot learn.
Vec2 square_to_uniform_disk_concentric(const Vec2& u) {
    const Vec2 offset = 2.0f * u - Vec2(1.0f);
    if (offset.x == 0.0f && offset.y == 0.0f) return Vec2(0.0f);
    const bool x_major = std::abs(offset.x) > std::abs(offset.y);
    const float r = select(x_major, offset.x, offset.y);
    const float minor = select(x_major, offset.y, offset.x);
    // theta = phi when x dominates, pi/2 - phi otherwise, with phi in [-pi/4, pi/4].
    const Vec2 cs = cos_sin_quarter_turn((kPi / 4.0f) * (minor / r));
    return r * Vec2(select(x_major, cs.x, cs.y), select(x_major, cs.y, cs.x));
}

Vec3 square_to_cosine_hemisphere(const Vec2& u) {
    const Vec2 d = square_to_uniform_disk_concentric(u);
    const float z = safe_sqrt(1.0f - d.x * d.x - d.y * d.y);
    return Vec3(d.x, d.y, z);
}

float cosine_hemisphere_pdf(const Vec3& w) {
    return w.z > 0.0f ? w.z * kInvPi : 0.0f;
}

Vec3 square_to_uniform_hemisphere(const Vec2& u) {
    const float z = u.x;
    const float r = safe_sqrt(1.0f - z * z);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float uniform_hemisphere_pdf(const Vec3& w) {
    return w.z > 0.0f ? kInv2Pi : 0.0f;
}

Vec3 square_to_uniform_sphere(const Vec2& u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = safe_sqrt(1.0f - z * z);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float uniform_sphere_pdf() {
    return kInv4Pi;
}

Vec3 square_to_uniform_cone(const Vec2& u, float cos_theta_max) {
    const float cos_theta = 1.0f - u.x * (1.0f - cos_theta_max);
    const float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

float uniform_cone_pdf(const Vec3& w, float cos_theta_max) {
    if (w.z < cos_theta_max) return 0.0f;
    return 1.0f / (2.0f * kPi * (1.0f - cos_theta_max));
}

Vec2 square_to_uniform_triangle(const Vec2& u) {
    // Heitz 2019: area-preserving, low distortion. Selects rather than a branch on the
    // random comparison.
    const bool lower = u.x < u.y;
    const float half_x = u.x / 2.0f, half_y = u.y / 2.0f;
    const float b0 = select(lower, half_x, u.x - half_y);
    const float b1 = select(lower, u.y - half_x, half_y);
    return Vec2(b0, b1);
}

}  // namespace glint::warp
