#pragma once
// Energy-conserving modified Phong (Lafortune & Willems 1994): a Lambertian term plus a
// lobe around the mirror direction,
//   f = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha),   alpha = angle(wi, mirror(wo)).
// The lobe's albedo never exceeds ks, so kd + ks <= 1 conserves energy; both terms are
// symmetric in wo and wi, so the BSDF is reciprocal. Two-sided like LambertianBsdf.
#include <glint/material/bsdf.h>
#include <glint/math/warp.h>

namespace glint {

class PhongBsdf final : public Bsdf {
public:
    PhongBsdf(const Spectrum& diffuse, const Spectrum& specular, float exponent)
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
        const float cos_alpha = std::max(0.0f, glm::dot(wi, mirror(wo)));
        const float lobe = (m_exponent + 2.0f) * kInv2Pi * std::pow(cos_alpha, m_exponent);
        return m_diffuse * kInvPi + m_specular * lobe;
    }

    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (!same_hemisphere(wo, wi)) return 0.0f;
        const float cos_alpha = std::max(0.0f, glm::dot(wi, mirror(wo)));
        const float lobe_pdf = (m_exponent + 1.0f) * kInv2Pi * std::pow(cos_alpha, m_exponent);
        return m_specular_probability * lobe_pdf +
               (1.0f - m_specular_probability) * abs_cos_theta(wi) * kInvPi;
    }

    bool sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                         BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        Vec3 wi;
        if (u_lobe < m_specular_probability) {
            // cos(alpha) distributed as (n + 1) cos^n around the mirror direction.
            const float cos_alpha = std::pow(u.x, 1.0f / (m_exponent + 1.0f));
            const float sin_alpha = safe_sqrt(1.0f - cos_alpha * cos_alpha);
            const float phi = 2.0f * kPi * u.y;
            wi = Frame::from_normal(mirror(wo))
                     .to_world(
                         Vec3(sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha));
            if (!same_hemisphere(wo, wi)) return false;  // the lobe dipped below the surface
        } else {
            wi = warp::square_to_cosine_hemisphere(u);
            if (wo.z < 0.0f) wi.z = -wi.z;
        }
        const float p = pdf_unscaled(wo, wi);
        if (p <= 0.0f) return false;
        const uint32_t lobe = u_lobe < m_specular_probability ? kBsdfGlossy : kBsdfDiffuse;
        out = BsdfSample{eval_unscaled(wo, wi), wi, p, kBsdfReflection | lobe, 1.0f};
        return true;
    }

private:
    static Vec3 mirror(const Vec3& w) { return Vec3(-w.x, -w.y, w.z); }

    Spectrum m_diffuse;
    Spectrum m_specular;
    float m_exponent;
    float m_specular_probability;
};

}  // namespace glint
