#include <glint/material/materials.h>
#include <glint/material/principled_bsdf.h>
#include <glint/spectral/dispersion.h>

#include <optional>

#include <fmt/format.h>

namespace glint {
namespace {

// The index of refraction whose Fresnel reflectance at normal incidence is f0:
// f0 = ((eta - 1) / (eta + 1))^2.
float eta_from_f0(float f0) {
    const float r = std::sqrt(std::clamp(f0, 0.0f, 0.99f));
    return (1.0f + r) / (1.0f - r);
}

float clamped_alpha(float roughness) {
    return std::max(roughness_to_alpha(roughness), PrincipledBsdf::kMinAlpha);
}

struct PrincipledInputs {
    SpectrumInput base_color;
    FloatInput metallic, roughness, transmission;
    // Channels of a glTF metallic-roughness texture, multiplying the two factors above;
    // constant 1 without one.
    FloatInput packed_metallic{1.0f}, packed_roughness{1.0f};
    float ior = 1.5f;
    float specular_eta = 1.5f;
    float clearcoat = 0.0f, clearcoat_roughness = 0.03f;
    float sheen = 0.0f, sheen_tint = 0.5f;
    SceneColor emission;
    Rgb absorption{0.0f};
    // The transmission's index per wavelength, from `abbe` (glTF KHR_materials_dispersion);
    // RGB mode renders `ior`, its value at 587.56 nm.
    std::optional<spectral::DispersiveIor> dispersion;
};

class PrincipledMaterial final : public Material {
public:
    // The specular layer's albedo table covers every alpha the roughness can take: one value
    // for a constant, the whole range for a textured one.
    explicit PrincipledMaterial(const PrincipledInputs& in)
        : m_in(in),
          m_interior(in.absorption),
          m_specular_albedo(in.specular_eta,
                            textured_roughness() ? PrincipledBsdf::kMinAlpha : constant_alpha(),
                            textured_roughness() ? 1.0f : constant_alpha()),
          m_coat_albedo(1.5f, clamped_alpha(in.clearcoat_roughness),
                        clamped_alpha(in.clearcoat_roughness)) {}

    // The transmission's index per wavelength where `abbe` gave one; null otherwise.
    const spectral::DispersiveIor* dispersion() const {
        return m_in.dispersion ? &*m_in.dispersion : nullptr;
    }

    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        PrincipledParams p;
        p.base_color = m_in.base_color.eval(si);
        p.metallic = m_in.metallic.eval(si) * m_in.packed_metallic.eval(si);
        p.alpha = clamped_alpha(m_in.roughness.eval(si) * m_in.packed_roughness.eval(si));
        p.ior = m_in.ior;
        p.transmission = m_in.transmission.eval(si);
        p.clearcoat = m_in.clearcoat;
        p.clearcoat_alpha = clamped_alpha(m_in.clearcoat_roughness);
        p.sheen = m_in.sheen;
        p.sheen_tint = m_in.sheen_tint;
        return arena.make<PrincipledBsdf>(p, m_specular_albedo, m_coat_albedo);
    }
    Spectrum albedo(const SurfaceInteraction& si) const override {
        return m_in.base_color.eval(si);
    }
    SceneColor emission() const override { return m_in.emission; }
    // Absorption inside (KHR_materials_volume) is a medium that only absorbs, as for glass.
    MediumInterface intrinsic_media() const override {
        if (!m_interior.absorbs()) return {};
        return MediumInterface{&m_interior, nullptr};
    }

private:
    bool textured_roughness() const {
        return m_in.roughness.is_textured() || m_in.packed_roughness.is_textured();
    }
    float constant_alpha() const { return clamped_alpha(m_in.roughness.representative()); }

    PrincipledInputs m_in;
    AbsorbingMedium m_interior;
    CoatAlbedoTable m_specular_albedo;
    CoatAlbedoTable m_coat_albedo;
};

float number_in(const Params& params, const std::string& name, float fallback, float lo, float hi) {
    if (params.is_ref(name, "texture")) {
        params.fail(fmt::format("'{}' must be a number (textures are not supported for it)", name));
    }
    const float value = params.get_float(name, fallback);
    if (!(value >= lo && value <= hi))
        params.fail(fmt::format("'{}' must lie in [{}, {}]", name, lo, hi));
    return value;
}

}  // namespace

// glint.principled{...}: one material for most surfaces, the Disney / Blender Principled and
// glTF metallic-roughness model (principled_bsdf.h; docs/materials.md).
//   base_color           spectrum or texture  0.8   in [0, 1]: diffuse colour of a dielectric,
//                                                   F0 of a metal, tint of transmission
//   metallic             float or texture     0     in [0, 1]
//   roughness            float or texture     0.5   in [0, 1], alpha = roughness^2 (>= 0.001)
//   metallic_roughness   texture or file      -     glTF packing: green = roughness, blue =
//                                                   metallic, multiplying the two above
//   ior                  float                1.5   in [1, 10], of the transmission (and of the
//                                                   specular reflection without `specular`)
//   abbe                 float                -     in [5, 1000]: Abbe number V_d of the
//                                                   transmission's dispersion around n_d = ior
//   specular             float                -     in [0, 1]: a dielectric's reflectance at
//                                                   normal incidence is 0.08 specular (0.5 gives
//                                                   0.04, i.e. ior 1.5); when given it wins
//                                                   over `ior` for the opaque reflection
//   transmission         float or texture     0     in [0, 1], the part of the dielectric that
//                                                   is rough glass
//   clearcoat            float                0     in [0, 1], weight of a clear coat (ior 1.5)
//   clearcoat_roughness  float                0.03  in [0, 1]
//   sheen                float                0     in [0, 1], Burley's sheen at grazing angles
//   sheen_tint           float                0.5   in [0, 1], white (0) to the base hue (1)
//   absorption           spectrum             0     >= 0, Beer-Lambert coefficient of the inside
//                                                   per scene unit (seen through transmission)
//   emission             spectrum             0     emitted radiance (a light source when not
//                                                   black), times
//   emission_strength    float                1     >= 0
std::unique_ptr<Material> make_principled_material(const Params& params, TextureTable& textures) {
    PrincipledInputs in;
    in.base_color = textures.spectrum(params, "base_color", Rgb(0.8f), 0.0f, 1.0f);
    in.metallic = textures.scalar(params, "metallic", 0.0f, 0.0f, 1.0f);
    in.roughness = textures.scalar(params, "roughness", 0.5f, 0.0f, 1.0f);
    if (const Texture* packed = textures.texture_or_file(params, "metallic_roughness")) {
        in.packed_roughness = FloatInput::channel(packed, 1, 0.0f, 1.0f);
        in.packed_metallic = FloatInput::channel(packed, 2, 0.0f, 1.0f);
    }
    in.ior = number_in(params, "ior", 1.5f, 1.0f, 10.0f);
    if (params.has("abbe"))
        in.dispersion = spectral::DispersiveIor::from_abbe(
            in.ior, number_in(params, "abbe", 64.0f, 5.0f, 1000.0f));
    in.specular_eta = in.ior;
    if (params.has("specular"))
        in.specular_eta = eta_from_f0(0.08f * number_in(params, "specular", 0.5f, 0.0f, 1.0f));
    // Rough refraction through an index-matched interface is a delta (straight through): the
    // glass keeps an index a little above 1.
    in.ior = std::max(in.ior, 1.01f);
    in.transmission = textures.scalar(params, "transmission", 0.0f, 0.0f, 1.0f);
    in.clearcoat = number_in(params, "clearcoat", 0.0f, 0.0f, 1.0f);
    in.clearcoat_roughness = number_in(params, "clearcoat_roughness", 0.03f, 0.0f, 1.0f);
    in.sheen = number_in(params, "sheen", 0.0f, 0.0f, 1.0f);
    in.sheen_tint = number_in(params, "sheen_tint", 0.5f, 0.0f, 1.0f);
    if (params.is_ref("emission", "texture")) {
        params.fail(
            "'emission' must be a colour: textured emission is not supported yet (area lights "
            "emit a constant radiance)");
    }
    const Rgb emission = params.get_rgb("emission", Rgb(0.0f));
    if (!(emission.min_value() >= 0.0f) || !std::isfinite(emission.max_value()))
        params.fail("'emission' must be finite and not negative");
    const float strength = params.get_float("emission_strength", 1.0f);
    if (!(strength >= 0.0f) || !std::isfinite(strength))
        params.fail("'emission_strength' must be a finite number >= 0");
    in.emission = SceneColor(emission * strength, RgbRole::illuminant);
    const Rgb absorption = params.get_rgb("absorption", Rgb(0.0f));
    if (!(absorption.min_value() >= 0.0f) || !absorption.is_finite())
        params.fail("'absorption' must be finite and not negative");
    in.absorption = absorption;
    return std::make_unique<PrincipledMaterial>(in);
}

}  // namespace glint
