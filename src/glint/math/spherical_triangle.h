#pragma once
// Uniform sampling of the solid angle a triangle subtends (Arvo 1995, "Stratified sampling of
// spherical triangles"): every direction towards the triangle is equally likely, so the
// density seen from the receiving point is 1 / solid angle, with none of area sampling's
// dist^2 / cos blow-up near the light.
#include <glint/math/vector.h>

namespace glint {

/// The spherical triangle that world triangle (a, b, c) projects to around `ref`. Computed
/// in double: the angles come from differences of nearly equal values for small or grazing
/// triangles, and float loses them first there.
class SphericalTriangle {
public:
    SphericalTriangle(const Vec3& ref, const Vec3& a, const Vec3& b, const Vec3& c);

    /// Solid angle in steradians (0 for a degenerate projection).
    double solid_angle() const { return m_solid_angle; }
    /// A unit direction from `ref`, uniform over the spherical triangle for uniform `u`.
    Vec3 sample(const Vec2& u) const;

private:
    glm::dvec3 m_a, m_b, m_c;  // unit directions from ref to the vertices
    double m_alpha = 0.0;      // the spherical triangle's interior angle at a
    double m_cos_c = 1.0;      // cosine of the arc from a to b
    double m_solid_angle = 0.0;
};

}  // namespace glint
