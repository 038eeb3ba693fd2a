#pragma once
// Small helpers shared by the test files.
#include <glint/core/error.h>
#include <glint/math/vector.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>

namespace glint::test {

// True in the sanitizer tree (GLINT_SANITIZE). CI runs that tree's tests without the `slow`
// label (suites named *Slow); a parametrized test whose heaviest cases are statistical
// convergence checks skips just those cases there. They take half a minute or more each
// under the sanitizers, run in the normal tree, and share their code with the cases that stay.
#ifdef GLINT_SANITIZER_BUILD
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

// The message of the glint::Error that `f` throws, or "" when it throws none.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// Whether `part` occurs in `text` (messages are checked by their key phrases).
inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A unit direction at polar angle `degrees` from +z (or -z when `inside`), azimuth `phi`.
inline Vec3 direction(float degrees, float phi = 0.7f, bool inside = false) {
    const float theta = glm::radians(degrees);
    const Vec3 w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    return inside ? Vec3(w.x, w.y, -w.z) : w;
}

// A folder of its own for a test, removed when it goes out of scope (also on failure).
class TempDir {
public:
    explicit TempDir(const std::string& prefix = "glint-test") {
        m_path = std::filesystem::temp_directory_path() /
                 (prefix + "-" + std::to_string(std::random_device()()));
        std::filesystem::create_directories(m_path);
    }
    ~TempDir() { std::filesystem::remove_all(m_path); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return (m_path / name).string(); }

private:
    std::filesystem::path m_path;
};

}  // namespace glint::test
