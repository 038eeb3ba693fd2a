#pragma once
// A smooth interface between two dielectrics (glass, water): exact Fresnel reflectance,
// Snell refraction, total internal reflection. The 1/eta^2 that radiance picks up on
// refraction, because the solid angle is compressed (Veach 1997, ch. 5), is applied by the
// Bsdf wrappers in radiance mode (bsdf.h); this class gives f without it.
#include <glint/material/bsdf.h>
#include <glint/material/fresnel.h>

namespace glint {

class SmoothDielectricBsdf final : public Bsdf {
public:
    // `eta` = index inside / index outside (outside is the side the normal points to).
    // `hero_only`: the index is that of the hero wavelength of a dispersive glass, so f is
    // carried by the hero alone (Spectrum::hero_only).
    explicit SmoothDielectricBsdf(float eta, bool hero_only = false)
        : Bsdf(kBsdfReflection | kBsdfTransmission | kBsdfDelta, eta),
          m_eta(eta),
          m_hero_only(hero_only) {}

protected:
    Spectrum eval_unscaled(const Vec3&, const Vec3&) const override { return Spectrum(0.0f); }
    float pdf_unscaled(const Vec3&, const Vec3&) const override { return 0.0f; }

    bool sample_unscaled(const Vec3& wo, const Vec2&, float u_lobe,
                         BsdfSample& out) const override {
        const float cos_o = cos_theta(wo);
        if (cos_o == 0.0f) return false;
        const float reflectance = fresnel_dielectric(cos_o, m_eta);
        if (u_lobe < reflectance) {
            out = reflection(wo, reflectance, reflectance);
            return true;
        }
        const float transmittance = 1.0f - reflectance;
        // Never nullopt here: total internal reflection has reflectance 1.
        const std::optional<BsdfSample> refracted = refraction(wo, transmittance, transmittance);
        if (!refracted) return false;
        out = *refracted;
        return true;
    }

    DeltaLobes delta_lobes_unscaled(const Vec3& wo) const override {
        DeltaLobes lobes;
        const float cos_o = cos_theta(wo);
        if (cos_o == 0.0f) return lobes;
        const float reflectance = fresnel_dielectric(cos_o, m_eta);
        if (reflectance > 0.0f) lobes.add(reflection(wo, reflectance, 1.0f));
        if (reflectance < 1.0f) {
            if (const auto t = refraction(wo, 1.0f - reflectance, 1.0f)) lobes.add(*t);
        }
        return lobes;
    }

private:
    // The mirror lobe of weight `weight`, chosen with probability `pdf`.
    BsdfSample reflection(const Vec3& wo, float weight, float pdf) const {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        return BsdfSample{carried(weight / abs_cos_theta(wi)), wi, pdf,
                          kBsdfReflection | kBsdfDelta, 1.0f};
    }

    // The refracted lobe of weight `weight` (before any 1/eta^2), chosen with probability `pdf`.
    std::optional<BsdfSample> refraction(const Vec3& wo, float weight, float pdf) const {
        const float cos_o = cos_theta(wo);
        // Relative index across the interface in the direction the light path travels.
        const float eta = cos_o > 0.0f ? m_eta : 1.0f / m_eta;
        const Vec3 n(0.0f, 0.0f, cos_o > 0.0f ? 1.0f : -1.0f);
        Vec3 wi;
        if (!refract(wo, n, eta, wi)) return std::nullopt;
        return BsdfSample{carried(weight / abs_cos_theta(wi)), wi, pdf,
                          kBsdfTransmission | kBsdfDelta, eta};
    }

    // The value at the hero alone (the others 0): the film reads a path that went
    // through here at its hero (core/secondary_wavelengths.h).
    Spectrum carried(float f) const {
        return m_hero_only ? Spectrum(f).hero_only() / static_cast<float>(Spectrum::kValues)
                           : Spectrum(f);
    }

    float m_eta;
    bool m_hero_only;
};

}  // namespace glint
