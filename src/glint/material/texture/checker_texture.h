#pragma once
// glint.texture.checker: alternating squares of two colours, on the surface through a 2D
// mapping (box-filtered over the pixel footprint, so it does not alias), or cubes in
// object space (dimension = 3).
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>

#include <memory>

namespace glint {

class TextureTable;

// The fraction of [x - half_width, x + half_width] covered by "odd" unit cells (those
// with floor(x) odd), from the closed-form integral of that square wave; the point value
// (0 or 1) when half_width is 0.
float checker_odd_fraction(float x, float half_width);

std::unique_ptr<Texture> make_checker_texture(const Params& params, TextureTable& table);

}  // namespace glint
