#pragma once
// Parameters shared by the procedural textures (checker, noise, fbm, turbulence, wood,
// marble), read and checked in one place so that every texture reports them alike.
#include <glint/core/params.h>

namespace glint {

// A colour: a number (grey) or {r, g, b}, every channel >= 0 (values above 1 are allowed,
// e.g. for an emitter's radiance).
Rgb read_colour(const Params& params, const std::string& name, const Rgb& fallback);
// A number > 0.
float read_positive(const Params& params, const std::string& name, float fallback);
// A number >= 0.
float read_non_negative(const Params& params, const std::string& name, float fallback);

// Octaves of a fractal sum (noise.h): `octaves` (1 to kMaxOctaves), `lacunarity` (the
// frequency ratio between octaves, > 0, default 2) and `gain` (the weight ratio, >= 0,
// default 0.5).
struct FractalSettings {
    int octaves = 6;
    float lacunarity = 2.0f;
    float gain = 0.5f;
};
// Beyond 16 octaves the finest one is 65536 times finer than the first: below float
// precision for any useful scale, and only slower.
inline constexpr int kMaxOctaves = 16;
FractalSettings read_fractal_settings(const Params& params, int default_octaves);

}  // namespace glint
