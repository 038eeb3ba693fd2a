#include <glint/material/dispersion.h>
#include <glint/material/materials.h>
#include <glint/material/rough_dielectric.h>
#include <glint/material/smooth_dielectric.h>

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <vector>

namespace glint {
namespace {

class DielectricMaterial final : public Material {
public:
    DielectricMaterial(const FloatInput& ior, const Spectrum& absorption,
                       const FloatInput& roughness, std::optional<Dispersion> dispersion)
        : m_ior(ior), m_interior(absorption), m_roughness(roughness), m_dispersion(dispersion) {}
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
    MediumInterface medium_interface() const override {
        if (m_interior.sigma_a().is_black()) return {};
        return MediumInterface{&m_interior, nullptr};
    }

private:
    // A dispersive glass bends each wavelength its own way: in spectral mode it scatters by
    // the hero wavelength's index and its BSDF ends the other wavelengths (their directions
    // would differ; Spectrum::hero_only), which keeps the estimate unbiased at the cost of
    // colour noise after the glass. RGB mode uses n_d.
    float index(const SurfaceInteraction& si) const {
        if (!m_dispersion) return m_ior.eval(si);
        const SampledWavelengths* lambda = active_wavelengths();
        if (lambda == nullptr) return m_dispersion->reference_index();
        return m_dispersion->index(lambda->hero());
    }

    FloatInput m_ior;
    AbsorbingMedium m_interior;
    FloatInput m_roughness;
    std::optional<Dispersion> m_dispersion;
};

// The dispersion a glint.dielectric{...} states: Sellmeier coefficients, or an Abbe number
// with `ior` as n_d; none for a constant index.
std::optional<Dispersion> read_dispersion(const Params& params, const FloatInput& ior) {
    const bool sellmeier = params.has("sellmeier");
    const bool abbe = params.has("abbe");
    if (sellmeier && abbe) params.fail("give 'sellmeier' or 'abbe', not both");
    if (sellmeier) {
        if (params.has("ior")) params.fail("give 'sellmeier' or 'ior', not both");
        const std::vector<double> v = params.get_numbers("sellmeier");
        if (v.size() != 6) {
            params.fail(fmt::format("'sellmeier' must be 6 numbers {{B1, B2, B3, C1, C2, C3}} "
                                    "(C in square micrometres), got {}",
                                    v.size()));
        }
        for (double x : v) {
            if (!std::isfinite(x) || x < 0.0)
                params.fail("'sellmeier' coefficients must be finite and not negative");
        }
        const Dispersion d = Dispersion::sellmeier({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
        if (!(d.reference_index() > 1.0f && d.index(380.0f) > 1.0f))
            params.fail("'sellmeier' gives no index above 1 over the visible range");
        return d;
    }
    if (abbe) {
        const float v = params.get_float("abbe");
        if (!(v >= 1.0f) || !std::isfinite(v))
            params.fail(fmt::format("'abbe' must be a finite number >= 1, got {}", v));
        if (ior.is_textured()) params.fail("'abbe' needs a constant 'ior' (n_d), not a texture");
        return Dispersion::from_abbe(ior.representative(), v);
    }
    return std::nullopt;
}

}  // namespace

// glint.dielectric{...}: glass, water, any clear interface; smooth or rough.
//   ior         float or texture  1.5  index inside over index outside, in [0.01, 100]
//   absorption  spectrum          0    Beer-Lambert coefficient of the inside, per scene unit
//   roughness   float or texture  0    in [0, 1], alpha = roughness^2 (GGX, rough_dielectric.h);
//                                       0 is smooth glass (smooth_dielectric.h)
//   abbe        float             none dispersion: the Abbe number V_d, with `ior` as n_d
//                                       (a Cauchy index; BK7 64.2, diamond 55.3, water 55.7)
//   sellmeier   6 numbers         none dispersion: {B1, B2, B3, C1, C2, C3}, C in µm²;
//                                       replaces `ior` (BK7: 1.03961212, 0.231792344,
//                                       1.01046945, 0.00600069867, 0.0200179144, 103.560653)
// Dispersion matters in spectral mode (glint.render{ spectral = true }); RGB mode uses the
// index at 587.56 nm.
std::unique_ptr<Material> make_dielectric_material(const Params& params, TextureTable& textures) {
    // A texture (say a noise between 1.45 and 1.55) makes the index vary over the surface.
    const FloatInput ior = textures.scalar(params, "ior", 1.5f, 0.01f, 100.0f);
    const Rgb absorption = params.get_rgb("absorption", Rgb(0.0f));
    if (absorption.min_value() < 0.0f) {
        params.fail("'absorption' must not be negative");
    }
    const FloatInput roughness = textures.scalar(params, "roughness", 0.0f, 0.0f, 1.0f);
    std::optional<Dispersion> dispersion = read_dispersion(params, ior);
    return std::make_unique<DielectricMaterial>(ior, uplift(absorption, RgbRole::unbounded),
                                                roughness, dispersion);
}

}  // namespace glint
