#include <glint/material/texture/noise.h>
#include <glint/material/texture/noise_texture.h>
#include <glint/material/texture/pattern_params.h>
#include <glint/material/texture/solid_mapping.h>

namespace glint {
namespace {

enum class NoisePattern { kNoise, kFbm, kTurbulence };

class NoiseTexture final : public Texture {
public:
    NoiseTexture(NoisePattern pattern, SolidMapping mapping, FractalSettings fractal, Rgb low,
                 Rgb high)
        : m_pattern(pattern), m_mapping(mapping), m_fractal(fractal), m_low(low), m_high(high) {}

    Rgb eval(const TextureContext& ctx) const override {
        const float t = std::clamp(colour_position(pattern(ctx)), 0.0f, 1.0f);
        return m_low * (1.0f - t) + m_high * t;
    }

    // The pattern value: in [-kNoiseBound, kNoiseBound] for noise and fbm, in
    // [0, kNoiseBound] for turbulence.
    float pattern(const TextureContext& ctx) const override {
        const Vec3 q = m_mapping.map(ctx);
        switch (m_pattern) {
            case NoisePattern::kNoise:
                return perlin_noise(q);
            case NoisePattern::kFbm:
                return fbm(q, m_fractal.octaves, m_fractal.lacunarity, m_fractal.gain);
            case NoisePattern::kTurbulence:
                return turbulence(q, m_fractal.octaves, m_fractal.lacunarity, m_fractal.gain);
        }
        return 0.0f;
    }

private:
    // Signed patterns put 0 half-way between the colours; turbulence starts at `low`.
    float colour_position(float value) const {
        return m_pattern == NoisePattern::kTurbulence ? value : 0.5f + 0.5f * value;
    }

    NoisePattern m_pattern;
    SolidMapping m_mapping;
    FractalSettings m_fractal;
    Rgb m_low, m_high;
};

std::unique_ptr<Texture> make(NoisePattern pattern, const Params& params) {
    const Rgb low = read_colour(params, "low", Rgb(0.0f));
    const Rgb high = read_colour(params, "high", Rgb(1.0f));
    const FractalSettings fractal = pattern == NoisePattern::kNoise
                                        ? FractalSettings{1, 2.0f, 0.5f}
                                        : read_fractal_settings(params, 6);
    return std::make_unique<NoiseTexture>(pattern, read_solid_mapping(params), fractal, low, high);
}

}  // namespace

// glint.texture.noise{...}: one octave of Perlin noise.
//   low, high   colours for noise -1 and +1 (0 is half-way)     defaults 0 and 1
//   scale       frequency: lattice cells per unit               default 1
//   transform   places the pattern in object space              default identity
std::unique_ptr<Texture> make_noise_texture(const Params& params, TextureTable&) {
    return make(NoisePattern::kNoise, params);
}

// glint.texture.fbm{...}: fractional Brownian motion; as noise, plus
//   octaves     1 to 16                                         default 6
//   lacunarity  frequency ratio between octaves, > 0            default 2
//   gain        amplitude ratio between octaves, >= 0           default 0.5
std::unique_ptr<Texture> make_fbm_texture(const Params& params, TextureTable&) {
    return make(NoisePattern::kFbm, params);
}

// glint.texture.turbulence{...}: as fbm with |noise|; `low` at 0, `high` at 1.
std::unique_ptr<Texture> make_turbulence_texture(const Params& params, TextureTable&) {
    return make(NoisePattern::kTurbulence, params);
}

}  // namespace glint
