#pragma once
// Plastic: a diffuse base under a clear dielectric coat (smooth or GGX-rough), after
// Mitsuba's `plastic` and `roughplastic` (Jakob, Mitsuba 0.6 documentation):
//   f = f_coat + diffuse (1 - E(wo)) (1 - E(wi)) / (pi eta^2 (1 - diffuse F_int))
// f_coat is the coat's microfacet reflection with dielectric Fresnel (as in
// RoughDielectricBsdf), a delta lobe when the coat is smooth. E(w) is the coat's directional
// albedo (CoatAlbedoTable; for a smooth coat the Fresnel reflectance F(w)), so 1 - E is the
// light that crosses the coat. The 1 / eta^2 and the series 1 / (1 - diffuse F_int) account
// for light going in and out of the coat and bouncing between coat and base, with
// F_int = 1 - (1 - E_avg) / eta^2 the coat's average reflectance seen from inside (the
// outside average transmittance 1 - E_avg over eta^2, by reciprocity).
//
// Why it never creates energy: the diffuse term's albedo is
//   (1 - E(wo)) diffuse (1 - E_avg) / (eta^2 (1 - diffuse F_int))
//     = (1 - E(wo)) diffuse (1 - F_int) / (1 - diffuse F_int)  <=  1 - E(wo)
// for diffuse <= 1, and the coat reflects E(wo), so the total is at most 1 at every angle
// and roughness (up to the table's accuracy, about 1e-3). Using Fresnel weights 1 - F for a
// rough coat, as Mitsuba's smooth plastic does, would not be safe: a rough coat can reflect
// more than F(wo) near normal incidence, where its tilted facets see larger Fresnel values.
// Both terms are symmetric in wo and wi, so the BSDF is reciprocal; it is two-sided.
#include <glint/material/bsdf.h>
#include <glint/material/coat_albedo.h>
#include <glint/material/fresnel.h>
#include <glint/material/microfacet.h>
#include <glint/math/warp.h>

namespace glint {

class PlasticBsdf final : public Bsdf {
public:
    // `diffuse` in [0, 1]; `coat` isotropic; `coat_albedo` made for the coat's index (>= 1)
    // and covering its alpha; it must outlive the BSDF.
    PlasticBsdf(const Spectrum& diffuse, const GgxDistribution& coat,
                const CoatAlbedoTable& coat_albedo)
        : Bsdf(kBsdfReflection | kBsdfDiffuse |
               (coat.effectively_smooth() ? kBsdfDelta : kBsdfGlossy)),
          m_coat(coat),
          m_coat_albedo(&coat_albedo),
          m_eta(coat_albedo.eta()) {
        const float internal_reflectance =
            1.0f - (1.0f - coat_albedo.average_albedo(coat.alpha_x())) / (m_eta * m_eta);
        // 1 / (1 - rho r_i): the geometric series of bounces between the base and the coat.
        const Spectrum bounces =
            diffuse.map([&](float rho) { return 1.0f / (1.0f - rho * internal_reflectance); });
        const float eta2 = m_eta * m_eta;
        m_diffuse_scale =
            map(diffuse, bounces, [&](float rho, float b) { return rho * b * kInvPi / eta2; });
        m_base_albedo = map(diffuse, bounces, [&](float rho, float b) {
                            return rho * (1.0f - internal_reflectance) * b;
                        }).average();
    }

protected:
    Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (!same_hemisphere(wo, wi)) return Spectrum(0.0f);
        const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
        const Spectrum base = m_diffuse_scale * ((1.0f - coat_albedo(o)) * (1.0f - coat_albedo(i)));
        if (m_coat.effectively_smooth()) return base;
        const Vec3 wm = glm::normalize(o + i);
        const float coat = fresnel_dielectric(glm::dot(o, wm), m_eta) * m_coat.d(wm) *
                           m_coat.g2(o, i) / (4.0f * o.z * i.z);
        return base + Spectrum(coat);
    }

    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override {
        if (!same_hemisphere(wo, wi)) return 0.0f;
        const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
        const float p_coat = coat_probability(o);
        const float base = (1.0f - p_coat) * i.z * kInvPi;
        if (m_coat.effectively_smooth()) return base;
        const Vec3 wm = glm::normalize(o + i);
        return base + p_coat * m_coat.visible_normal_pdf(o, wm) / (4.0f * glm::dot(o, wm));
    }

    bool sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                         BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        const Vec3 o = mirror_to_upper(wo);
        const float p_coat = coat_probability(o);
        const bool coat = u_lobe < p_coat;
        if (coat && m_coat.effectively_smooth()) {
            out = smooth_coat(wo, p_coat);
            return true;
        }
        Vec3 wi;
        if (coat) {
            wi = reflect(o, m_coat.sample_visible_normal(o, u));
            if (wi.z <= 0.0f) return false;  // reflected into the surface
        } else {
            wi = warp::square_to_cosine_hemisphere(u);
        }
        if (wo.z < 0.0f) wi.z = -wi.z;
        const float p = pdf_unscaled(wo, wi);
        if (!(p > 0.0f)) return false;
        const uint32_t lobe = coat ? kBsdfGlossy : kBsdfDiffuse;
        out = BsdfSample{eval_unscaled(wo, wi), wi, p, kBsdfReflection | lobe, 1.0f};
        return true;
    }

    // Only the smooth coat is a delta lobe; the diffuse base is not listed.
    DeltaLobes delta_lobes_unscaled(const Vec3& wo) const override {
        DeltaLobes lobes;
        if (wo.z != 0.0f && m_coat.effectively_smooth()) {
            const BsdfSample coat = smooth_coat(wo, 1.0f);
            if (!coat.f.is_black()) lobes.add(coat);
        }
        return lobes;
    }

private:
    // The smooth coat's mirror lobe, of weight F(wo), chosen with probability `pdf`.
    BsdfSample smooth_coat(const Vec3& wo, float pdf) const {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        const float cos_o = std::abs(wo.z);
        const float fresnel = fresnel_dielectric(cos_o, m_eta);
        return BsdfSample{Spectrum(fresnel / cos_o), wi, pdf, kBsdfReflection | kBsdfDelta, 1.0f};
    }

    float coat_albedo(const Vec3& w) const { return m_coat_albedo->albedo(w.z, m_coat.alpha_x()); }

    // The coat is sampled in proportion to its share of the reflected energy: E(wo) against
    // the base's (1 - E(wo)) times its average albedo.
    float coat_probability(const Vec3& o) const {
        const float coat = coat_albedo(o);
        const float total = coat + (1.0f - coat) * m_base_albedo;
        return total > 0.0f ? coat / total : 0.0f;
    }

    GgxDistribution m_coat;
    const CoatAlbedoTable* m_coat_albedo;  // owned by the material
    float m_eta;
    Spectrum m_diffuse_scale;
    float m_base_albedo;
};

}  // namespace glint
