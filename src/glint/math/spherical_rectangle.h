#pragma once
// Uniform sampling of the solid angle a rectangle subtends (Urena, Fajardo and King 2013,
// "An area-preserving parametrization for spherical rectangles"): the density seen from
// the receiving point is 1 / solid angle, and the map from the unit square is continuous,
// so stratified and Sobol points keep their stratification on the light.
#include <glint/math/vector.h>

namespace glint {

/// The rectangle with corner `corner` and orthogonal edges `edge_x`, `edge_y`, seen from
/// `ref`. In double, as SphericalTriangle, for small and grazing rectangles.
class SphericalRectangle {
public:
    SphericalRectangle(const Vec3& ref, const Vec3& corner, const Vec3& edge_x, const Vec3& edge_y);

    /// Solid angle in steradians (0 when `ref` lies in the rectangle's plane).
    double solid_angle() const { return m_solid_angle; }
    /// A point on the rectangle, uniform in solid angle from `ref` for uniform `u`.
    Vec3 sample(const Vec2& u) const;

private:
    glm::dvec3 m_ref;
    glm::dvec3 m_x, m_y, m_z;  // the rectangle's frame; z points from the plane towards ref
    double m_x0 = 0.0, m_x1 = 0.0, m_y0 = 0.0, m_y1 = 0.0, m_z0 = 0.0;  // in that frame
    double m_b0 = 0.0, m_b1 = 0.0, m_k = 0.0;
    double m_solid_angle = 0.0;
};

}  // namespace glint
