#include <glint/material/lambertian.h>
#include <glint/material/materials.h>

namespace glint {
namespace {

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const Spectrum& reflectance) : m_reflectance(reflectance) {}
    const Bsdf* bsdf(const SurfaceInteraction&, Arena& arena) const override {
        return arena.make<LambertianBsdf>(m_reflectance);
    }
    Spectrum albedo(const SurfaceInteraction&) const override { return m_reflectance; }

private:
    Spectrum m_reflectance;
};

}  // namespace

std::unique_ptr<Material> make_diffuse_material(const Params& params) {
    const Spectrum reflectance = params.get_spectrum("reflectance", Spectrum(0.5f));
    if (reflectance.max_value() > 1.0f ||
        std::min({reflectance.r, reflectance.g, reflectance.b}) < 0.0f) {
        params.fail("'reflectance' must lie in [0, 1] so the surface does not create energy");
    }
    return std::make_unique<DiffuseMaterial>(reflectance);
}

}  // namespace glint
