#include <glint/math/spherical_triangle.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

using DVec3 = glm::dvec3;

// The unit normal of the great circle through unit vectors p and q; zero when they coincide.
DVec3 great_circle_normal(const DVec3& p, const DVec3& q) {
    const DVec3 n = glm::cross(p, q);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : DVec3(0.0);
}

// The angle between two great-circle normals, as the interior angle of the triangle at the
// vertex they share (one of them points the other way round the triangle).
double interior_angle(const DVec3& n_in, const DVec3& n_out) {
    return std::acos(std::clamp(-glm::dot(n_in, n_out), -1.0, 1.0));
}

// The part of unit vector `v` orthogonal to unit vector `axis`, normalised.
DVec3 orthonormal_part(const DVec3& v, const DVec3& axis) {
    const DVec3 o = v - glm::dot(v, axis) * axis;
    const double len = glm::length(o);
    return len > 0.0 ? o / len : DVec3(0.0);
}

}  // namespace

SphericalTriangle::SphericalTriangle(const Vec3& ref, const Vec3& a, const Vec3& b, const Vec3& c) {
    const DVec3 o(ref);
    m_a = glm::normalize(DVec3(a) - o);
    m_b = glm::normalize(DVec3(b) - o);
    m_c = glm::normalize(DVec3(c) - o);
    const DVec3 n_ab = great_circle_normal(m_a, m_b);
    const DVec3 n_bc = great_circle_normal(m_b, m_c);
    const DVec3 n_ca = great_circle_normal(m_c, m_a);
    if (n_ab == DVec3(0.0) || n_bc == DVec3(0.0) || n_ca == DVec3(0.0)) return;
    m_alpha = interior_angle(n_ca, n_ab);
    const double beta = interior_angle(n_ab, n_bc);
    const double gamma = interior_angle(n_bc, n_ca);
    // Girard's theorem: the area of a spherical triangle is its angle excess.
    m_solid_angle = std::max(0.0, m_alpha + beta + gamma - M_PI);
    m_cos_c = glm::dot(m_a, m_b);
}

// Arvo's construction: u.x chooses the sub-triangle (a, b, c') holding that fraction of the
// area, which fixes c' on the arc from a to c; u.y then chooses a point on the arc from b to
// c' so that the density is uniform (the arc's cosine is linear in u.y).
Vec3 SphericalTriangle::sample(const Vec2& u) const {
    const double area = u.x * m_solid_angle;
    const double s = std::sin(area - m_alpha), t = std::cos(area - m_alpha);
    const double sin_alpha = std::sin(m_alpha), cos_alpha = std::cos(m_alpha);
    const double uu = t - cos_alpha;
    const double vv = s + sin_alpha * m_cos_c;
    const double denominator = (vv * s + uu * t) * sin_alpha;
    const double q = denominator != 0.0
                         ? std::clamp(((vv * t - uu * s) * cos_alpha - vv) / denominator, -1.0, 1.0)
                         : 1.0;
    const DVec3 c_prime =
        q * m_a + std::sqrt(std::max(0.0, 1.0 - q * q)) * orthonormal_part(m_c, m_a);
    const double z = 1.0 - u.y * (1.0 - glm::dot(c_prime, m_b));
    const DVec3 w =
        z * m_b + std::sqrt(std::max(0.0, 1.0 - z * z)) * orthonormal_part(c_prime, m_b);
    return Vec3(glm::normalize(w));
}

}  // namespace glint
