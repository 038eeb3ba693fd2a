#pragma once
// The concrete materials. Each has a factory taking checked Params; registry.cpp maps
// scene-language names to these factories.
#include <glint/core/params.h>
#include <glint/material/material.h>

#include <memory>

namespace glint {

std::unique_ptr<Material> make_diffuse_material(const Params& params);
std::unique_ptr<Material> make_mirror_material(const Params& params);
std::unique_ptr<Material> make_dielectric_material(const Params& params);
std::unique_ptr<Material> make_emissive_material(const Params& params);
std::unique_ptr<Material> make_phong_material(const Params& params);

}  // namespace glint
