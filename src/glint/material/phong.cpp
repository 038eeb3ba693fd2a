#include <glint/material/blinn_phong.h>
#include <glint/material/materials.h>
#include <glint/material/phong.h>

namespace glint {
namespace {

class PhongMaterial final : public Material {
public:
    PhongMaterial(const SpectrumInput& diffuse, const SpectrumInput& specular, float exponent,
                  bool blinn)
        : m_diffuse(diffuse), m_specular(specular), m_exponent(exponent), m_blinn(blinn) {}
    const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const override {
        // A textured diffuse colour is cut where kd + ks would exceed 1.
        Spectrum kd = m_diffuse.eval(si);
        const Spectrum ks = m_specular.eval(si);
        kd = min(kd, Spectrum(1.0f) - ks);
        if (m_blinn) return arena.make<BlinnPhongBsdf>(kd, ks, m_exponent);
        return arena.make<PhongBsdf>(kd, ks, m_exponent);
    }
    Spectrum albedo(const SurfaceInteraction& si) const override {
        return m_diffuse.eval(si) + m_specular.eval(si);
    }

private:
    SpectrumInput m_diffuse;
    SpectrumInput m_specular;
    float m_exponent;
    bool m_blinn;
};

}  // namespace

// glint.phong{...}: a diffuse term plus a glossy lobe, kd + ks <= 1.
//   model     string               "phong"  "phong": cos^n about the mirror direction
//                                            (phong.h); "blinn": cos^n of the half-vector
//                                            angle (blinn_phong.h)
//   diffuse   spectrum or texture  0.5      in [0, 1]
//   specular  spectrum             0.2      in [0, 1]
//   exponent  float                50       in [0, 100000]
std::unique_ptr<Material> make_phong_material(const Params& params, TextureTable& textures) {
    const std::string model = params.get_string("model", "phong");
    if (model != "phong" && model != "blinn") {
        params.fail("unknown 'model' '" + model + "'; known models: 'phong', 'blinn'");
    }
    const SpectrumInput diffuse = textures.spectrum(params, "diffuse", Rgb(0.5f), 0.0f, 1.0f);
    const SpectrumInput specular = textures.spectrum(params, "specular", Rgb(0.2f), 0.0f, 1.0f);
    const float exponent = params.get_float("exponent", 50.0f);
    if (specular.is_textured()) params.fail("'specular' cannot be a texture; 'diffuse' can");
    const Spectrum total = diffuse.representative() * (diffuse.is_textured() ? 0.0f : 1.0f) +
                           specular.representative();
    if (total.max_value() > 1.0f) {
        params.fail(
            "'diffuse' + 'specular' must not exceed 1 in any channel, or the surface would create "
            "energy");
    }
    if (!(exponent >= 0.0f && exponent <= 1e5f)) params.fail("'exponent' must be in [0, 100000]");
    return std::make_unique<PhongMaterial>(diffuse, specular, exponent, model == "blinn");
}

}  // namespace glint
