#pragma once
// The principled BSDF: one surface model with a few artist-facing parameters, after Burley
// 2012/2015 ("Physically-Based Shading at Disney", "Extending the Disney BRDF to a BSDF with
// Integrated Subsurface Scattering"), the glTF 2.0 metallic-roughness BRDF (Appendix B) and
// OpenPBR's layering. Written as layers, each of which takes what it reflects away from
// what lies under it, so that no combination of parameters creates energy:
//
//   f = c f_coat + T_c(o) T_c(i) [ m f_metal + (1 - m) t f_glass + (1 - m) (1 - t) f_opaque ]
//   f_opaque = s f_sheen + T_s(o) T_s(i) [ f_spec + base/pi (1 - E(o)) (1 - E(i)) / (1 - E_avg) ]
//
//   f_coat   GGX reflection, dielectric Fresnel of index 1.5, its own roughness; c = clearcoat.
//            T_c(w) = 1 - c E_coat(w), E_coat its directional albedo (CoatAlbedoTable).
//   f_metal  GGX reflection with Schlick's Fresnel, F0 = base colour; m = metallic.
//   f_glass  rough glass (RoughDielectricBsdf) of index `ior`, its refraction tinted by the
//            base colour; t = transmission.
//   f_sheen  Burley's sheen, sheen colour (1 - cos theta_d)^5 (theta_d between wi and the
//            half vector); s = sheen. T_s(w) = 1 - s colour E_sheen(w), E_sheen its albedo.
//   f_spec   GGX reflection with the dielectric Fresnel of `specular_eta` (from `specular` or
//            `ior`, principled.cpp), E(w) its directional albedo and E_avg its cosine-weighted
//            average (CoatAlbedoTable).
//   diffuse  Lambertian, weighted by the light the specular layer lets through on the way in
//            and out; the 1 / (1 - E_avg) makes a white base reflect exactly what the layer
//            passes: E(o) + (1 - E(o)) = 1 (Kelemen and Szirmay-Kalos 2001's coupling).
//
// Energy: a layer of albedo a(w) over a BSDF of albedo A <= 1 reflects
// a(o) + (1 - a(o)) integral (1 - a(i)) f cos <= a(o) + (1 - a(o)) A <= 1, so the whole is
// <= 1 for every parameter set. A white opaque dielectric without sheen or coat reflects
// exactly 1 (to the albedo table's accuracy, 1e-3), and so does a white metal at roughness 0;
// single-scattering GGX loses energy at high roughness (no multiple-scattering
// compensation), and the coat and sheen layers lose the light that the physical layers
// would bounce back down into the base (docs/materials.md gives the figures).
//
// Reciprocity: every reflection term is symmetric in wo and wi; refraction obeys generalised
// reciprocity (that of RoughDielectricBsdf times factors symmetric in wo and wi).
//
// Every lobe is glossy or diffuse, never a delta: roughness is clamped to alpha >=
// kMinAlpha, so that all lobes combine in one mixture pdf. Sampling picks a lobe by an
// estimate of its albedo at wo (weights w_k) and samples it: pdf = sum_k w_k pdf_k / sum_k w_k,
// for coat and specular (GGX visible normals), glass (its own sampling) and the cosine lobe
// (diffuse and sheen). Two-sided like PlasticBsdf: from below, the reflection layers mirror
// both directions; the glass sees the inverse index, as RoughDielectricBsdf does.
#include <glint/material/bsdf.h>
#include <glint/material/coat_albedo.h>
#include <glint/material/fresnel.h>
#include <glint/material/microfacet.h>
#include <glint/material/rough_dielectric.h>

namespace glint {

/// The Burley sheen's directional albedo E_sheen(cos theta) for a white sheen of weight 1,
/// tabulated once (by quadrature) and read by linear interpolation.
float sheen_albedo(float cos_theta);

/// The values of the principled model at one point (textures already evaluated).
struct PrincipledParams {
    Spectrum base_color{0.8f};        ///< in [0, 1]
    float metallic = 0.0f;            ///< in [0, 1]
    float alpha = 0.25f;              ///< GGX alpha of the base (metal, specular, glass)
    float ior = 1.5f;                 ///< the glass's index inside / outside, > 1
    float transmission = 0.0f;        ///< in [0, 1], fraction of the dielectric base that is glass
    float clearcoat = 0.0f;           ///< in [0, 1]
    float clearcoat_alpha = 0.0009f;  ///< GGX alpha of the coat
    float sheen = 0.0f;               ///< in [0, 1]
    float sheen_tint = 0.5f;          ///< in [0, 1]: 0 white sheen, 1 the base colour's hue
};

class PrincipledBsdf final : public Bsdf {
public:
    /// Below this GGX alpha the lobes are not made sharper: they stay glossy (see above).
    static constexpr float kMinAlpha = 1e-3f;

    /// `specular_albedo`: the specular layer's table, for its index (>= 1) and covering
    /// params.alpha; `coat_albedo`: the clear coat's, index 1.5, covering clearcoat_alpha.
    /// Both must outlive the BSDF (the material owns them).
    PrincipledBsdf(const PrincipledParams& params, const CoatAlbedoTable& specular_albedo,
                   const CoatAlbedoTable& coat_albedo);

    /// The sampling strategies, in the order the lobe weights list them.
    enum Strategy { kCoat, kSpecular, kGlass, kCosine, kStrategies };
    /// The weight with which sample() picks each strategy at wo (for tests).
    void strategy_weights(const Vec3& wo, float weights[kStrategies]) const;

protected:
    Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const override;
    float pdf_unscaled(const Vec3& wo, const Vec3& wi) const override;
    bool sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                         BsdfSample& out) const override;

private:
    static uint32_t flags_for(const PrincipledParams& p);

    // The reflection of GGX `distribution` at the mirrored pair (o, i), without Fresnel:
    // D(wm) G2 / (4 cos_o cos_i), and its sampling density.
    static float ggx_reflection(const GgxDistribution& distribution, const Vec3& o, const Vec3& i);
    static float ggx_reflection_pdf(const GgxDistribution& distribution, const Vec3& o,
                                    const Vec3& i);

    float coat_transmittance(const Vec3& w) const;      // T_c
    Spectrum sheen_transmittance(const Vec3& w) const;  // T_s
    float specular_albedo(const Vec3& w) const;         // E

    PrincipledParams m_p;
    GgxDistribution m_base;
    GgxDistribution m_coat;
    RoughDielectricBsdf m_glass;
    const CoatAlbedoTable* m_specular_albedo;  // owned by the material
    const CoatAlbedoTable* m_coat_albedo;      // owned by the material
    float m_specular_eta;
    float m_diffuse_scale;  // 1 / (pi (1 - E_avg))
    Spectrum m_sheen_color;
};

}  // namespace glint
