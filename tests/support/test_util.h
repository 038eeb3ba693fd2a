#pragma once
// Small helpers shared by the test files.
#include <glint/core/error.h>
#include <glint/math/vector.h>

#include <cmath>
#include <functional>
#include <string>

namespace glint::test {

// The message of the glint::Error that `f` throws, or "" when it throws none.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// A unit direction at polar angle `degrees` from +z (or -z when `inside`), azimuth `phi`.
inline Vec3 direction(float degrees, float phi = 0.7f, bool inside = false) {
    const float theta = glm::radians(degrees);
    const Vec3 w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    return inside ? Vec3(w.x, w.y, -w.z) : w;
}

}  // namespace glint::test
