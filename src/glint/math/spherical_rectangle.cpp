#include <glint/math/spherical_rectangle.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

using DVec3 = glm::dvec3;

DVec3 unit_cross(const DVec3& p, const DVec3& q) {
    const DVec3 n = glm::cross(p, q);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : DVec3(0.0);
}

double angle_between_normals(const DVec3& n, const DVec3& m) {
    return std::acos(std::clamp(-glm::dot(n, m), -1.0, 1.0));
}

}  // namespace

SphericalRectangle::SphericalRectangle(const Vec3& ref, const Vec3& corner, const Vec3& edge_x,
                                       const Vec3& edge_y)
    : m_ref(ref) {
    const DVec3 ex(edge_x), ey(edge_y);
    const double width = glm::length(ex), height = glm::length(ey);
    m_x = ex / width;
    m_y = ey / height;
    m_z = glm::cross(m_x, m_y);
    const DVec3 d = DVec3(corner) - m_ref;
    m_z0 = glm::dot(d, m_z);
    // Work in the frame where the rectangle lies at negative z, below the reference point.
    if (m_z0 > 0.0) {
        m_z = -m_z;
        m_z0 = -m_z0;
    }
    m_x0 = glm::dot(d, m_x);
    m_y0 = glm::dot(d, m_y);
    m_x1 = m_x0 + width;
    m_y1 = m_y0 + height;
    if (!(m_z0 < 0.0)) return;  // in the plane: no solid angle
    const DVec3 v00(m_x0, m_y0, m_z0), v01(m_x0, m_y1, m_z0);
    const DVec3 v10(m_x1, m_y0, m_z0), v11(m_x1, m_y1, m_z0);
    // Normals of the planes through ref and each edge, pointing into the pyramid.
    const DVec3 n0 = unit_cross(v00, v10), n1 = unit_cross(v10, v11);
    const DVec3 n2 = unit_cross(v11, v01), n3 = unit_cross(v01, v00);
    const double g0 = angle_between_normals(n0, n1), g1 = angle_between_normals(n1, n2);
    const double g2 = angle_between_normals(n2, n3), g3 = angle_between_normals(n3, n0);
    m_b0 = n0.z;
    m_b1 = n2.z;
    m_k = 2.0 * M_PI - g2 - g3;
    // The quadrilateral's angle excess is its solid angle.
    m_solid_angle = std::max(0.0, g0 + g1 - m_k);
}

// u.x picks x by the solid angle of the strip [x0, x] (inverting its closed form), u.y picks
// y along that strip by the arc's height, which is linear in solid angle.
Vec3 SphericalRectangle::sample(const Vec2& u) const {
    const double au = u.x * m_solid_angle + m_k;
    const double fu = (std::cos(au) * m_b0 - m_b1) / std::sin(au);
    double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + m_b0 * m_b0);
    cu = std::clamp(cu, -1.0, 1.0);
    const double xu =
        std::clamp(-(cu * m_z0) / std::sqrt(std::max(1e-300, 1.0 - cu * cu)), m_x0, m_x1);
    const double d = std::sqrt(xu * xu + m_z0 * m_z0);
    const double h0 = m_y0 / std::sqrt(d * d + m_y0 * m_y0);
    const double h1 = m_y1 / std::sqrt(d * d + m_y1 * m_y1);
    const double hv = h0 + u.y * (h1 - h0);
    const double hv2 = hv * hv;
    const double yv =
        hv2 < 1.0 - 1e-12 ? std::clamp(hv * d / std::sqrt(1.0 - hv2), m_y0, m_y1) : m_y1;
    return Vec3(m_ref + xu * m_x + yv * m_y + m_z0 * m_z);
}

}  // namespace glint
