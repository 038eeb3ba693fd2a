#pragma once
// A material parameter that is either a constant or a texture: what every colour,
// roughness or weight of a material is, so that any of them can vary over a surface.
#include <glint/core/spectrum.h>
#include <glint/material/texture/texture.h>

namespace glint {

class SpectrumInput {
public:
    SpectrumInput() = default;
    // A constant colour; `hi` is the bound it was checked against: at most 1 makes it a
    // reflectance, anything else an unbounded quantity (what `uplift` needs to know).
    explicit SpectrumInput(const Rgb& constant, float hi = 1.0f)
        : m_constant(constant), m_role(role_for(hi)) {}
    // Texture values are clamped to [lo, hi], so a texture cannot break a limit that a
    // constant is checked against (a reflectance above 1 would create energy).
    SpectrumInput(const Texture* texture, float lo, float hi)
        : m_texture(texture), m_lo(lo), m_hi(hi), m_role(role_for(hi)) {}

    Spectrum eval(const SurfaceInteraction& si) const {
        if (!m_texture) return uplift(m_constant, m_role);
        return uplift(m_texture->eval(TextureContext(si)).clamped(m_lo, m_hi), m_role);
    }
    bool is_textured() const { return m_texture != nullptr; }
    // The constant value, or a representative one (0.5) for a texture.
    Spectrum representative() const { return uplift(m_texture ? Rgb(0.5f) : m_constant, m_role); }

private:
    static RgbRole role_for(float hi) {
        return hi <= 1.0f ? RgbRole::reflectance : RgbRole::unbounded;
    }

    Rgb m_constant{0.0f};
    const Texture* m_texture = nullptr;
    float m_lo = 0.0f, m_hi = 0.0f;
    RgbRole m_role = RgbRole::reflectance;
};

class FloatInput {
public:
    FloatInput() = default;
    explicit FloatInput(float constant) : m_constant(constant) {}
    FloatInput(const Texture* texture, float lo, float hi)
        : m_texture(texture), m_lo(lo), m_hi(hi) {}
    // One channel (0 red, 1 green, 2 blue) of a colour texture instead of the channels'
    // average: for textures that pack several parameters, like glTF's metallic-roughness
    // maps (roughness in green, metallic in blue).
    static FloatInput channel(const Texture* texture, int channel, float lo, float hi) {
        FloatInput input(texture, lo, hi);
        input.m_channel = channel;
        return input;
    }

    float eval(const SurfaceInteraction& si) const {
        if (!m_texture) return m_constant;
        const TextureContext context(si);
        const float v =
            m_channel < 0 ? m_texture->eval_float(context) : m_texture->eval(context)[m_channel];
        return std::clamp(v, m_lo, m_hi);
    }
    bool is_textured() const { return m_texture != nullptr; }
    float representative() const { return m_texture ? 0.5f * (m_lo + m_hi) : m_constant; }

private:
    float m_constant = 0.0f;
    const Texture* m_texture = nullptr;
    float m_lo = 0.0f, m_hi = 0.0f;
    int m_channel = -1;  // the average of the channels
};

}  // namespace glint
