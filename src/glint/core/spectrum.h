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
#include <memory>

namespace glint {

// What an Rgb stands for when it becomes a Spectrum. In RGB mode all three are the identity;
// a spectral mode needs to know which it is (a smooth spectrum bounded by 1 for a
// reflectance, one shaped like the illuminant for an emitter, an unbounded one otherwise).
enum class RgbRole {
    reflectance,  ///< in [0, 1]: albedos, tints, the reflectance at normal incidence
    illuminant,   ///< what a light or an emitting surface radiates
    unbounded,    ///< any other non-negative quantity: indices of refraction, absorption
};

// The wavelengths one path carries in spectral mode (hero wavelength sampling, Wilkie et al.
// 2014): the hero λ0 drawn from a density over the visible range, λ1..λ3 the same draw
// rotated by a quarter, a half and three quarters of the unit interval, so each is
// distributed by that density too and together they stratify it.
struct SampledWavelengths {
    static constexpr int kCount = 4;
    std::array<float, kCount> nm{};
    std::array<float, kCount> pdf{};  // per nm, of each wavelength's own draw

    static SampledWavelengths sample_visible(float u);
    float hero() const { return nm[0]; }
};

// How spectral mode turns colours into values at a wavelength and back: the spectral data
// module supplies it (core cannot depend on that module). `uplift` gives the values at the
// wavelengths `nm` of the spectrum an Rgb stands for (all at once: finding a colour's
// spectrum costs more than evaluating it); `observer` is what one unit of radiance at `nm`
// adds to the film's linear Rec.709, per nm (so that ∫ observer(λ) uplift(white,
// illuminant, λ) dλ is white).
struct SpectralModel {
    using Values = std::array<float, SampledWavelengths::kCount>;
    Values (*uplift)(const Rgb& rgb, RgbRole role, const Values& nm) = nullptr;
    Rgb (*observer)(float nm) = nullptr;
};

// The wavelengths of the path a thread is following, with the model that reads colours at
// them. Spectrum values created while one is active (WavelengthScope) are values at its
// wavelengths; with none, in RGB mode, a Spectrum holds RGB. Per thread, because a path is
// followed by one thread from its start to the film, and because it reaches every place
// that makes a Spectrum (textures, materials, lights) without a parameter through each.
struct WavelengthContext {
    SampledWavelengths lambda;
    const SpectralModel* model = nullptr;
};

namespace detail {
inline thread_local const WavelengthContext* t_active_wavelengths = nullptr;
}

// The active wavelengths, or nullptr in RGB mode.
inline const SampledWavelengths* active_wavelengths() {
    const WavelengthContext* c = detail::t_active_wavelengths;
    return c != nullptr ? &c->lambda : nullptr;
}
inline bool spectral_mode_active() {
    return detail::t_active_wavelengths != nullptr;
}

// Makes `context` the active wavelengths of this thread for its lifetime (a path from its
// start until its value reached the film), restoring what was active before (nesting, as
// when a thread runs another task while waiting).
class WavelengthScope {
public:
    explicit WavelengthScope(const WavelengthContext& context)
        : m_previous(detail::t_active_wavelengths) {
        detail::t_active_wavelengths = &context;
    }
    ~WavelengthScope() { detail::t_active_wavelengths = m_previous; }
    WavelengthScope(const WavelengthScope&) = delete;
    WavelengthScope& operator=(const WavelengthScope&) = delete;

private:
    const WavelengthContext* m_previous;
};

class Spectrum;
namespace detail {
// Spectral mode's uplift (spectrum.cpp), out of line: RGB mode's stays a copy.
Spectrum uplift_at_wavelengths(const Rgb& rgb, RgbRole role, const WavelengthContext& c);
}  // namespace detail

class Spectrum {
public:
    // How many floats `stored()` gives and `from_stored()` takes (caches on disk).
    static constexpr int kStoredValues = 3;
    static constexpr int kValues = SampledWavelengths::kCount;

    constexpr Spectrum() = default;
    constexpr explicit Spectrum(float v) : m_v{v, v, v, v} {}

    // In RGB mode the fourth value repeats the first (r): every operation is per value,
    // so it stays a copy, and max/min over four values are those over r, g, b.
    Spectrum& operator+=(const Spectrum& o) {
        for (int i = 0; i < kValues; ++i) m_v[i] += o.m_v[i];
        return *this;
    }
    Spectrum& operator*=(const Spectrum& o) {
        for (int i = 0; i < kValues; ++i) m_v[i] *= o.m_v[i];
        return *this;
    }
    Spectrum& operator*=(float s) {
        for (int i = 0; i < kValues; ++i) m_v[i] *= s;
        return *this;
    }
    Spectrum& operator/=(float s) { return *this *= 1.0f / s; }

    friend Spectrum operator-(const Spectrum& a, const Spectrum& b) {
        return combine(a, b, [](float x, float y) { return x - y; });
    }
    // Per value; 0 where the divisor is 0 (a ratio of throughputs with a black channel).
    friend Spectrum operator/(const Spectrum& a, const Spectrum& b) {
        return combine(a, b, [](float x, float y) { return y != 0 ? x / y : 0.0f; });
    }
    friend bool operator==(const Spectrum& a, const Spectrum& b) {
        return a.m_v[0] == b.m_v[0] && a.m_v[1] == b.m_v[1] && a.m_v[2] == b.m_v[2] &&
               a.m_v[3] == b.m_v[3];
    }
    friend Spectrum min(const Spectrum& a, const Spectrum& b) {
        return combine(a, b, [](float x, float y) { return std::min(x, y); });
    }
    friend Spectrum max(const Spectrum& a, const Spectrum& b) {
        return combine(a, b, [](float x, float y) { return std::max(x, y); });
    }
    friend Spectrum exp(const Spectrum& s) {
        // Grey media and white light have one value: one exp, not four (the same bits).
        if (s.is_constant()) return Spectrum(std::exp(s.m_v[0]));
        return s.map([](float x) { return std::exp(x); });
    }
    /// Whether every value is the same (a grey quantity).
    bool is_constant() const { return m_v[0] == m_v[1] && m_v[0] == m_v[2] && m_v[0] == m_v[3]; }
    // `f` applied to each value: for quantities defined per wavelength by a scalar formula,
    // like the Fresnel reflectance of a metal from its complex index.
    template <typename F>
    Spectrum map(F f) const {
        Spectrum r;
        for (int i = 0; i < kValues; ++i) r.m_v[i] = f(m_v[i]);
        return r;
    }
    template <typename F>
    friend Spectrum map(const Spectrum& a, const Spectrum& b, F f) {
        return combine(a, b, f);
    }
    // A quantity defined per wavelength (a measured index, a tabulated emitter): f(nm) at
    // each active wavelength. Spectral mode only: call it where spectral_mode_active().
    template <typename F>
    static Spectrum at_wavelengths(F f) {
        const WavelengthContext* c = detail::t_active_wavelengths;
        Spectrum r;
        for (int i = 0; i < kValues; ++i) r.m_v[i] = f(c->lambda.nm[i]);
        return r;
    }

    // What a dispersive event leaves: the hero wavelength alone carries the path on, the
    // others are 0. The hero's value is multiplied by their count, so that the film's mean
    // over the wavelengths is the hero's own estimate: a path that went through the event
    // is an estimate at one wavelength, the others' would follow other directions. This
    // keeps termination in the value, not in the path's wavelengths, so light and camera
    // subpaths and stored photons carry it as they carry any throughput. (The same
    // Spectrum in RGB mode, where there is no hero.)
    Spectrum hero_only() const {
        if (!spectral_mode_active()) return *this;
        Spectrum r;
        r.m_v[0] = m_v[0] * static_cast<float>(kValues);
        return r;
    }

    bool is_black() const {
        return m_v[0] == 0.0f && m_v[1] == 0.0f && m_v[2] == 0.0f && m_v[3] == 0.0f;
    }
    bool is_finite() const {
        return std::isfinite(m_v[0]) && std::isfinite(m_v[1]) && std::isfinite(m_v[2]) &&
               std::isfinite(m_v[3]);
    }
    bool is_non_negative() const { return min_value() >= 0.0f; }
    float max_value() const { return std::max(std::max(m_v[0], m_v[1]), std::max(m_v[2], m_v[3])); }
    float min_value() const { return std::min(std::min(m_v[0], m_v[1]), std::min(m_v[2], m_v[3])); }
    float average() const {
        if (spectral_mode_active()) return (m_v[0] + m_v[1] + m_v[2] + m_v[3]) / 4.0f;
        return (m_v[0] + m_v[1] + m_v[2]) / 3.0f;
    }
    float luminance() const {
        if (spectral_mode_active()) return to_rgb(*this).luminance();
        return Rgb(m_v[0], m_v[1], m_v[2]).luminance();
    }
    /// How many values hero-channel sampling (delta tracking in chromatic media) chooses
    /// among: the three channels in RGB mode, the wavelengths in spectral mode.
    static int active_values() { return spectral_mode_active() ? kValues : 3; }
    /// Value `i` in [0, active_values()): the coefficient hero-channel sampling uses.
    float value(int i) const { return m_v[i]; }
    Spectrum clamped(float lo, float hi) const {
        return map([lo, hi](float x) { return std::clamp(x, lo, hi); });
    }

    std::array<float, kStoredValues> stored() const { return {m_v[0], m_v[1], m_v[2]}; }
    static Spectrum from_stored(const std::array<float, kStoredValues>& v) {
        return {v[0], v[1], v[2], v[0]};
    }

    // The film's colour of `s` held as RGB mode holds it: for sums that outlive a path's
    // wavelengths (SPPM adds passes with different wavelengths). Read such a sum back with
    // to_rgb only where no wavelengths are active. The identity in RGB mode.
    friend Spectrum resolved_to_rgb(const Spectrum& s) {
        if (!spectral_mode_active()) return s;
        const Rgb c = to_rgb(s);
        return {c.r, c.g, c.b, c.r};
    }

    friend Spectrum uplift(const Rgb& rgb, RgbRole role);
    friend Rgb to_rgb(const Spectrum& s);
    friend Spectrum detail::uplift_at_wavelengths(const Rgb& rgb, RgbRole role,
                                                  const WavelengthContext& c);

private:
    // The four values as one 16-byte vector of GCC's (and Clang's) vector extension, but with
    // a float's alignment, so that every struct holding a Spectrum keeps its layout. What it
    // changes is the calling convention: a function returning a Spectrum returns it in one
    // SSE register, not in two halves that the caller's vector code then read back as one
    // from the stack (a stalled store forward at every call that is not inlined: a medium's
    // transmittance, a BSDF's value, a light's radiance). The arithmetic stays per value,
    // the same bits.
    typedef float Values __attribute__((vector_size(16), aligned(4)));
    static_assert(kValues == 4, "Spectrum::Values holds four floats");

    std::array<float, kValues> values() const { return {m_v[0], m_v[1], m_v[2], m_v[3]}; }

    template <typename F>
    static Spectrum combine(const Spectrum& a, const Spectrum& b, F f) {
        Spectrum r;
        for (int i = 0; i < kValues; ++i) r.m_v[i] = f(a.m_v[i], b.m_v[i]);
        return r;
    }

    constexpr Spectrum(float a, float b, float c, float d) : m_v{a, b, c, d} {}

    Values m_v{0.0f, 0.0f, 0.0f, 0.0f};
};
static_assert(sizeof(Spectrum) == 16 && alignof(Spectrum) == alignof(float),
              "a Spectrum is four floats, aligned as a float");

namespace detail {
// Spectral mode's film colour (spectrum.cpp), out of line: RGB mode's stays a copy.
Rgb spectral_to_rgb(const std::array<float, Spectrum::kValues>& v, const WavelengthContext& c);
}  // namespace detail

// An Rgb as the Spectrum it stands for: the Rgb itself in RGB mode, its uplifted spectrum's
// values at the path's wavelengths in spectral mode.
inline Spectrum uplift(const Rgb& rgb, RgbRole role) {
    const WavelengthContext* c = detail::t_active_wavelengths;
    if (c != nullptr) return detail::uplift_at_wavelengths(rgb, role, *c);
    return {rgb.r, rgb.g, rgb.b, rgb.r};
}
// The colour the film records for a Spectrum: the identity in RGB mode; in spectral mode
// the Monte Carlo estimate of its colour from the values at the path's wavelengths.
inline Rgb to_rgb(const Spectrum& s) {
    const WavelengthContext* c = detail::t_active_wavelengths;
    if (c != nullptr) return detail::spectral_to_rgb(s.values(), *c);
    return {s.m_v[0], s.m_v[1], s.m_v[2]};
}

// The spectral distribution an emitter states itself (`blackbody = 2700`, a named illuminant,
// a table: spectral/emission_params.h), luminance 1: spectral mode reads it at a path's
// wavelengths, where a plain colour is uplifted to a smooth spectrum (a sodium lamp's line
// or a fluorescent tube's peaks are not smooth).
class EmissionSpectrum {
public:
    virtual ~EmissionSpectrum() = default;
    virtual float eval(float nm) const = 0;
};

// A colour the scene fixed when it was built (a light's radiance, a metal's index, an
// absorption): kept as the Rgb and made a Spectrum where a path reads it, so that spectral
// mode reads it at that path's wavelengths. In RGB mode spectrum() is the Rgb's Spectrum.
class SceneColor {
public:
    SceneColor() = default;
    SceneColor(const Rgb& rgb, RgbRole role) : m_rgb(rgb), m_role(role) {}
    // From a Spectrum made while no wavelengths were active (an RGB one), as code that
    // builds lights from C++ writes them.
    SceneColor(const Spectrum& rgb_spectrum, RgbRole role = RgbRole::illuminant)  // NOLINT
        : m_rgb(to_rgb(rgb_spectrum)), m_role(role) {}
    // An emitter's `factor` (its colour parameter) times a spectral `shape` whose colour is
    // `shape_rgb`: RGB mode renders factor x shape_rgb, spectral mode the factor (uplifted)
    // times the shape at each wavelength.
    SceneColor(const Rgb& factor, std::shared_ptr<const EmissionSpectrum> shape,
               const Rgb& shape_rgb)
        : m_rgb(factor * shape_rgb),
          m_role(RgbRole::illuminant),
          m_factor(factor),
          m_shape(std::move(shape)) {}

    Spectrum spectrum() const {
        if (m_shape && spectral_mode_active()) return shaped_spectrum();
        return uplift(m_rgb, m_role);
    }
    const Rgb& rgb() const { return m_rgb; }
    RgbRole role() const { return m_role; }
    bool is_black() const { return m_rgb.is_black(); }
    SceneColor scaled(float s) const {
        SceneColor c = *this;
        c.m_rgb = m_rgb * s;
        c.m_factor = m_factor * s;
        return c;
    }

private:
    Spectrum shaped_spectrum() const {
        const EmissionSpectrum& shape = *m_shape;
        Spectrum s = uplift(m_factor, RgbRole::unbounded);
        s *= Spectrum::at_wavelengths([&](float nm) { return shape.eval(nm); });
        return s;
    }

    Rgb m_rgb;
    RgbRole m_role = RgbRole::illuminant;
    Rgb m_factor{0.0f};                               // with a shape: the colour parameter
    std::shared_ptr<const EmissionSpectrum> m_shape;  // null: the Rgb is uplifted
};

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
