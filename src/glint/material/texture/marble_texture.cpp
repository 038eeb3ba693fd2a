#include <glint/material/texture/marble_texture.h>
#include <glint/material/texture/noise.h>
#include <glint/material/texture/pattern_params.h>
#include <glint/material/texture/solid_mapping.h>

namespace glint {
namespace {

struct MarbleSettings {
    float frequency = 4.0f;          // radians of the vein wave per unit along x
    float turbulence_amount = 6.0f;  // radians of phase added by turbulence
    float noise_scale = 1.5f;        // frequency of the turbulence
    float sharpness = 12.0f;         // larger: thinner veins
    FractalSettings fractal{6, 2.0f, 0.5f};
    Rgb base{0.88f, 0.86f, 0.82f};
    Rgb vein{0.22f, 0.22f, 0.26f};
};

class MarbleTexture final : public Texture {
public:
    MarbleTexture(SolidMapping mapping, MarbleSettings settings)
        : m_mapping(mapping), m_settings(settings) {}

    Rgb eval(const TextureContext& ctx) const override {
        const float t = pattern(ctx);
        return m_settings.base * (1.0f - t) + m_settings.vein * t;
    }

    // How much vein colour, in [0, 1].
    float pattern(const TextureContext& ctx) const override {
        const Vec3 q = m_mapping.map(ctx);
        const FractalSettings& f = m_settings.fractal;
        const float disturbance =
            turbulence(q * m_settings.noise_scale, f.octaves, f.lacunarity, f.gain);
        const float wave =
            std::sin(m_settings.frequency * q.x + m_settings.turbulence_amount * disturbance);
        return vein_ramp(0.5f + 0.5f * wave);
    }

private:
    // A power of the wave's position m in [0, 1]: flat where the wave is low (the base),
    // rising only near the crest, so veins are thin lines; smooth, so they have no edge.
    float vein_ramp(float m) const {
        return std::pow(std::clamp(m, 0.0f, 1.0f), m_settings.sharpness);
    }

    SolidMapping m_mapping;
    MarbleSettings m_settings;
};

}  // namespace

// glint.texture.marble{...}
//   base, vein          colours                         defaults {0.88,0.86,0.82}, {0.22,0.22,0.26}
//   frequency           vein wave, radians per unit along x, >= 0       default 4
//   turbulence_amount   phase disturbance in radians, >= 0              default 6
//   noise_scale         frequency of the turbulence, > 0                default 1.5
//   sharpness           ramp exponent, > 0 (larger: thinner veins)      default 12
//   octaves, lacunarity, gain   of the turbulence (pattern_params.h)    defaults 6, 2, 0.5
//   transform, scale            place the pattern (solid_mapping.h)
std::unique_ptr<Texture> make_marble_texture(const Params& params, TextureTable&) {
    MarbleSettings s;
    s.base = read_colour(params, "base", s.base);
    s.vein = read_colour(params, "vein", s.vein);
    s.frequency = read_non_negative(params, "frequency", s.frequency);
    s.turbulence_amount = read_non_negative(params, "turbulence_amount", s.turbulence_amount);
    s.noise_scale = read_positive(params, "noise_scale", s.noise_scale);
    s.sharpness = read_positive(params, "sharpness", s.sharpness);
    s.fractal = read_fractal_settings(params, s.fractal.octaves);
    return std::make_unique<MarbleTexture>(read_solid_mapping(params), s);
}

}  // namespace glint
