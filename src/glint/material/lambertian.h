#pragma once
// Ideal diffuse reflection, two-sided: it reflects on whichever side the viewer is.
#include <glint/material/bsdf.h>
#include <glint/math/warp.h>

namespace glint {

class LambertianBsdf final : public Bsdf {
public:
    explicit LambertianBsdf(const Spectrum& reflectance)
        : Bsdf(kBsdfReflection | kBsdfDiffuse), m_f(reflectance * kInvPi) {}

protected:
    Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const override {
        return same_hemisphere(wo, wi) ? m_f : Spectrum(0.0f);
    }
    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override {
        return same_hemisphere(wo, wi) ? abs_cos_theta(wi) * kInvPi : 0.0f;
    }
    Spectrum eval_pdf_unscaled(const Vec3& wo, const Vec3& wi, float& pdf_out) const override {
        if (!same_hemisphere(wo, wi)) {
            pdf_out = 0.0f;
            return Spectrum(0.0f);
        }
        pdf_out = abs_cos_theta(wi) * kInvPi;
        return m_f;
    }
    bool sample_unscaled(const Vec3& wo, const Vec2& u, float, BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        Vec3 wi = warp::square_to_cosine_hemisphere(u);
        if (wo.z < 0.0f) wi.z = -wi.z;
        const float p = abs_cos_theta(wi) * kInvPi;
        if (p <= 0.0f) return false;
        out.f = m_f;
        out.wi = wi;
        out.pdf = p;
        out.flags = kBsdfReflection | kBsdfDiffuse;
        out.eta = 1.0f;
        return true;
    }

private:
    Spectrum m_f;  // reflectance / pi, the same in every direction
};

}  // namespace glint
