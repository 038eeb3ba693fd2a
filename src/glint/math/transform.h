#pragma once
// Affine transform with its inverse kept alongside, so normals and inverse queries are cheap.
#include <glint/math/vector.h>

namespace glint {

class Transform {
public:
    Transform() = default;
    explicit Transform(const Mat4& m);
    Transform(const Mat4& m, const Mat4& inverse) : m_matrix(m), m_inverse(inverse) {}

    static Transform translate(const Vec3& offset);
    static Transform scale(const Vec3& factors);
    // Rotation by `degrees` about `axis` (right-handed).
    static Transform rotate(float degrees, const Vec3& axis);

    Transform operator*(const Transform& rhs) const;
    Transform inverse() const { return Transform(m_inverse, m_matrix); }

    Vec3 point(const Vec3& p) const { return Vec3(m_matrix * Vec4(p, 1.0f)); }
    Vec3 vector(const Vec3& v) const { return Mat3(m_matrix) * v; }
    // Normals transform by the inverse transpose; the result is not normalised.
    Vec3 normal(const Vec3& n) const { return glm::transpose(Mat3(m_inverse)) * n; }

    const Mat4& matrix() const { return m_matrix; }
    const Mat4& inverse_matrix() const { return m_inverse; }
    bool is_identity() const { return m_matrix == Mat4(1.0f); }
    // True when the transform flips orientation (negative determinant).
    bool swaps_handedness() const { return glm::determinant(Mat3(m_matrix)) < 0.0f; }

private:
    Mat4 m_matrix{1.0f};
    Mat4 m_inverse{1.0f};
};

}  // namespace glint
