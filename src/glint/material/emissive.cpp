#include <glint/material/materials.h>
#include <glint/spectral/emission_params.h>

namespace glint {
namespace {

// A light source surface: emits, does not reflect.
class EmissiveMaterial final : public Material {
public:
    EmissiveMaterial(const SceneColor& radiance, bool two_sided)
        : m_radiance(radiance), m_two_sided(two_sided) {}
    const Bsdf* bsdf(const SurfaceInteraction&, Arena&) const override { return nullptr; }
    SceneColor emission() const override { return m_radiance; }
    bool emits_two_sided() const override { return m_two_sided; }
    bool may_scatter_specularly() const override { return false; }

private:
    SceneColor m_radiance;
    bool m_two_sided;
};

}  // namespace

std::unique_ptr<Material> make_emissive_material(const Params& params, TextureTable&) {
    // `radiance` may be shaped by `blackbody = T` or `spectrum = ...` (emission_params.h).
    return std::make_unique<EmissiveMaterial>(spectral::read_emission_color(params, "radiance"),
                                              params.get_bool("two_sided", false));
}

}  // namespace glint
