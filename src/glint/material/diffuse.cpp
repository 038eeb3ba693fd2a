#include <glint/material/lambertian.h>
#include <glint/material/materials.h>

namespace glint {
namespace {

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const SpectrumInput& reflectance) : m_reflectance(reflectance) {}
    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        return arena.make<LambertianBsdf>(m_reflectance.eval(si));
    }
    Spectrum albedo(const SurfaceInteraction& si) const override { return m_reflectance.eval(si); }

private:
    SpectrumInput m_reflectance;
};

}  // namespace

std::unique_ptr<Material> make_diffuse_material(const Params& params, TextureTable& textures) {
    // In [0, 1] so the surface does not create energy.
    const SpectrumInput reflectance =
        textures.spectrum(params, "reflectance", Spectrum(0.5f), 0.0f, 1.0f);
    return std::make_unique<DiffuseMaterial>(reflectance);
}

}  // namespace glint
