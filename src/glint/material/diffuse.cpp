#include <glint/material/lambertian.h>
#include <glint/material/materials.h>

#include <optional>

namespace glint {
namespace {

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const SpectrumInput& reflectance) : m_reflectance(reflectance) {
        if (!reflectance.is_textured()) m_uniform_bsdf.emplace(reflectance.representative());
    }
    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        // The shared BSDF holds the RGB reflectance: spectral mode reads it at the path's
        // wavelengths instead.
        if (m_uniform_bsdf && !spectral_mode_active()) return &*m_uniform_bsdf;
        return arena.make<LambertianBsdf>(m_reflectance.eval(si));
    }
    Spectrum albedo(const SurfaceInteraction& si) const override { return m_reflectance.eval(si); }
    bool may_scatter_specularly() const override { return false; }

private:
    SpectrumInput m_reflectance;
    // Without a texture the BSDF is the same at every hit (it lives in the shading frame),
    // so it is built once and shared, read-only, by all threads.
    std::optional<LambertianBsdf> m_uniform_bsdf;
};

}  // namespace

std::unique_ptr<Material> make_diffuse_material(const Params& params, TextureTable& textures) {
    // In [0, 1] so the surface does not create energy.
    const SpectrumInput reflectance =
        textures.spectrum(params, "reflectance", Rgb(0.5f), 0.0f, 1.0f);
    return std::make_unique<DiffuseMaterial>(reflectance);
}

}  // namespace glint
