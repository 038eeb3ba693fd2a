#include <glint/math/warp.h>

namespace glint::warp {

Vec2 square_to_uniform_disk_concentric(const Vec2& u) {
    const Vec2 offset = 2.0f * u - Vec2(1.0f);
    if (offset.x == 0.0f && offset.y == 0.0f) return Vec2(0.0f);
    float r, theta;
    if (std::abs(offset.x) > std::abs(offset.y)) {
        r = offset.x;
        theta = (kPi / 4.0f) * (offset.y / offset.x);
    } else {
        r = offset.y;
        theta = kPi / 2.0f - (kPi / 4.0f) * (offset.x / offset.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
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
    // Heitz 2019: area-preserving, low distortion.
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2.0f;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2.0f;
        b0 = u.x - b1;
    }
    return Vec2(b0, b1);
}

}  // namespace glint::warp
