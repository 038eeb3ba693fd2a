#include <glint/math/direction_cone.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

constexpr float kPiF = 3.14159265358979f;

float safe_acos(float c) {
    return std::acos(std::clamp(c, -1.0f, 1.0f));
}

// Rotates v by `angle` about the unit axis `k` (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& k, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0f - c));
}

}  // namespace

DirectionCone DirectionCone::merged(const DirectionCone& a, const DirectionCone& b) {
    if (a.empty) return b;
    if (b.empty) return a;
    const float theta_a = safe_acos(a.cos_theta), theta_b = safe_acos(b.cos_theta);
    const float theta_d = safe_acos(glm::dot(a.axis, b.axis));
    if (std::min(theta_d + theta_b, kPiF) <= theta_a) return a;
    if (std::min(theta_d + theta_a, kPiF) <= theta_b) return b;
    // The cone whose edges touch both cones' far edges, its axis turned from a's towards b's.
    const float theta_o = 0.5f * (theta_a + theta_d + theta_b);
    if (theta_o >= kPiF) return whole_sphere();
    const Vec3 k = glm::cross(a.axis, b.axis);
    const float k_len = glm::length(k);
    if (!(k_len > 1e-7f)) return whole_sphere();  // opposite axes
    const Vec3 axis = glm::normalize(rotate(a.axis, k / k_len, theta_o - theta_a));
    return {axis, std::cos(theta_o), false};
}

}  // namespace glint
