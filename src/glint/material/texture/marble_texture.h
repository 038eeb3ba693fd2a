#pragma once
// glint.texture.marble: veins from a sine wave across x whose phase is disturbed by
// turbulence (Perlin 1985), in object space.
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>

#include <memory>

namespace glint {

class TextureTable;

std::unique_ptr<Texture> make_marble_texture(const Params& params, TextureTable& table);

}  // namespace glint
