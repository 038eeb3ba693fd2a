#pragma once
// Scene-language names of the materials. A new material is one file plus one line here.
#include <glint/core/params.h>
#include <glint/material/material.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

std::vector<std::string> material_types();
// Builds the material named by params.type(); throws glint::Error for unknown names.
std::unique_ptr<Material> make_material(const Params& params);

}  // namespace glint
