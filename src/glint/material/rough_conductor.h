#pragma once
// A rough metal: GGX microfacet reflection with the Fresnel reflectance of a conductor
// (Cook & Torrance 1982; Walter et al. 2007),
//   f(wo, wi) = F(wo.wm) D(wm) G2(wo, wi) / (4 cos(wo) cos(wi)),   wm = normalize(wo + wi),
// sampled through the visible normals, so pdf(wo, wi) = D_wo(wm) / (4 wo.wm). Reciprocal
// (wo.wm = wi.wm, G2 symmetric) and two-sided. With alpha below GgxDistribution::kSmoothAlpha
// it is a perfect mirror with the same Fresnel reflectance (a delta lobe).
//
// Only single scattering is modelled: light that would bounce between facets is lost, so a
// rough conductor with F = 1 reflects less than 1 (tests/material/test_microfacet.cpp prints
// how much less, docs/materials.md lists the figures).
#include <glint/material/bsdf.h>
#include <glint/material/fresnel.h>
#include <glint/material/microfacet.h>

namespace glint {

// A conductor's Fresnel reflectance times a tint, or the tint alone for a perfect reflector
// (F = 1 at every angle: for white-furnace tests and for artists who want no Fresnel colour).
struct ConductorFresnel {
    Spectrum eta{1.0f};
    Spectrum k{0.0f};
    Spectrum tint{1.0f};
    bool perfect = false;

    static ConductorFresnel perfect_reflector(const Spectrum& tint = Spectrum(1.0f)) {
        return {Spectrum(1.0f), Spectrum(0.0f), tint, true};
    }
    Spectrum eval(float cos_theta_i) const {
        return perfect ? tint : tint * fresnel_conductor(cos_theta_i, eta, k);
    }
};

class RoughConductorBsdf final : public Bsdf {
public:
    RoughConductorBsdf(const GgxDistribution& distribution, const ConductorFresnel& fresnel)
        : Bsdf(kBsdfReflection | (distribution.effectively_smooth() ? kBsdfDelta : kBsdfGlossy)),
          m_distribution(distribution),
          m_fresnel(fresnel) {}

protected:
    Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (m_distribution.effectively_smooth() || !same_hemisphere(wo, wi)) return Spectrum(0.0f);
        const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
        const Vec3 wm = glm::normalize(o + i);
        const float g2 = m_distribution.g2(o, i);
        return m_fresnel.eval(glm::dot(o, wm)) * (m_distribution.d(wm) * g2 / (4.0f * o.z * i.z));
    }

    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (m_distribution.effectively_smooth() || !same_hemisphere(wo, wi)) return 0.0f;
        const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
        const Vec3 wm = glm::normalize(o + i);
        // d(wi) / d(wm) = 4 wo.wm for reflection about wm.
        return m_distribution.visible_normal_pdf(o, wm) / (4.0f * glm::dot(o, wm));
    }

    bool sample_unscaled(const Vec3& wo, const Vec2& u, float, BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        if (m_distribution.effectively_smooth()) {
            out = mirror(wo);
            return true;
        }
        const Vec3 o = mirror_to_upper(wo);
        const Vec3 wm = m_distribution.sample_visible_normal(o, u);
        Vec3 wi = reflect(o, wm);
        if (wi.z <= 0.0f) return false;  // reflected into the surface: masked
        if (wo.z < 0.0f) wi.z = -wi.z;
        const float p = pdf_unscaled(wo, wi);
        if (!(p > 0.0f)) return false;
        out = BsdfSample{eval_unscaled(wo, wi), wi, p, kBsdfReflection | kBsdfGlossy, 1.0f};
        return true;
    }

    DeltaLobes delta_lobes_unscaled(const Vec3& wo) const override {
        DeltaLobes lobes;
        if (wo.z != 0.0f && m_distribution.effectively_smooth()) lobes.add(mirror(wo));
        return lobes;
    }

private:
    // The delta lobe of the effectively smooth case: a mirror with the Fresnel reflectance.
    BsdfSample mirror(const Vec3& wo) const {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        const Spectrum f = m_fresnel.eval(abs_cos_theta(wo)) / abs_cos_theta(wi);
        return BsdfSample{f, wi, 1.0f, kBsdfReflection | kBsdfDelta, 1.0f};
    }

    GgxDistribution m_distribution;
    ConductorFresnel m_fresnel;
};

}  // namespace glint
