#include <glint/math/transform.h>

#include <glm/gtc/matrix_transform.hpp>

namespace glint {

Transform::Transform(const Mat4& m) : m_matrix(m), m_inverse(glm::inverse(m)) {}

Transform Transform::translate(const Vec3& offset) {
    return Transform(glm::translate(Mat4(1.0f), offset), glm::translate(Mat4(1.0f), -offset));
}

Transform Transform::scale(const Vec3& factors) {
    return Transform(glm::scale(Mat4(1.0f), factors), glm::scale(Mat4(1.0f), 1.0f / factors));
}

Transform Transform::rotate(float degrees, const Vec3& axis) {
    const Mat4 r = glm::rotate(Mat4(1.0f), glm::radians(degrees), glm::normalize(axis));
    return Transform(r, glm::transpose(r));
}

Transform Transform::operator*(const Transform& rhs) const {
    return Transform(m_matrix * rhs.m_matrix, rhs.m_inverse * m_inverse);
}

}  // namespace glint
