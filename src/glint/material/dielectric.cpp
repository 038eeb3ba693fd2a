#include <glint/material/materials.h>
#include <glint/material/rough_dielectric.h>
#include <glint/material/smooth_dielectric.h>

namespace glint {
namespace {

class DielectricMaterial final : public Material {
public:
    DielectricMaterial(const FloatInput& ior, const Spectrum& absorption,
                       const FloatInput& roughness)
        : m_ior(ior), m_interior(absorption), m_roughness(roughness) {}
    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        const float ior = m_ior.eval(si);
        const GgxDistribution distribution(roughness_to_alpha(m_roughness.eval(si)));
        // An index-matched interface is invisible however rough: light passes straight on.
        if (distribution.effectively_smooth() || ior == 1.0f) {
            return arena.make<SmoothDielectricBsdf>(ior);
        }
        return arena.make<RoughDielectricBsdf>(ior, distribution);
    }
    Spectrum albedo(const SurfaceInteraction&) const override { return Spectrum(1.0f); }
    // Beer-Lambert absorption inside is a medium that only absorbs: the first user of the
    // medium hook. Clear glass separates no media.
    MediumInterface intrinsic_media() const override {
        if (m_interior.sigma_a().is_black()) return {};
        return MediumInterface{&m_interior, nullptr};
    }

private:
    FloatInput m_ior;
    AbsorbingMedium m_interior;
    FloatInput m_roughness;
};

}  // namespace

// glint.dielectric{...}: glass, water, any clear interface; smooth or rough.
//   ior         float or texture  1.5  index inside over index outside, in [0.01, 100]
//   absorption  spectrum          0    Beer-Lambert coefficient of the inside, per scene unit
//   roughness   float or texture  0    in [0, 1], alpha = roughness^2 (GGX, rough_dielectric.h);
//                                       0 is smooth glass (smooth_dielectric.h)
std::unique_ptr<Material> make_dielectric_material(const Params& params, TextureTable& textures) {
    // A texture (say a noise between 1.45 and 1.55) makes the index vary over the surface.
    const FloatInput ior = textures.scalar(params, "ior", 1.5f, 0.01f, 100.0f);
    const Rgb absorption = params.get_rgb("absorption", Rgb(0.0f));
    if (absorption.min_value() < 0.0f) {
        params.fail("'absorption' must not be negative");
    }
    const FloatInput roughness = textures.scalar(params, "roughness", 0.0f, 0.0f, 1.0f);
    return std::make_unique<DielectricMaterial>(ior, uplift(absorption, RgbRole::unbounded),
                                                roughness);
}

}  // namespace glint
