#include <glint/material/materials.h>
#include <glint/material/registry.h>

#include <map>

namespace glint {
namespace {

using MaterialFactory = std::unique_ptr<Material> (*)(const Params&);

const std::map<std::string, MaterialFactory>& factories() {
    static const std::map<std::string, MaterialFactory> table = {
        {"diffuse", make_diffuse_material},
        {"mirror", make_mirror_material},
        {"dielectric", make_dielectric_material},
        {"emissive", make_emissive_material},
        {"phong", make_phong_material},
    };
    return table;
}

}  // namespace

std::vector<std::string> material_types() {
    std::vector<std::string> names;
    for (const auto& [name, factory] : factories()) names.push_back(name);
    return names;
}

std::unique_ptr<Material> make_material(const Params& params) {
    auto it = factories().find(params.type());
    if (it == factories().end()) params.fail("unknown material type");
    auto material = it->second(params);
    params.check_all_used();
    return material;
}

}  // namespace glint
