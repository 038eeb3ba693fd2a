#include <glint/material/conductor_presets.h>
#include <glint/material/materials.h>
#include <glint/material/rough_conductor.h>
#include <glint/spectral/conductors.h>

#include <fmt/format.h>

namespace glint {
namespace {

class ConductorMaterial final : public Material {
public:
    ConductorMaterial(const SceneColor& eta, const SceneColor& k, const FloatInput& roughness,
                      float anisotropy, const SpectrumInput& tint,
                      const spectral::ConductorData* measured)
        : m_eta(eta),
          m_k(k),
          m_roughness(roughness),
          m_anisotropy(anisotropy),
          m_tint(tint),
          m_measured(measured) {}

    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        const float alpha = roughness_to_alpha(m_roughness.eval(si));
        const ConductorFresnel fresnel{eta(), k(), m_tint.eval(si), false};
        return arena.make<RoughConductorBsdf>(GgxDistribution::anisotropic(alpha, m_anisotropy),
                                              fresnel);
    }
    const spectral::ConductorData* measured() const { return m_measured; }
    // The reflectance at normal incidence, the colour one sees in a metal.
    Spectrum albedo(const SurfaceInteraction& si) const override {
        return m_tint.eval(si) * fresnel_conductor(1.0f, eta(), k());
    }

private:
    // The index at the path's wavelengths: measured values where the scene named a metal and
    // spectral mode is on, the colours' uplift otherwise (RGB mode: the colours).
    Spectrum eta() const {
        if (m_measured && spectral_mode_active())
            return Spectrum::at_wavelengths([this](float nm) { return m_measured->eval(nm).eta; });
        return m_eta.spectrum();
    }
    Spectrum k() const {
        if (m_measured && spectral_mode_active())
            return Spectrum::at_wavelengths([this](float nm) { return m_measured->eval(nm).k; });
        return m_k.spectrum();
    }

    // Colours, read at each path's wavelengths in spectral mode.
    SceneColor m_eta;
    SceneColor m_k;
    FloatInput m_roughness;
    float m_anisotropy;
    SpectrumInput m_tint;
    // The measured η(λ), k(λ) behind m_eta and m_k when the scene named a `metal` (what a
    // spectral mode evaluates per wavelength); null for RGB constants.
    const spectral::ConductorData* m_measured;
};

std::string conductor_preset_names() {
    std::string names;
    for (const ConductorPreset& preset : kConductorPresets) {
        names += fmt::format("{}'{}'", names.empty() ? "" : ", ", preset.name);
    }
    return names;
}

std::string measured_names() {
    std::string names;
    for (const std::string& name : spectral::conductor_names())
        names += fmt::format("{}'{}'", names.empty() ? "" : ", ", name);
    return names;
}

}  // namespace

// glint.conductor{...}: a metal, smooth or rough.
//   metal       string    -            measured η(λ), k(λ): "Au", "Ag", "Cu", "Al" (or "gold",
//                                       ...; spectral/conductors.h), integrated to RGB in RGB mode,
//                                       evaluated per wavelength in spectral mode
//   preset      string    "aluminium"  RGB constants of a metal: "gold", "silver", "copper" or
//                                       "aluminium" (conductor_presets.h); or give both of
//   eta, k      spectrum  -            the complex index eta + i k per channel (eta > 0, k >= 0)
//   roughness   float or texture  0.1  in [0, 1], alpha = roughness^2; 0 is a mirror
//   anisotropy  float     0            in [-1, 1]: > 0 stretches highlights along the surface
//                                       tangent (the u direction), < 0 across it
//   tint        spectrum or texture 1  in [0, 1], multiplies the Fresnel reflectance
std::unique_ptr<Material> make_conductor_material(const Params& params, TextureTable& textures) {
    const bool has_eta = params.has("eta"), has_k = params.has("k");
    if (params.has("preset") && (has_eta || has_k)) {
        params.fail("give either 'preset' or 'eta' and 'k', not both");
    }
    if (params.has("metal") && (params.has("preset") || has_eta || has_k)) {
        params.fail("give 'metal' alone, without 'preset', 'eta' or 'k'");
    }
    if (has_eta != has_k) params.fail("give both 'eta' and 'k' (the complex index eta + i k)");
    SceneColor eta, k;
    const spectral::ConductorData* measured = nullptr;
    if (has_eta) {
        const Rgb eta_rgb = params.get_rgb("eta"), k_rgb = params.get_rgb("k");
        if (eta_rgb.min_value() <= 0.0f) params.fail("'eta' must be positive");
        if (k_rgb.min_value() < 0.0f) params.fail("'k' must not be negative");
        eta = SceneColor(eta_rgb, RgbRole::unbounded);
        k = SceneColor(k_rgb, RgbRole::unbounded);
    } else if (params.has("metal")) {
        const std::string name = params.get_string("metal");
        const spectral::ConductorData* metal = spectral::named_conductor(name);
        if (!metal) {
            params.fail(
                fmt::format("unknown 'metal' '{}'; measured metals: {}", name, measured_names()));
        }
        eta = SceneColor(metal->rgb_eta(), RgbRole::unbounded);
        k = SceneColor(metal->rgb_k(), RgbRole::unbounded);
        measured = metal;
    } else {
        const std::string name = params.get_string("preset", "aluminium");
        const ConductorPreset* preset = find_conductor_preset(name);
        if (!preset) {
            params.fail(
                fmt::format("unknown 'preset' '{}'; known presets: {}", name, conductor_preset_names()));
        }
        eta = SceneColor(preset->eta, RgbRole::unbounded);
        k = SceneColor(preset->k, RgbRole::unbounded);
    }
    const FloatInput roughness = textures.scalar(params, "roughness", 0.1f, 0.0f, 1.0f);
    const float anisotropy = params.get_float("anisotropy", 0.0f);
    if (!(anisotropy >= -1.0f && anisotropy <= 1.0f)) {
        params.fail("'anisotropy' must lie in [-1, 1]");
    }
    const SpectrumInput tint = textures.spectrum(params, "tint", Rgb(1.0f), 0.0f, 1.0f);
    return std::make_unique<ConductorMaterial>(eta, k, roughness, anisotropy, tint, measured);
}

}  // namespace glint
