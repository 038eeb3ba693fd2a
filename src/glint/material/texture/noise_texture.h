#pragma once
// glint.texture.noise, glint.texture.fbm and glint.texture.turbulence: solid textures of
// Perlin noise (noise.h) in object space, coloured between `low` and `high`. As a scalar
// (bump, roughness) they give the raw pattern value.
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>

#include <memory>

namespace glint {

class TextureTable;

std::unique_ptr<Texture> make_noise_texture(const Params& params, TextureTable& table);
std::unique_ptr<Texture> make_fbm_texture(const Params& params, TextureTable& table);
std::unique_ptr<Texture> make_turbulence_texture(const Params& params, TextureTable& table);

}  // namespace glint
