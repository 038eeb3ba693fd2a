#pragma once
// Rough glass: reflection and refraction by GGX microfacets (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces"), the rough counterpart of
// SmoothDielectricBsdf with the same conventions: `eta` is the index inside over the index
// outside, radiance is scaled by 1/eta^2 on refraction (by the Bsdf wrappers, bsdf.h: the
// formulas below are without it), and BsdfSample::eta is the index on wi's side over the
// index on wo's side.
//
// Light arriving from inside (wo.z < 0) is handled by mirroring both directions into the
// upper hemisphere and inverting eta: the interface seen from inside is an interface seen
// from outside onto a medium of index 1/eta. In that frame, with eta_r = n(wi side) / n(wo side)
// for refraction:
//   reflection   wm = normalize(wo + wi)
//                f = F(wo.wm) D(wm) G2 / (4 cos_o cos_i)
//                pdf = F D_wo(wm) / (4 wo.wm)
//   refraction   wm = normalize(wo + eta_r wi), the generalised half vector, turned up
//                f = (1 - F) D(wm) G2 |wi.wm| |wo.wm| / (cos_o |cos_i| (wi.wm + wo.wm/eta_r)^2)
//                pdf = (1 - F) D_wo(wm) |wi.wm| / (wi.wm + wo.wm/eta_r)^2
// where the last factor of each pdf is the Jacobian d(wm)/d(wi) (Walter et al., eqs. 14, 17)
// and F is the dielectric Fresnel reflectance at the facet, which also chooses between the
// lobes when sampling. Only facets that face wo and, for refraction, face away from wi
// contribute (a facet cannot refract light through its back).
#include <glint/material/bsdf.h>
#include <glint/material/fresnel.h>
#include <glint/material/microfacet.h>

namespace glint {

class RoughDielectricBsdf final : public Bsdf {
public:
    // `eta` = index inside / index outside. The distribution must not be effectively smooth
    // (use SmoothDielectricBsdf then: the material chooses).
    // `hero_only`: the index is that of the hero wavelength of a dispersive glass, so f is
    // carried by the hero alone (Spectrum::hero_only).
    RoughDielectricBsdf(float eta, const GgxDistribution& distribution, bool hero_only = false)
        : Bsdf(kBsdfReflection | kBsdfTransmission | kBsdfGlossy, eta),
          m_eta(eta),
          m_distribution(distribution),
          m_hero_only(hero_only) {}

protected:
    Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const override {
        const Config c = configure(wo, wi);
        if (!c.valid) return Spectrum(0.0f);
        const float g2 = m_distribution.g2(c.o, c.i);
        const float d = m_distribution.d(c.wm);
        const float fresnel = facet_fresnel(c);
        if (c.reflection) return carried(fresnel * d * g2 / (4.0f * c.o.z * c.i.z));
        const float cos_om = glm::dot(c.o, c.wm), cos_im = glm::dot(c.i, c.wm);
        const float denominator = sqr(cos_im + cos_om / c.eta) * c.o.z * std::abs(c.i.z);
        const float f = (1.0f - fresnel) * d * g2 * std::abs(cos_im * cos_om) / denominator;
        return carried(f);  // the wrappers add 1/eta^2 for radiance (bsdf.h)
    }

    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override {
        const Config c = configure(wo, wi);
        if (!c.valid) return 0.0f;
        const float cos_om = glm::dot(c.o, c.wm);
        const float visible = m_distribution.visible_normal_pdf(c.o, c.wm);
        const float fresnel = facet_fresnel(c);
        if (c.reflection) return fresnel * visible / (4.0f * cos_om);
        const float cos_im = glm::dot(c.i, c.wm);
        return (1.0f - fresnel) * visible * std::abs(cos_im) / sqr(cos_im + cos_om / c.eta);
    }

    bool sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                         BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        const bool inside = wo.z < 0.0f;
        const float eta = inside ? 1.0f / m_eta : m_eta;
        const Vec3 o = mirror_to_upper(wo);
        const Vec3 wm = m_distribution.sample_visible_normal(o, u);
        const float fresnel = fresnel_dielectric(glm::dot(o, wm), eta);
        const bool reflection = u_lobe < fresnel;
        Vec3 wi;
        if (reflection) {
            wi = reflect(o, wm);
            if (wi.z <= 0.0f) return false;  // reflected into the surface
        } else {
            if (!refract(o, wm, eta, wi) || wi.z >= 0.0f) return false;
        }
        if (inside) wi.z = -wi.z;
        const float p = pdf_unscaled(wo, wi);
        if (!(p > 0.0f)) return false;
        const uint32_t lobe = reflection ? kBsdfReflection : kBsdfTransmission;
        out = BsdfSample{eval_unscaled(wo, wi), wi, p, lobe | kBsdfGlossy, reflection ? 1.0f : eta};
        return true;
    }

private:
    // The value at the hero alone (the others 0): the film reads a path that went
    // through here at its hero (core/secondary_wavelengths.h).
    Spectrum carried(float f) const {
        return m_hero_only ? Spectrum(f).hero_only() / static_cast<float>(Spectrum::kValues)
                           : Spectrum(f);
    }

    // The pair (wo, wi) mirrored so that wo is in the upper hemisphere, with the relative
    // index of the lower side and the microfacet normal that connects them.
    struct Config {
        Vec3 o, i, wm;
        float eta = 1.0f;
        bool reflection = false;
        bool valid = false;
    };

    Config configure(const Vec3& wo, const Vec3& wi) const {
        Config c;
        if (wo.z == 0.0f || wi.z == 0.0f) return c;
        const bool inside = wo.z < 0.0f;
        c.eta = inside ? 1.0f / m_eta : m_eta;
        c.o = inside ? Vec3(wo.x, wo.y, -wo.z) : wo;
        c.i = inside ? Vec3(wi.x, wi.y, -wi.z) : wi;
        c.reflection = c.i.z > 0.0f;
        Vec3 wm = c.reflection ? c.o + c.i : c.o + c.eta * c.i;
        const float length2 = length_squared(wm);
        if (!(length2 > 0.0f)) return c;  // index matched and wi = -wo: no facet
        wm /= std::sqrt(length2);
        if (wm.z < 0.0f) wm = -wm;
        if (wm.z == 0.0f) return c;
        c.wm = wm;
        // wo must see the facet's front; a refracted wi leaves through its back.
        const float cos_om = glm::dot(c.o, wm), cos_im = glm::dot(c.i, wm);
        c.valid = cos_om > 0.0f && (c.reflection ? cos_im > 0.0f : cos_im < 0.0f);
        return c;
    }

    // The Fresnel reflectance of the facet. For refraction it is taken on the side of the
    // lower index, where it is well conditioned (from the denser side, 1 - F loses its
    // precision near the critical angle), so that f(wo, wi) and f(wi, wo) agree to rounding.
    static float facet_fresnel(const Config& c) {
        const Vec3& from = c.reflection || c.eta >= 1.0f ? c.o : c.i;
        return fresnel_dielectric(glm::dot(from, c.wm), c.eta);  // negative cos: from below
    }

    float m_eta;
    GgxDistribution m_distribution;
    bool m_hero_only;
};

}  // namespace glint
