#pragma once
// glint.texture.wood: concentric growth rings around the pattern's y axis, made irregular
// by fractal noise, in object space.
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>

#include <memory>

namespace glint {

class TextureTable;

std::unique_ptr<Texture> make_wood_texture(const Params& params, TextureTable& table);

}  // namespace glint
