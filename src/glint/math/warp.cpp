#include <glint/math/warp.h>

namespace glint::warp {

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

}  // namespace glint::warp
