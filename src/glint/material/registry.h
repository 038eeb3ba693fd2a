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

/// The key of the light a material of `type` emits (a spectrum that defaults to 1), empty
/// for a material that emits none: what makes a shape an area light, for an editor.
std::string material_emission_key(const std::string& type);
// Builds the material named by params.type(), with the bump or normal map every material
// accepts; throws glint::Error for unknown names.
std::unique_ptr<Material> make_material(const Params& params, TextureTable& textures);

}  // namespace glint
