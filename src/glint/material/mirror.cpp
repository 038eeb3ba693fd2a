#include <glint/material/materials.h>
#include <glint/material/specular_reflection.h>

#include <optional>

namespace glint {
namespace {

class MirrorMaterial final : public Material {
public:
    explicit MirrorMaterial(const SpectrumInput& tint) : m_tint(tint) {
        if (!tint.is_textured()) m_uniform_bsdf.emplace(tint.representative());
    }
    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        // The shared BSDF holds the RGB tint: spectral mode reads it at the path's wavelengths.
        if (m_uniform_bsdf && !spectral_mode_active()) return &*m_uniform_bsdf;
        return arena.make<SpecularReflectionBsdf>(m_tint.eval(si));
    }
    Spectrum albedo(const SurfaceInteraction& si) const override { return m_tint.eval(si); }

private:
    SpectrumInput m_tint;
    std::optional<SpecularReflectionBsdf> m_uniform_bsdf;  // untextured: one BSDF for every hit
};

}  // namespace

std::unique_ptr<Material> make_mirror_material(const Params& params, TextureTable& textures) {
    const SpectrumInput tint = textures.spectrum(params, "tint", Rgb(1.0f), 0.0f, 1.0f);
    return std::make_unique<MirrorMaterial>(tint);
}

}  // namespace glint
