#include <glint/core/error.h>
#include <glint/math/motion_transform.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint {

TransformParts decompose(const Transform& xf) {
    const Mat4& m = xf.matrix();
    const Vec3 a0(m[0]), a1(m[1]), a2(m[2]);
    // A = Q U by Gram-Schmidt on A's columns: Q orthonormal, U upper triangular.
    const float r00 = glm::length(a0);
    const Vec3 q0 = a0 / r00;
    const float r01 = glm::dot(q0, a1);
    const Vec3 u1 = a1 - r01 * q0;
    const float r11 = glm::length(u1);
    const Vec3 q1 = u1 / r11;
    const float r02 = glm::dot(q0, a2), r12 = glm::dot(q1, a2);
    const Vec3 u2 = a2 - r02 * q0 - r12 * q1;
    float r22 = glm::length(u2);
    Vec3 q2 = u2 / r22;
    // A mirror: Q would be a reflection, which no quaternion describes; S takes the sign.
    if (glm::dot(glm::cross(q0, q1), q2) < 0.0f) {
        q2 = -q2;
        r22 = -r22;
    }
    TransformParts parts;
    parts.translation = Vec3(m[3]);
    parts.rotation = glm::normalize(glm::quat_cast(Mat3(q0, q1, q2)));
    parts.scale = Vec3(r00, r11, r22);
    parts.shear = Vec3(r01, r02, r12);
    return parts;
}

Transform compose(const TransformParts& parts) {
    Mat3 s(1.0f);  // column-major: s[column][row]
    s[0][0] = parts.scale.x;
    s[1][1] = parts.scale.y;
    s[2][2] = parts.scale.z;
    s[1][0] = parts.shear.x;
    s[2][0] = parts.shear.y;
    s[2][1] = parts.shear.z;
    Mat4 m(glm::mat3_cast(parts.rotation) * s);
    m[3] = Vec4(parts.translation, 1.0f);
    return Transform(m);
}

namespace {

// Spherical linear interpolation of unit quaternions that are at most 180 degrees apart
// (the constructor makes them so); nearly equal ones are blended linearly, where slerp's
// division by sin(theta) would lose its precision.
glm::quat slerp(const glm::quat& a, const glm::quat& b, float t) {
    const float cos_theta = std::clamp(glm::dot(a, b), -1.0f, 1.0f);
    if (cos_theta > 0.9995f) return glm::normalize(a * (1.0f - t) + b * t);
    const float theta = std::acos(cos_theta);
    const float sin_theta = std::sin(theta);
    return glm::normalize(a * (std::sin((1.0f - t) * theta) / sin_theta) +
                          b * (std::sin(t * theta) / sin_theta));
}

}  // namespace

MotionTransform::MotionTransform(std::vector<Transform> keys) : m_keys(std::move(keys)) {
    if (m_keys.empty()) m_keys.emplace_back();
    m_parts.clear();
    for (const Transform& key : m_keys) {
        m_parts.push_back(decompose(key));
        // q and -q are the same rotation; the one nearer the previous key turns the short way.
        if (m_parts.size() > 1 &&
            glm::dot(m_parts[m_parts.size() - 2].rotation, m_parts.back().rotation) < 0.0f)
            m_parts.back().rotation = -m_parts.back().rotation;
    }
}

Transform MotionTransform::at(float time) const {
    if (!is_moving()) return m_keys.front();
    const float segments = static_cast<float>(m_keys.size() - 1);
    const float x = std::clamp(time, 0.0f, 1.0f) * segments;
    const size_t i = std::min(static_cast<size_t>(x), m_keys.size() - 2);
    const float t = x - static_cast<float>(i);
    if (t == 0.0f) return m_keys[i];
    if (t == 1.0f) return m_keys[i + 1];
    const TransformParts& a = m_parts[i];
    const TransformParts& b = m_parts[i + 1];
    TransformParts p;
    p.translation = glm::mix(a.translation, b.translation, t);
    p.rotation = slerp(a.rotation, b.rotation, t);
    p.scale = glm::mix(a.scale, b.scale, t);
    p.shear = glm::mix(a.shear, b.shear, t);
    return compose(p);
}

Bounds3 MotionTransform::bounds_of_keys(const Bounds3& local) const {
    Bounds3 result;
    for (const Transform& key : m_keys) result.expand(local.transformed(key));
    return result;
}

MotionTransform MotionTransform::operator*(const MotionTransform& rhs) const {
    if (!is_moving() && !rhs.is_moving())
        return MotionTransform(m_keys.front() * rhs.m_keys.front());
    if (is_moving() && rhs.is_moving() && key_count() != rhs.key_count()) {
        throw Error(
            "a moving group placed in a moving group must have as many motion keys as "
            "it (" +
            std::to_string(rhs.key_count()) + " against " + std::to_string(key_count()) + ")");
    }
    const size_t n = std::max(key_count(), rhs.key_count());
    std::vector<Transform> keys;
    for (size_t i = 0; i < n; ++i)
        keys.push_back(m_keys[is_moving() ? i : 0] * rhs.m_keys[rhs.is_moving() ? i : 0]);
    return MotionTransform(std::move(keys));
}

}  // namespace glint
