#include <glint/material/materials.h>
#include <glint/material/phong.h>

namespace glint {
namespace {

class PhongMaterial final : public Material {
public:
    PhongMaterial(const Spectrum& diffuse, const Spectrum& specular, float exponent)
        : m_diffuse(diffuse), m_specular(specular), m_exponent(exponent) {}
    const Bsdf* bsdf(const SurfaceInteraction&, Arena& arena) const override {
        return arena.make<PhongBsdf>(m_diffuse, m_specular, m_exponent);
    }
    Spectrum albedo(const SurfaceInteraction&) const override { return m_diffuse + m_specular; }

private:
    Spectrum m_diffuse;
    Spectrum m_specular;
    float m_exponent;
};

}  // namespace

std::unique_ptr<Material> make_phong_material(const Params& params) {
    const Spectrum diffuse = params.get_spectrum("diffuse", Spectrum(0.5f));
    const Spectrum specular = params.get_spectrum("specular", Spectrum(0.2f));
    const float exponent = params.get_float("exponent", 50.0f);
    const Spectrum total = diffuse + specular;
    if (std::min({diffuse.r, diffuse.g, diffuse.b, specular.r, specular.g, specular.b}) < 0.0f) {
        params.fail("'diffuse' and 'specular' must not be negative");
    }
    if (total.max_value() > 1.0f) {
        params.fail("'diffuse' + 'specular' must not exceed 1 in any channel, or the surface would create energy");
    }
    if (!(exponent >= 0.0f && exponent <= 1e5f)) params.fail("'exponent' must be in [0, 100000]");
    return std::make_unique<PhongMaterial>(diffuse, specular, exponent);
}

}  // namespace glint
