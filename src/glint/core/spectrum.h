#pragma once
// Radiometric quantity per colour channel (linear Rec.709 RGB today). A type of its own
// so that a spectral mode can replace it without touching every BSDF.
#include <algorithm>
#include <cmath>

namespace glint {

struct Spectrum {
    float r = 0.0f, g = 0.0f, b = 0.0f;

    constexpr Spectrum() = default;
    constexpr explicit Spectrum(float v) : r(v), g(v), b(v) {}
    constexpr Spectrum(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}

    float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }

    Spectrum& operator+=(const Spectrum& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    Spectrum& operator*=(const Spectrum& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    Spectrum& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    Spectrum& operator/=(float s) { return *this *= 1.0f / s; }

    bool is_black() const { return r == 0.0f && g == 0.0f && b == 0.0f; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
    float max_value() const { return std::max(r, std::max(g, b)); }
    float average() const { return (r + g + b) / 3.0f; }
    // Rec.709 luminance.
    float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
};

inline Spectrum operator+(Spectrum a, const Spectrum& b) {
    return a += b;
}
inline Spectrum operator-(const Spectrum& a, const Spectrum& b) {
    return {a.r - b.r, a.g - b.g, a.b - b.b};
}
inline Spectrum operator*(Spectrum a, const Spectrum& b) {
    return a *= b;
}
inline Spectrum operator*(Spectrum a, float s) {
    return a *= s;
}
inline Spectrum operator*(float s, Spectrum a) {
    return a *= s;
}
inline Spectrum operator/(Spectrum a, float s) {
    return a /= s;
}
inline Spectrum operator/(const Spectrum& a, const Spectrum& b) {
    return {b.r != 0 ? a.r / b.r : 0.0f, b.g != 0 ? a.g / b.g : 0.0f, b.b != 0 ? a.b / b.b : 0.0f};
}
inline bool operator==(const Spectrum& a, const Spectrum& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
}
inline Spectrum exp(const Spectrum& s) {
    return {std::exp(s.r), std::exp(s.g), std::exp(s.b)};
}

}  // namespace glint
