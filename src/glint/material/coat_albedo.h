#pragma once
// Directional albedo of a dielectric coat's reflection: the fraction E(cos theta, alpha) of
// the light arriving from a direction at cos theta that a GGX-rough dielectric interface of
// relative index eta reflects (single scattering, Fresnel at each facet),
//   E(wo) = integral of F(wo.wm) D(wm) G2(wo, wi) / (4 cos_o cos_i) cos_i dwi,
// and its cosine-weighted hemispherical average E_avg = 2 integral of E(mu) mu dmu. For a
// smooth coat (alpha = 0) E is the Fresnel reflectance. PlasticBsdf weights its diffuse
// base by the light the coat does not reflect, 1 - E, on the way in and out, which keeps it
// energy-conserving at any roughness (see plastic.h).
//
// E has no closed form: it is tabulated on construction, by a fixed midpoint rule over the
// visible-normal sampling of the coat (a deterministic quadrature), on a grid in
// sqrt(cos theta) (E changes fastest near grazing) and in roughness = sqrt(alpha), and read
// back by bilinear interpolation. Accuracy is about 1e-3 (tests/material/test_microfacet.cpp
// compares it with Monte Carlo).
#include <vector>

namespace glint {

class CoatAlbedoTable {
public:
    // A table for alpha in [alpha_min, alpha_max]; one column when they are equal (a constant
    // roughness), 17 otherwise (a textured one). eta >= 1.
    CoatAlbedoTable(float eta, float alpha_min, float alpha_max);

    float eta() const { return m_eta; }
    // E(cos theta, alpha) for cos theta in [0, 1]; alpha is clamped to the table's range.
    float albedo(float cos_theta, float alpha) const;
    // The cosine-weighted average of E over the hemisphere, at this alpha.
    float average_albedo(float alpha) const;

private:
    struct Position {
        int index;
        float fraction;
    };
    Position alpha_position(float alpha) const;
    float alpha_of_column(int column) const;
    float albedo_in_column(int column, float cos_theta) const;

    float m_eta;
    float m_roughness_min, m_roughness_max;
    int m_columns;
    std::vector<float> m_albedo;   // m_columns rows of kCosineNodes, per alpha column
    std::vector<float> m_average;  // per alpha column
};

}  // namespace glint
