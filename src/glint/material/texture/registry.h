#pragma once
// Scene-language names of the textures (glint.texture.<name>{...}). A new texture is one
// file plus one line in registry.cpp.
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>
#include <glint/material/texture/texture_table.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

std::vector<std::string> texture_types();
// Builds the texture named by params.type(); throws glint::Error for unknown names.
std::unique_ptr<Texture> make_texture(const Params& params, TextureTable& table);

}  // namespace glint
