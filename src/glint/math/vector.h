#pragma once
// Vector types used across glint: thin aliases over glm so that geometry code reads
// like the papers it implements.
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glint {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Vec2i = glm::ivec2;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;

inline constexpr float kPi = 3.14159265358979323846f;
// The largest float below 1: where a sample in [0, 1) must stay below 1 after rounding.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kInv2Pi = 0.5f / kPi;
inline constexpr float kInv4Pi = 0.25f / kPi;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline float max_component(const Vec3& v) {
    return std::max(v.x, std::max(v.y, v.z));
}
inline float min_component(const Vec3& v) {
    return std::min(v.x, std::min(v.y, v.z));
}
inline float length_squared(const Vec3& v) {
    return glm::dot(v, v);
}
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline float safe_sqrt(float x) {
    return std::sqrt(std::max(0.0f, x));
}
inline float sqr(float x) {
    return x * x;
}

// Flip `v` into the hemisphere of `reference`.
inline Vec3 face_forward(const Vec3& v, const Vec3& reference) {
    return glm::dot(v, reference) < 0.0f ? -v : v;
}

}  // namespace glint
