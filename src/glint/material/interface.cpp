#include <glint/material/materials.h>
#include <glint/material/smooth_dielectric.h>

namespace glint {
namespace {

// A surface that only bounds media: it neither reflects nor bends light. Scene::intersect
// passes through it, so walks never stop there, and so do shadow rays
// (transport/visibility.h). Its BSDF, an index-matched smooth interface (eta = 1: Fresnel
// reflectance 0, the direction unchanged), serves only code that meets it through the
// acceleration structure directly.
class InterfaceMaterial final : public Material {
public:
    const Bsdf* bsdf(const SurfaceInteraction&, Arena& arena) const override {
        return arena.make<SmoothDielectricBsdf>(1.0f);
    }
    bool is_interface() const override { return true; }
};

}  // namespace

// glint.interface{}: no parameters; media attach to it in the media issue.
std::unique_ptr<Material> make_interface_material(const Params&, TextureTable&) {
    return std::make_unique<InterfaceMaterial>();
}

}  // namespace glint
