#pragma once
// The concrete materials. Each has a factory taking checked Params (and the scene's
// textures, for parameters that may be textured); registry.cpp maps
// scene-language names to these factories.
#include <glint/core/params.h>
#include <glint/material/material.h>
#include <glint/material/texture/texture_table.h>

#include <memory>

namespace glint {

std::unique_ptr<Material> make_diffuse_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_mirror_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_dielectric_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_emissive_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_phong_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_conductor_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_plastic_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_principled_material(const Params& params, TextureTable& textures);
std::unique_ptr<Material> make_interface_material(const Params& params, TextureTable& textures);

}  // namespace glint
