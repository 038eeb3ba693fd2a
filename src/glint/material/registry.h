#pragma once
// Scene-language names of the materials. A new material is one file plus one line here.
#include <glint/core/params.h>
#include <glint/material/material.h>
#include <glint/material/texture/texture_table.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

std::vector<std::string> material_types();
// Builds the material named by params.type(), with the bump or normal map every material
// accepts; throws glint::Error for unknown names.
std::unique_ptr<Material> make_material(const Params& params, TextureTable& textures);

}  // namespace glint
