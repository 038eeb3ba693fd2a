#include <glint/core/secondary_wavelengths.h>
#include <glint/material/materials.h>
#include <glint/material/rough_dielectric.h>
#include <glint/material/smooth_dielectric.h>
#include <glint/spectral/dispersion.h>

#include <optional>

#include <fmt/format.h>

namespace glint {
namespace {

class DielectricMaterial final : public Material {
public:
    DielectricMaterial(const FloatInput& ior, const Rgb& absorption, const FloatInput& roughness,
                       std::optional<spectral::DispersiveIor> dispersion)
        : m_ior(ior), m_interior(absorption), m_roughness(roughness), m_dispersion(dispersion) {}
    // The index per wavelength where the scene gave dispersion (RGB mode renders m_ior, its
    // value at 587.56 nm); null where the index is m_ior at every wavelength.
    const spectral::DispersiveIor* dispersion() const {
        return m_dispersion ? &*m_dispersion : nullptr;
    }
    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        const float ior = index(si);
        const bool hero_only = m_dispersion.has_value() && spectral_mode_active();
        const GgxDistribution distribution(roughness_to_alpha(m_roughness.eval(si)));
        // An index-matched interface is invisible however rough: light passes straight on.
        if (distribution.effectively_smooth() || ior == 1.0f) {
            return arena.make<SmoothDielectricBsdf>(ior, hero_only);
        }
        return arena.make<RoughDielectricBsdf>(ior, distribution, hero_only);
    }
    Spectrum albedo(const SurfaceInteraction&) const override { return Spectrum(1.0f); }
    // Beer-Lambert absorption inside is a medium that only absorbs: the first user of the
    // medium hook. Clear glass separates no media.
    MediumInterface intrinsic_media() const override {
        if (!m_interior.absorbs()) return {};
        return MediumInterface{&m_interior, nullptr};
    }

private:
    // A dispersive glass bends each wavelength its own way: in spectral mode it scatters by
    // the hero wavelength's index and its BSDF ends the other wavelengths (their directions
    // would differ; Spectrum::hero_only), which keeps the estimate unbiased at the cost of
    // colour noise after the glass. RGB mode uses m_ior, the index at 587.56 nm.
    float index(const SurfaceInteraction& si) const {
        const SampledWavelengths* lambda = m_dispersion ? active_wavelengths() : nullptr;
        if (lambda == nullptr) return m_ior.eval(si);
        terminate_secondary_wavelengths();
        return static_cast<float>(m_dispersion->eval(lambda->hero()));
    }

    FloatInput m_ior;
    AbsorbingMedium m_interior;
    FloatInput m_roughness;
    std::optional<spectral::DispersiveIor> m_dispersion;
};

std::string dielectric_preset_names() {
    std::string names;
    for (const std::string& name : spectral::dielectric_names())
        names += fmt::format("{}'{}'", names.empty() ? "" : ", ", name);
    return names;
}

// The index of refraction as a function of wavelength, from `ior` (a number, or a preset's
// name) with `abbe`, or from `sellmeier_b` and `sellmeier_c`, or from `cauchy`; nothing when
// the index is a plain number or texture without dispersion.
std::optional<spectral::DispersiveIor> read_dispersion(const Params& params) {
    const bool sellmeier = params.has("sellmeier_b") || params.has("sellmeier_c");
    const bool cauchy = params.has("cauchy"), abbe = params.has("abbe");
    const bool named = params.has("ior") && params.is_string("ior");
    if (int(sellmeier) + int(cauchy) + int(abbe) + int(named) > 1)
        params.fail(
            "give one of a preset 'ior' name, 'abbe', 'sellmeier_b' and 'sellmeier_c', "
            "or 'cauchy'");
    if ((sellmeier || cauchy) && params.has("ior"))
        params.fail("'ior' follows from the Sellmeier or Cauchy coefficients: leave it out");
    if (named) {
        const std::string name = params.get_string("ior");
        auto preset = spectral::named_dielectric(name);
        if (!preset)
            params.fail(fmt::format("unknown 'ior' preset '{}'; known: {} (or give a number)", name,
                                    dielectric_preset_names()));
        return preset;
    }
    if (abbe) {
        const float n_d = params.get_float("ior", 1.5f);
        const float v_d = params.get_float("abbe");
        if (!(n_d >= 1.0f && n_d <= 10.0f)) params.fail("with 'abbe', 'ior' must be in [1, 10]");
        if (!(v_d >= 5.0f && v_d <= 1000.0f))
            params.fail("'abbe' (the Abbe number V_d) must be in [5, 1000]");
        return spectral::DispersiveIor::from_abbe(n_d, v_d);
    }
    if (sellmeier) {
        const std::vector<double> b = params.get_numbers("sellmeier_b");
        const std::vector<double> c = params.get_numbers("sellmeier_c");
        if (auto problem = spectral::DispersiveIor::check_sellmeier(b, c)) params.fail(*problem);
        return spectral::DispersiveIor::sellmeier(b, c);
    }
    if (cauchy) {
        const std::vector<double> t = params.get_numbers("cauchy");
        if (t.empty() || t.size() > 3)
            params.fail("'cauchy' is {A, B} or {A, B, C}: n = A + B/λ² + C/λ⁴, λ in µm");
        return spectral::DispersiveIor::cauchy(t[0], t.size() > 1 ? t[1] : 0.0,
                                               t.size() > 2 ? t[2] : 0.0);
    }
    return std::nullopt;
}

}  // namespace

// glint.dielectric{...}: glass, water, any clear interface; smooth or rough.
//   ior         float, texture or preset  1.5  index inside over index outside, in
//                                       [0.01, 100]; or a dispersive preset: "BK7",
//                                       "fused silica", "diamond", "water"
//   abbe        float     -            Abbe number V_d: dispersion around n_d = ior
//   sellmeier_b, sellmeier_c  numbers  -  Sellmeier terms (λ in µm, C in µm²)
//   cauchy      numbers   -            {A, B[, C]}: n = A + B/λ² + C/λ⁴, λ in µm
//   With dispersion, RGB mode uses the index at 587.56 nm (n_d).
//   absorption  spectrum          0    Beer-Lambert coefficient of the inside, per scene unit
//   roughness   float or texture  0    in [0, 1], alpha = roughness^2 (GGX, rough_dielectric.h);
//                                       0 is smooth glass (smooth_dielectric.h)
std::unique_ptr<Material> make_dielectric_material(const Params& params, TextureTable& textures) {
    const std::optional<spectral::DispersiveIor> dispersion = read_dispersion(params);
    // A texture (say a noise between 1.45 and 1.55) makes the index vary over the surface.
    const FloatInput ior = dispersion ? FloatInput(static_cast<float>(dispersion->reference()))
                                      : textures.scalar(params, "ior", 1.5f, 0.01f, 100.0f);
    if (dispersion && !(dispersion->reference() >= 1.0 && dispersion->reference() <= 10.0))
        params.fail(
            fmt::format("the index at 587.56 nm is {}, outside [1, 10]", dispersion->reference()));
    const Rgb absorption = params.get_rgb("absorption", Rgb(0.0f));
    if (absorption.min_value() < 0.0f) {
        params.fail("'absorption' must not be negative");
    }
    const FloatInput roughness = textures.scalar(params, "roughness", 0.0f, 0.0f, 1.0f);
    return std::make_unique<DielectricMaterial>(ior, absorption, roughness, dispersion);
}

}  // namespace glint
