#include <glint/material/materials.h>
#include <glint/material/registry.h>

#include <cmath>
#include <map>

namespace glint {
namespace {

using MaterialFactory = std::unique_ptr<Material> (*)(const Params&, TextureTable&);

struct MaterialRow {
    MaterialFactory make;
    const char* emission_key;  // the key of the light it emits; "" for none
};

const std::map<std::string, MaterialRow>& factories() {
    // One row per material, so that adding one is a one-line change.
    // clang-format off
    static const std::map<std::string, MaterialRow> table = {
        {"diffuse", {make_diffuse_material, ""}},
        {"mirror", {make_mirror_material, ""}},
        {"dielectric", {make_dielectric_material, ""}},
        {"emissive", {make_emissive_material, "radiance"}},
        {"phong", {make_phong_material, ""}},
        {"conductor", {make_conductor_material, ""}},
        {"plastic", {make_plastic_material, ""}},
        {"principled", {make_principled_material, ""}},
        {"interface", {make_interface_material, ""}},
    };
    // clang-format on
    return table;
}

// bump = texture, bump_scale = s; or normal_map = texture or file, normal_map_flip_y.
void read_perturbation(const Params& params, TextureTable& textures, Material& material) {
    const Texture* bump = textures.texture_or_file(params, "bump");
    const float bump_scale = params.get_float("bump_scale", 1.0f);
    const Texture* normal_map = textures.texture_or_file(params, "normal_map");
    const bool flip_y = params.get_bool("normal_map_flip_y", false);
    if (bump && normal_map) params.fail("give either 'bump' or 'normal_map', not both");
    if (!std::isfinite(bump_scale)) params.fail("'bump_scale' must be a finite number");
    if (bump) material.set_perturbation(NormalPerturbation::bump(bump, bump_scale));
    if (normal_map) material.set_perturbation(NormalPerturbation::normal_map(normal_map, flip_y));
}

}  // namespace

std::vector<std::string> material_types() {
    std::vector<std::string> names;
    for (const auto& [name, factory] : factories()) names.push_back(name);
    return names;
}

std::unique_ptr<Material> make_material(const Params& params, TextureTable& textures) {
    auto it = factories().find(params.type());
    if (it == factories().end()) params.fail("unknown material type");
    const size_t textures_before = textures.textures_handed_out();
    auto material = it->second.make(params, textures);
    material->set_uses_textures(textures.textures_handed_out() != textures_before);
    read_perturbation(params, textures, *material);
    params.check_all_used();
    return material;
}

std::string material_emission_key(const std::string& type) {
    auto it = factories().find(type);
    return it == factories().end() ? "" : it->second.emission_key;
}

}  // namespace glint
