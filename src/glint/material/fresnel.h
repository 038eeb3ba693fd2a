#pragma once
#include <glint/math/vector.h>

namespace glint {

// Unpolarised Fresnel reflectance of a dielectric interface. `cos_theta_i` is signed:
// negative means the light arrives from the inside; `eta` = n_inside / n_outside.
inline float fresnel_dielectric(float cos_theta_i, float eta) {
    cos_theta_i = std::clamp(cos_theta_i, -1.0f, 1.0f);
    if (cos_theta_i < 0.0f) {
        eta = 1.0f / eta;
        cos_theta_i = -cos_theta_i;
    }
    const float sin2_t = (1.0f - cos_theta_i * cos_theta_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;  // total internal reflection
    const float cos_theta_t = safe_sqrt(1.0f - sin2_t);
    const float r_parallel = (eta * cos_theta_i - cos_theta_t) / (eta * cos_theta_i + cos_theta_t);
    const float r_perpendicular =
        (cos_theta_i - eta * cos_theta_t) / (cos_theta_i + eta * cos_theta_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

// Refracts `wi` (pointing away from the surface) about normal `n` on its side, with
// `eta` = n_transmitted / n_incident. False on total internal reflection.
inline bool refract(const Vec3& wi, const Vec3& n, float eta, Vec3& wt) {
    const float cos_i = glm::dot(n, wi);
    const float sin2_i = std::max(0.0f, 1.0f - cos_i * cos_i);
    const float sin2_t = sin2_i / (eta * eta);
    if (sin2_t >= 1.0f) return false;
    const float cos_t = safe_sqrt(1.0f - sin2_t);
    wt = -wi / eta + (cos_i / eta - cos_t) * n;
    return true;
}

inline Vec3 reflect(const Vec3& wo, const Vec3& n) {
    return -wo + 2.0f * glm::dot(wo, n) * n;
}

}  // namespace glint
