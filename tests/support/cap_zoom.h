#pragma once
// A magnified view of a cap of directions, for chi-square tests of small lights.
#include <glint/math/frame.h>
#include <glint/math/vector.h>

#include <cmath>
#include <optional>

namespace glint::test {

// Zooms the cap of directions within `cos_min` of `axis` onto the whole sphere, so that a
// small light still spreads over many chi-square bins. The map keeps phi and stretches
// 1 - cos(theta) linearly, which scales solid angle by the constant 2 / (1 - cos_min);
// densities scale by the inverse. Samples outside the cap are counted in `outside`.
class CapZoom {
    using DVec3 = glm::dvec3;

public:
    CapZoom(const Vec3& axis, double cos_min)
        : m_frame(Frame::from_normal(axis)), m_width(1.0 - cos_min) {}

    std::optional<Vec3> to_sphere(const Vec3& w) {
        const DVec3 l = local(DVec3(w));
        const double one_minus_z =
            (l.x * l.x + l.y * l.y) / (1.0 + l.z);  // 1 - cos, no cancellation
        if (l.z <= 0.0 || one_minus_z > m_width) {
            ++outside;
            return std::nullopt;
        }
        const double z = 1.0 - 2.0 * one_minus_z / m_width;
        const double phi = std::atan2(l.y, l.x);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return Vec3(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                    static_cast<float>(z));
    }
    // The world direction that `to_sphere` maps to `v`, and the density factor.
    Vec3 from_sphere(const Vec3& v) const {
        const double one_minus_z = 0.5 * (1.0 - v.z) * m_width;
        const double r = std::sqrt(std::max(0.0, one_minus_z * (2.0 - one_minus_z)));
        const double phi = std::atan2(v.y, v.x);
        const DVec3 l(r * std::cos(phi), r * std::sin(phi), 1.0 - one_minus_z);
        return Vec3(DVec3(m_frame.s()) * l.x + DVec3(m_frame.t()) * l.y + DVec3(m_frame.n()) * l.z);
    }
    double density_scale() const { return 0.5 * m_width; }

    int outside = 0;

private:
    DVec3 local(const DVec3& w) const {
        return DVec3(glm::dot(w, DVec3(m_frame.s())), glm::dot(w, DVec3(m_frame.t())),
                     glm::dot(w, DVec3(m_frame.n())));
    }
    Frame m_frame;
    double m_width;
};

}  // namespace glint::test
