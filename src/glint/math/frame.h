#pragma once
// Orthonormal basis around a normal; BSDFs work in this local frame where z is the normal.
#include <glint/math/vector.h>

namespace glint {

class Frame {
public:
    Frame() = default;
    Frame(const Vec3& s, const Vec3& t, const Vec3& n) : m_s(s), m_t(t), m_n(n) {}

    // Builds a frame from a unit normal (Duff et al. 2017, branchless and continuous).
    static Frame from_normal(const Vec3& n) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        Vec3 s(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        Vec3 t(b, sign + n.y * n.y * a, -n.y);
        return Frame(s, t, n);
    }

    // Builds a frame whose s axis follows `tangent` as closely as possible.
    static Frame from_normal_tangent(const Vec3& n, const Vec3& tangent) {
        Vec3 s = tangent - n * glm::dot(n, tangent);
        const float len2 = glm::dot(s, s);
        if (!(len2 > 1e-12f)) return from_normal(n);
        s *= 1.0f / std::sqrt(len2);  // one division instead of three
        return Frame(s, glm::cross(n, s), n);
    }

    Vec3 to_local(const Vec3& v) const {
        return Vec3(glm::dot(v, m_s), glm::dot(v, m_t), glm::dot(v, m_n));
    }
    Vec3 to_world(const Vec3& v) const { return m_s * v.x + m_t * v.y + m_n * v.z; }

    const Vec3& s() const { return m_s; }
    const Vec3& t() const { return m_t; }
    const Vec3& n() const { return m_n; }

private:
    Vec3 m_s{1, 0, 0}, m_t{0, 1, 0}, m_n{0, 0, 1};
};

// Trigonometry of a direction expressed in a local frame (z = normal).
inline float cos_theta(const Vec3& w) {
    return w.z;
}
inline float abs_cos_theta(const Vec3& w) {
    return std::abs(w.z);
}
inline bool same_hemisphere(const Vec3& a, const Vec3& b) {
    return a.z * b.z > 0.0f;
}

}  // namespace glint
