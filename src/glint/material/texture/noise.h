#pragma once
// Ken Perlin's improved gradient noise (SIGGRAPH 2002) and the fractal sums built on it.
//
// Guarantees, for every finite point p (measured and derived in noise.cpp and checked by
// tests/material/test_textures_procedural.cpp):
//   perlin_noise(p)      in [-kNoiseBound, kNoiseBound]; exactly 0 at integer lattice points;
//                        Lipschitz: |n(p) - n(q)| <= kNoiseLipschitz * |p - q|;
//                        periodic with period 256 along each axis.
//   fbm(p, ...)          in [-kNoiseBound, kNoiseBound] (a weighted mean of noise values);
//   turbulence(p, ...)   in [0, kNoiseBound] (a weighted mean of |noise| values).
// Everything is a pure function of its arguments: deterministic, thread-safe, and free of
// global mutable state. Coordinates beyond about 2^23 lose their fractional part (float);
// non-finite ones give 0.
#include <glint/math/vector.h>

namespace glint {

// A safe bound of |perlin_noise|: the worst case over every choice of corner gradients is
// 1.03635 (derived in noise.cpp); 1.04 leaves a margin for float rounding. Perlin's table
// itself reaches about 0.997.
inline constexpr float kNoiseBound = 1.04f;
// The largest slope |grad perlin_noise| over every choice of corner gradients: 2 * 15/8,
// reached at a cell centre along an axis (derived in noise.cpp). Perlin's table reaches
// 3.567, at (241.4665, 233.4995, 151.4789).
inline constexpr float kNoiseLipschitz = 3.75f;

// Improved Perlin noise: quintic fade 6t^5 - 15t^4 + 10t^3, gradients from the 12 edge
// directions of a cube, cells hashed with Perlin's fixed permutation of 256.
float perlin_noise(const Vec3& p);

// Fractional Brownian motion: octaves i = 0 .. octaves-1 of noise at frequency
// lacunarity^i with weight gain^i, divided by the sum of the weights, so that the range
// does not depend on octaves or gain. Requires octaves >= 1, gain >= 0.
float fbm(const Vec3& p, int octaves, float lacunarity = 2.0f, float gain = 0.5f);

// As fbm, but summing |noise|: a pattern with creases where the noise changes sign
// (Perlin's "turbulence"), in [0, kNoiseBound].
float turbulence(const Vec3& p, int octaves, float lacunarity = 2.0f, float gain = 0.5f);

}  // namespace glint
