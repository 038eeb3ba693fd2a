#pragma once
// The quantity a path carries: radiance, importance, throughput, a BSDF value. Opaque outside
// the colour module (rgb.h and this file): callers use its arithmetic and the methods below,
// never its channels, so that a spectral mode can change what it holds (three RGB values
// today, values at sampled wavelengths later) without touching its callers. Colours stated
// by a scene or read from a texture are `Rgb` and become a Spectrum through `uplift`; the
// film turns a Spectrum back into an Rgb through `to_rgb`.
#include <glint/core/rgb.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace glint {

// What an Rgb stands for when it becomes a Spectrum. In RGB mode all three are the identity;
// a spectral mode needs to know which it is (a smooth spectrum bounded by 1 for a
// reflectance, one shaped like the illuminant for an emitter, an unbounded one otherwise).
enum class RgbRole {
    reflectance,  ///< in [0, 1]: albedos, tints, the reflectance at normal incidence
    illuminant,   ///< what a light or an emitting surface radiates
    unbounded,    ///< any other non-negative quantity: indices of refraction, absorption
};

class Spectrum {
public:
    // How many floats `stored()` gives and `from_stored()` takes (caches on disk).
    static constexpr int kStoredValues = 3;

    constexpr Spectrum() = default;
    constexpr explicit Spectrum(float v) : m_r(v), m_g(v), m_b(v) {}

    Spectrum& operator+=(const Spectrum& o) {
        m_r += o.m_r;
        m_g += o.m_g;
        m_b += o.m_b;
        return *this;
    }
    Spectrum& operator*=(const Spectrum& o) {
        m_r *= o.m_r;
        m_g *= o.m_g;
        m_b *= o.m_b;
        return *this;
    }
    Spectrum& operator*=(float s) {
        m_r *= s;
        m_g *= s;
        m_b *= s;
        return *this;
    }
    Spectrum& operator/=(float s) { return *this *= 1.0f / s; }

    friend Spectrum operator-(const Spectrum& a, const Spectrum& b) {
        return {a.m_r - b.m_r, a.m_g - b.m_g, a.m_b - b.m_b};
    }
    // Per value; 0 where the divisor is 0 (a ratio of throughputs with a black channel).
    friend Spectrum operator/(const Spectrum& a, const Spectrum& b) {
        return {b.m_r != 0 ? a.m_r / b.m_r : 0.0f, b.m_g != 0 ? a.m_g / b.m_g : 0.0f,
                b.m_b != 0 ? a.m_b / b.m_b : 0.0f};
    }
    friend bool operator==(const Spectrum& a, const Spectrum& b) {
        return a.m_r == b.m_r && a.m_g == b.m_g && a.m_b == b.m_b;
    }
    friend Spectrum min(const Spectrum& a, const Spectrum& b) {
        return {std::min(a.m_r, b.m_r), std::min(a.m_g, b.m_g), std::min(a.m_b, b.m_b)};
    }
    friend Spectrum max(const Spectrum& a, const Spectrum& b) {
        return {std::max(a.m_r, b.m_r), std::max(a.m_g, b.m_g), std::max(a.m_b, b.m_b)};
    }
    friend Spectrum exp(const Spectrum& s) {
        return {std::exp(s.m_r), std::exp(s.m_g), std::exp(s.m_b)};
    }
    // `f` applied to each value: for quantities defined per wavelength by a scalar formula,
    // like the Fresnel reflectance of a metal from its complex index.
    template <typename F>
    Spectrum map(F f) const {
        return {f(m_r), f(m_g), f(m_b)};
    }
    template <typename F>
    friend Spectrum map(const Spectrum& a, const Spectrum& b, F f) {
        return {f(a.m_r, b.m_r), f(a.m_g, b.m_g), f(a.m_b, b.m_b)};
    }

    bool is_black() const { return m_r == 0.0f && m_g == 0.0f && m_b == 0.0f; }
    bool is_finite() const {
        return std::isfinite(m_r) && std::isfinite(m_g) && std::isfinite(m_b);
    }
    bool is_non_negative() const { return min_value() >= 0.0f; }
    float max_value() const { return std::max(m_r, std::max(m_g, m_b)); }
    float min_value() const { return std::min(m_r, std::min(m_g, m_b)); }
    float average() const { return (m_r + m_g + m_b) / 3.0f; }
    /// How many values a Spectrum carries (channels in RGB mode): what hero-channel sampling
    /// (delta tracking in chromatic media) chooses among.
    static constexpr int kValues = 3;
    /// Value `i` in [0, kValues): the coefficient hero-channel sampling uses.
    float value(int i) const { return i == 0 ? m_r : (i == 1 ? m_g : m_b); }
    float luminance() const { return Rgb(m_r, m_g, m_b).luminance(); }
    Spectrum clamped(float lo, float hi) const {
        return {std::clamp(m_r, lo, hi), std::clamp(m_g, lo, hi), std::clamp(m_b, lo, hi)};
    }

    std::array<float, kStoredValues> stored() const { return {m_r, m_g, m_b}; }
    static Spectrum from_stored(const std::array<float, kStoredValues>& v) {
        return {v[0], v[1], v[2]};
    }

    friend Spectrum uplift(const Rgb& rgb, RgbRole role);
    friend Rgb to_rgb(const Spectrum& s);

private:
    constexpr Spectrum(float r, float g, float b) : m_r(r), m_g(g), m_b(b) {}

    float m_r = 0.0f, m_g = 0.0f, m_b = 0.0f;
};

// An Rgb as the Spectrum it stands for (the identity in RGB mode).
inline Spectrum uplift(const Rgb& rgb, RgbRole /*role*/) {
    return {rgb.r, rgb.g, rgb.b};
}
// The colour the film records for a Spectrum (the identity in RGB mode).
inline Rgb to_rgb(const Spectrum& s) {
    return {s.m_r, s.m_g, s.m_b};
}

inline Spectrum operator+(Spectrum a, const Spectrum& b) {
    return a += b;
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

}  // namespace glint
