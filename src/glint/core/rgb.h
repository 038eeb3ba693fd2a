#pragma once
// A colour as three numbers in linear Rec.709/sRGB primaries: what scenes state (material
// parameters, constant colours, light colours), what textures hold, and what the film and
// the display store. Light carried along a path is a `Spectrum` (spectrum.h), which is made
// from an Rgb by `uplift` and turned back into one by `to_rgb` at the film.
#include <algorithm>
#include <cmath>

namespace glint {

struct Rgb {
    float r = 0.0f, g = 0.0f, b = 0.0f;

    constexpr Rgb() = default;
    constexpr explicit Rgb(float v) : r(v), g(v), b(v) {}
    constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}

    // Writable only on a named Rgb: a write into a temporary (say to_rgb(s)[c] = v) would be
    // lost, so it does not compile.
    float operator[](int i) const& { return i == 0 ? r : (i == 1 ? g : b); }
    float& operator[](int i) & { return i == 0 ? r : (i == 1 ? g : b); }

    Rgb& operator+=(const Rgb& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    Rgb& operator*=(const Rgb& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    Rgb& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    Rgb& operator/=(float s) { return *this *= 1.0f / s; }

    bool is_black() const { return r == 0.0f && g == 0.0f && b == 0.0f; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
    float max_value() const { return std::max(r, std::max(g, b)); }
    float min_value() const { return std::min(r, std::min(g, b)); }
    float average() const { return (r + g + b) / 3.0f; }
    // Rec.709 luminance (Y of CIE XYZ for linear sRGB primaries): the one place its weights
    // are written.
    float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
    Rgb clamped(float lo, float hi) const {
        return {std::clamp(r, lo, hi), std::clamp(g, lo, hi), std::clamp(b, lo, hi)};
    }
};

inline Rgb operator+(Rgb a, const Rgb& b) {
    return a += b;
}
inline Rgb operator-(const Rgb& a, const Rgb& b) {
    return {a.r - b.r, a.g - b.g, a.b - b.b};
}
inline Rgb operator*(Rgb a, const Rgb& b) {
    return a *= b;
}
inline Rgb operator*(Rgb a, float s) {
    return a *= s;
}
inline Rgb operator*(float s, Rgb a) {
    return a *= s;
}
inline Rgb operator/(Rgb a, float s) {
    return a /= s;
}
inline bool operator==(const Rgb& a, const Rgb& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
}

}  // namespace glint
