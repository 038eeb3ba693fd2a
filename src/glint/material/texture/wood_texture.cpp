#include <glint/material/texture/noise.h>
#include <glint/material/texture/pattern_params.h>
#include <glint/material/texture/solid_mapping.h>
#include <glint/material/texture/wood_texture.h>

namespace glint {
namespace {

struct WoodSettings {
    float rings = 8.0f;         // rings per unit of distance from the axis
    float noise_amount = 1.5f;  // displacement of the rings, in rings
    float noise_scale = 1.5f;   // frequency of that displacement
    float grain = 4.0f;         // how much slower the displacement varies along the axis
    FractalSettings fractal{4, 2.0f, 0.5f};
    Rgb light{0.70f, 0.50f, 0.30f};
    Rgb dark{0.40f, 0.23f, 0.11f};
};

class WoodTexture final : public Texture {
public:
    WoodTexture(SolidMapping mapping, WoodSettings settings)
        : m_mapping(mapping), m_settings(settings) {}

    Rgb eval(const TextureContext& ctx) const override {
        const float t = pattern(ctx);
        return m_settings.light * (1.0f - t) + m_settings.dark * t;
    }

    // How dark the wood is, in [0, 1].
    float pattern(const TextureContext& ctx) const override {
        const Vec3 q = m_mapping.map(ctx);
        const float radius = std::sqrt(q.x * q.x + q.z * q.z);
        // A tree grows unevenly around and slowly along its trunk: the noise displacing
        // the rings is stretched along the axis by `grain`.
        const Vec3 noise_point = Vec3(q.x, q.y / m_settings.grain, q.z) * m_settings.noise_scale;
        const FractalSettings& f = m_settings.fractal;
        const float ring =
            radius * m_settings.rings +
            m_settings.noise_amount * fbm(noise_point, f.octaves, f.lacunarity, f.gain);
        return ring_profile(ring - std::floor(ring));
    }

private:
    // Light early wood turning smoothly into a narrower dark band of late wood, and back:
    // a raised cosine, periodic and smooth, squared to narrow the dark part.
    static float ring_profile(float phase) {
        const float wave = 0.5f - 0.5f * std::cos(2.0f * kPi * phase);
        return wave * wave;
    }

    SolidMapping m_mapping;
    WoodSettings m_settings;
};

}  // namespace

// glint.texture.wood{...}
//   light, dark    colours of early and late wood          defaults {0.7,0.5,0.3}, {0.4,0.23,0.11}
//   rings          rings per unit distance from the axis, > 0     default 8
//   noise_amount   ring displacement by fbm, in rings, >= 0       default 1.5
//   noise_scale    frequency of the displacing noise, > 0         default 1.5
//   grain          noise stretch along the axis, > 0              default 4
//   octaves, lacunarity, gain   of the fbm (pattern_params.h)     defaults 4, 2, 0.5
//   transform, scale            place the pattern (solid_mapping.h); the axis is its y axis
std::unique_ptr<Texture> make_wood_texture(const Params& params, TextureTable&) {
    WoodSettings s;
    s.light = read_colour(params, "light", s.light);
    s.dark = read_colour(params, "dark", s.dark);
    s.rings = read_positive(params, "rings", s.rings);
    s.noise_amount = read_non_negative(params, "noise_amount", s.noise_amount);
    s.noise_scale = read_positive(params, "noise_scale", s.noise_scale);
    s.grain = read_positive(params, "grain", s.grain);
    s.fractal = read_fractal_settings(params, s.fractal.octaves);
    return std::make_unique<WoodTexture>(read_solid_mapping(params), s);
}

}  // namespace glint
