#include <glint/material/materials.h>
#include <glint/material/specular_reflection.h>

namespace glint {
namespace {

class MirrorMaterial final : public Material {
public:
    explicit MirrorMaterial(const Spectrum& tint) : m_tint(tint) {}
    const Bsdf* bsdf(const SurfaceInteraction&, Arena& arena) const override {
        return arena.make<SpecularReflectionBsdf>(m_tint);
    }
    Spectrum albedo(const SurfaceInteraction&) const override { return m_tint; }

private:
    Spectrum m_tint;
};

}  // namespace

std::unique_ptr<Material> make_mirror_material(const Params& params) {
    const Spectrum tint = params.get_spectrum("tint", Spectrum(1.0f));
    if (tint.max_value() > 1.0f || std::min({tint.r, tint.g, tint.b}) < 0.0f) {
        params.fail("'tint' must lie in [0, 1]");
    }
    return std::make_unique<MirrorMaterial>(tint);
}

}  // namespace glint
