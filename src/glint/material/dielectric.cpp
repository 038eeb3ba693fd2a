#include <glint/material/materials.h>
#include <glint/material/smooth_dielectric.h>

namespace glint {
namespace {

class DielectricMaterial final : public Material {
public:
    DielectricMaterial(float ior, const Spectrum& absorption)
        : m_ior(ior), m_absorption(absorption) {}
    const Bsdf* bsdf(const SurfaceInteraction&, Arena& arena) const override {
        return arena.make<SmoothDielectricBsdf>(m_ior);
    }
    Spectrum albedo(const SurfaceInteraction&) const override { return Spectrum(1.0f); }
    Spectrum interior_absorption() const override { return m_absorption; }

private:
    float m_ior;
    Spectrum m_absorption;
};

}  // namespace

std::unique_ptr<Material> make_dielectric_material(const Params& params, TextureTable&) {
    const float ior = params.get_float("ior", 1.5f);
    if (!(ior > 0.0f)) params.fail("'ior' must be positive");
    const Spectrum absorption = params.get_spectrum("absorption", Spectrum(0.0f));
    if (std::min({absorption.r, absorption.g, absorption.b}) < 0.0f) {
        params.fail("'absorption' must not be negative");
    }
    return std::make_unique<DielectricMaterial>(ior, absorption);
}

}  // namespace glint
