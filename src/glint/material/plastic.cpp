#include <glint/material/materials.h>
#include <glint/material/plastic.h>

namespace glint {
namespace {

class PlasticMaterial final : public Material {
public:
    // The coat's albedo table covers every alpha the roughness can take: one value for a
    // constant, the whole range of a texture (clamped to [0, 1]).
    PlasticMaterial(const SpectrumInput& diffuse, float ior, const FloatInput& roughness)
        : m_diffuse(diffuse),
          m_roughness(roughness),
          m_coat_albedo(ior, roughness.is_textured() ? 0.0f : alpha(roughness.representative()),
                        roughness.is_textured() ? 1.0f : alpha(roughness.representative())) {}

    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        const GgxDistribution coat(alpha(m_roughness.eval(si)));
        return arena.make<PlasticBsdf>(m_diffuse.eval(si), coat, m_coat_albedo);
    }
    Spectrum albedo(const SurfaceInteraction& si) const override { return m_diffuse.eval(si); }

private:
    static float alpha(float roughness) { return roughness_to_alpha(roughness); }

    SpectrumInput m_diffuse;
    FloatInput m_roughness;
    CoatAlbedoTable m_coat_albedo;
};

}  // namespace

// glint.plastic{...}: a diffuse base under a clear dielectric coat (plastic.h).
//   diffuse    spectrum or texture  0.5  in [0, 1], the base's reflectance
//   ior        float                1.5  the coat's index of refraction, in [1, 10]
//   roughness  float or texture     0.1  in [0, 1], of the coat; alpha = roughness^2, 0 is
//                                         a smooth (delta) coat
std::unique_ptr<Material> make_plastic_material(const Params& params, TextureTable& textures) {
    const SpectrumInput diffuse = textures.spectrum(params, "diffuse", Rgb(0.5f), 0.0f, 1.0f);
    const float ior = params.get_float("ior", 1.5f);
    if (!(ior >= 1.0f && ior <= 10.0f)) params.fail("'ior' must lie in [1, 10]");
    const FloatInput roughness = textures.scalar(params, "roughness", 0.1f, 0.0f, 1.0f);
    return std::make_unique<PlasticMaterial>(diffuse, ior, roughness);
}

}  // namespace glint
