#pragma once
// Energy-conserving, reciprocal Blinn-Phong: a Lambertian term plus a lobe of cos^n of the
// half-vector angle, normalised as Ashikhmin & Shirley (2000, "An Anisotropic Phong BRDF
// Model", eq. 4, isotropic and without their Fresnel factor):
//   f = kd / pi + ks (n + 1) / (8 pi) cos^n(theta_h) / ((wo.wh) max(cos wo, cos wi)),
//   wh = normalize(wo + wi).
// The half vector is sampled with density p_h = (n + 1) / (2 pi) cos^n(theta_h), which gives
// wi the density p(wi) = p_h / (4 wo.wh); the lobe is exactly ks p(wi) / max(cos wo, cos wi),
// so its albedo, the integral of lobe * cos wi, is at most ks times the integral of p(wi), at
// most ks. Everything is symmetric in wo and wi (wo.wh = wi.wh), hence reciprocal; kd + ks <= 1
// conserves energy. Two-sided like LambertianBsdf.
#include <glint/material/bsdf.h>
#include <glint/material/fresnel.h>
#include <glint/material/microfacet.h>
#include <glint/math/warp.h>

namespace glint {

class BlinnPhongBsdf final : public Bsdf {
public:
    BlinnPhongBsdf(const Spectrum& diffuse, const Spectrum& specular, float exponent)
        : Bsdf(kBsdfReflection | (specular.is_black() ? 0u : kBsdfGlossy) |
               (diffuse.is_black() ? 0u : kBsdfDiffuse)),
          m_diffuse(diffuse),
          m_specular(specular),
          m_exponent(exponent) {
        const float d = m_diffuse.average(), s = m_specular.average();
        m_specular_probability = d + s > 0.0f ? s / (d + s) : 0.0f;
    }

protected:
    Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (!same_hemisphere(wo, wi)) return Spectrum(0.0f);
        const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
        const float lobe = lobe_pdf(o, i) / std::max(o.z, i.z);
        return m_diffuse * kInvPi + m_specular * lobe;
    }

    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (!same_hemisphere(wo, wi)) return 0.0f;
        const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
        return m_specular_probability * lobe_pdf(o, i) +
               (1.0f - m_specular_probability) * i.z * kInvPi;
    }

    bool sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                         BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        const bool specular = u_lobe < m_specular_probability;
        Vec3 wi;
        if (specular) {
            const float cos_h = std::pow(u.x, 1.0f / (m_exponent + 1.0f));
            const float sin_h = safe_sqrt(1.0f - cos_h * cos_h);
            const float phi = 2.0f * kPi * u.y;
            const Vec3 wh(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
            const Vec3 o = mirror_to_upper(wo);
            // A half vector facing away from wo mirrors it below the surface.
            if (glm::dot(o, wh) <= 0.0f) return false;
            wi = reflect(o, wh);
            if (wi.z <= 0.0f) return false;
        } else {
            wi = warp::square_to_cosine_hemisphere(u);
        }
        if (wo.z < 0.0f) wi.z = -wi.z;
        const float p = pdf_unscaled(wo, wi);
        if (!(p > 0.0f)) return false;
        const uint32_t lobe = specular ? kBsdfGlossy : kBsdfDiffuse;
        out = BsdfSample{eval_unscaled(wo, wi), wi, p, kBsdfReflection | lobe, 1.0f};
        return true;
    }

private:
    // p(wi) of the lobe for o, i in the upper hemisphere.
    float lobe_pdf(const Vec3& o, const Vec3& i) const {
        const Vec3 wh = glm::normalize(o + i);
        const float half_vector_pdf = (m_exponent + 1.0f) * kInv2Pi * std::pow(wh.z, m_exponent);
        return half_vector_pdf / (4.0f * glm::dot(o, wh));
    }

    Spectrum m_diffuse;
    Spectrum m_specular;
    float m_exponent;
    float m_specular_probability;
};

}  // namespace glint
