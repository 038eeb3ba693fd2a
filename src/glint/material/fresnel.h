#pragma once
#include <glint/core/spectrum.h>
#include <glint/math/vector.h>

#include <complex>

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

// Unpolarised Fresnel reflectance of a conductor (a metal) whose complex index relative to
// the outside medium is eta + i k, for light arriving from outside at cos_theta_i in [0, 1].
// The same equations as the dielectric case with a complex index: Snell's law gives a complex
// cos_theta_t, and the reflectance is the mean of the squared magnitudes of the parallel and
// perpendicular amplitude ratios (Born & Wolf, sec. 14.2). k = 0 gives fresnel_dielectric.
inline float fresnel_conductor(float cos_theta_i, float eta, float k) {
    using Complex = std::complex<float>;
    cos_theta_i = std::clamp(cos_theta_i, 0.0f, 1.0f);
    const Complex n(eta, k);
    const float sin2_i = 1.0f - cos_theta_i * cos_theta_i;
    const Complex cos_t = std::sqrt(Complex(1.0f) - sin2_i / (n * n));
    const Complex r_parallel = (n * cos_theta_i - cos_t) / (n * cos_theta_i + cos_t);
    const Complex r_perpendicular = (cos_theta_i - n * cos_t) / (cos_theta_i + n * cos_t);
    return 0.5f * (std::norm(r_parallel) + std::norm(r_perpendicular));
}

// With a complex index that varies with wavelength: the formula above at each of the
// Spectrum's values (its channels today, its wavelengths in a spectral mode).
inline Spectrum fresnel_conductor(float cos_theta_i, const Spectrum& eta, const Spectrum& k) {
    return map(eta, k, [cos_theta_i](float eta_v, float k_v) {
        return fresnel_conductor(cos_theta_i, eta_v, k_v);
    });
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
