#pragma once
// A smooth interface between two dielectrics (glass, water): exact Fresnel reflectance,
// Snell refraction, total internal reflection. Radiance is scaled by 1/eta^2 on
// refraction because the solid angle is compressed (Veach 1997, ch. 5).
#include <glint/material/bsdf.h>
#include <glint/material/fresnel.h>

namespace glint {

class SmoothDielectricBsdf final : public Bsdf {
public:
    // `eta` = index inside / index outside (outside is the side the normal points to).
    explicit SmoothDielectricBsdf(float eta)
        : Bsdf(kBsdfReflection | kBsdfTransmission | kBsdfDelta), m_eta(eta) {}

    Spectrum eval(const Vec3&, const Vec3&) const override { return Spectrum(0.0f); }
    float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }

    std::optional<BsdfSample> sample(const Vec3& wo, const Vec2&, float u_lobe) const override {
        const float cos_o = cos_theta(wo);
        if (cos_o == 0.0f) return std::nullopt;
        const float reflectance = fresnel_dielectric(cos_o, m_eta);
        if (u_lobe < reflectance) {
            const Vec3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample{Spectrum(reflectance / abs_cos_theta(wi)), wi, reflectance,
                              kBsdfReflection | kBsdfDelta, 1.0f};
        }
        // Relative index across the interface in the direction the light path travels.
        const float eta = cos_o > 0.0f ? m_eta : 1.0f / m_eta;
        const Vec3 n(0.0f, 0.0f, cos_o > 0.0f ? 1.0f : -1.0f);
        Vec3 wi;
        if (!refract(wo, n, eta, wi)) return std::nullopt;  // unreachable: TIR has R = 1
        const float transmittance = 1.0f - reflectance;
        const Spectrum f(transmittance / (eta * eta) / abs_cos_theta(wi));
        return BsdfSample{f, wi, transmittance, kBsdfTransmission | kBsdfDelta, eta};
    }

private:
    float m_eta;
};

}  // namespace glint
