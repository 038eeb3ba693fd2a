#pragma once
// The GGX (Trowbridge-Reitz) microfacet distribution, for the rough conductor, rough
// dielectric and plastic BSDFs. All directions are in the local shading frame (z = the
// macro-surface normal) and microfacet normals `wm` lie in the upper hemisphere.
//
//   D(wm)        density of microfacet normals per unit solid angle, normalised so that
//                the projected facet area is the macro area: integral of D(wm) cos(wm) = 1.
//   lambda(w)    Smith's auxiliary function; G1(w) = 1 / (1 + lambda(w)) is the fraction
//                of the facets facing w that w sees unmasked.
//   g2(wo, wi)   height-correlated masking-shadowing, 1 / (1 + lambda(wo) + lambda(wi))
//                (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 99).
//   sample_visible_normal(w, u) draws wm from the distribution of normals visible from w,
//                D_w(wm) = G1(w) max(0, w.wm) D(wm) / cos(w)   (Heitz 2018).
//
// Anisotropic: alpha_x is the roughness along the tangent (x), alpha_y along the bitangent.
#include <glint/math/frame.h>
#include <glint/math/vector.h>

namespace glint {

// The user's `roughness` in [0, 1] to GGX alpha: alpha = roughness^2 (Burley 2012,
// "Physically-Based Shading at Disney"), which spreads perceived roughness evenly over
// [0, 1]. roughness 0 is a perfectly smooth surface, 1 a very rough one (alpha = 1).
inline float roughness_to_alpha(float roughness) {
    return roughness * roughness;
}

// Mirrors w into the upper hemisphere. The reflection BSDFs built on microfacets are
// two-sided (like LambertianBsdf); the dielectric mirrors both directions to treat light
// arriving from inside as light arriving from outside of a medium with the inverse index.
inline Vec3 mirror_to_upper(const Vec3& w) {
    return Vec3(w.x, w.y, std::abs(w.z));
}

class GgxDistribution {
public:
    // Below this alpha the surface is treated as smooth (a delta lobe): D's peak,
    // 1 / (pi alpha^2), would otherwise exceed what float arithmetic resolves well.
    static constexpr float kSmoothAlpha = 1e-4f;

    explicit GgxDistribution(float alpha) : GgxDistribution(alpha, alpha) {}
    GgxDistribution(float alpha_x, float alpha_y) : m_alpha_x(alpha_x), m_alpha_y(alpha_y) {}

    // An anisotropic pair from one alpha and `anisotropy` in [-1, 1] (Burley 2012): positive
    // values stretch the highlight along the tangent, negative ones along the bitangent.
    static GgxDistribution anisotropic(float alpha, float anisotropy) {
        const float aspect = std::sqrt(1.0f - 0.9f * std::abs(anisotropy));
        const float along = alpha / aspect, across = alpha * aspect;
        return anisotropy >= 0.0f ? GgxDistribution(along, across) : GgxDistribution(across, along);
    }

    bool effectively_smooth() const { return std::max(m_alpha_x, m_alpha_y) < kSmoothAlpha; }
    float alpha_x() const { return m_alpha_x; }
    float alpha_y() const { return m_alpha_y; }

    // 1 / (pi ax ay cos^4 (1 + tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2), written with
    // the stretched normal (x / ax, y / ay, z) so that it needs no trigonometry.
    float d(const Vec3& wm) const {
        if (wm.z <= 0.0f) return 0.0f;
        const float x = wm.x / m_alpha_x, y = wm.y / m_alpha_y;
        const float s = x * x + y * y + wm.z * wm.z;
        return 1.0f / (kPi * m_alpha_x * m_alpha_y * s * s);
    }

    // (sqrt(1 + alpha^2 tan^2) - 1) / 2, with alpha the roughness in w's azimuth, in a form
    // that keeps its precision for small tan.
    float lambda(const Vec3& w) const {
        const float alpha2_sin2 = sqr(m_alpha_x * w.x) + sqr(m_alpha_y * w.y);
        if (alpha2_sin2 == 0.0f) return 0.0f;
        const float cos2 = w.z * w.z;
        if (cos2 == 0.0f) return kInfinity;  // grazing: every facet is masked
        const float alpha2_tan2 = alpha2_sin2 / cos2;
        return 0.5f * alpha2_tan2 / (1.0f + std::sqrt(1.0f + alpha2_tan2));
    }

    float g1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
    float g2(const Vec3& wo, const Vec3& wi) const {
        return 1.0f / (1.0f + lambda(wo) + lambda(wi));
    }

    // Density of sample_visible_normal(w, .) at wm, per unit solid angle of wm; w.z > 0.
    float visible_normal_pdf(const Vec3& w, const Vec3& wm) const {
        if (w.z <= 0.0f) return 0.0f;
        return g1(w) * std::max(0.0f, glm::dot(w, wm)) * d(wm) / w.z;
    }

    // Heitz 2018, "Sampling the GGX Distribution of Visible Normals": stretch the view
    // direction so that the microsurface becomes a hemisphere of unit radius (alpha = 1),
    // where the visible normals are those of a hemisphere seen from w_h, sample the
    // projected area that hemisphere shows to w_h, and stretch the normal back. w.z > 0.
    Vec3 sample_visible_normal(const Vec3& w, const Vec2& u) const {
        const Vec3 wh = glm::normalize(Vec3(m_alpha_x * w.x, m_alpha_y * w.y, w.z));
        // A basis around w_h, t1 horizontal (any horizontal axis when w_h is the pole).
        const float horizontal2 = wh.x * wh.x + wh.y * wh.y;
        const Vec3 t1 = horizontal2 > 0.0f ? Vec3(-wh.y, wh.x, 0.0f) / std::sqrt(horizontal2)
                                           : Vec3(1.0f, 0.0f, 0.0f);
        const Vec3 t2 = glm::cross(wh, t1);
        // The hemisphere projects onto the disk perpendicular to w_h as a half disk plus half
        // an ellipse whose minor radius is wh.z: a uniform point on the disk, with its t2
        // coordinate squeezed into that region, is uniform in projected area.
        const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
        const float p1 = r * std::cos(phi);
        const float squeeze = 0.5f * (1.0f + wh.z);
        const float p2 = (1.0f - squeeze) * safe_sqrt(1.0f - p1 * p1) + squeeze * r * std::sin(phi);
        // Lift the point onto the hemisphere, then undo the stretch (normals transform with
        // the inverse transpose, which for this diagonal stretch is a scale by alpha).
        const float p3 = safe_sqrt(1.0f - p1 * p1 - p2 * p2);
        const Vec3 nh = p1 * t1 + p2 * t2 + p3 * wh;
        return glm::normalize(Vec3(m_alpha_x * nh.x, m_alpha_y * nh.y, std::max(0.0f, nh.z)));
    }

private:
    float m_alpha_x;
    float m_alpha_y;
};

}  // namespace glint
