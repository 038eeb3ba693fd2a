#pragma once
// What the denoisers' tests measure on rendered images: a render with its two halves, the
// error against a converged reference with the reference's own noise taken off, and the
// edge bands and their contrast. Shared by the non-local means filter's tests
// (tests/integrator/test_denoise.cpp) and the network's (tests/denoise/).
#include <glint/film/image.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint::test {

// A render's whole image (with AOVs) and its two halves.
struct Halves {
    Image full, a, b;
};

// Renders scene `code` (relative paths from examples/) into a film with AOVs and halves;
// `threads` 0 uses all.
Halves render_halves(const std::string& code, int threads = 0);

float luminance(const Image& image, int x, int y);

// The relative MSE of `test` (glint compare's: (t - r)^2 / (r^2 + 0.01)) against the
// converged image, over the pixels of `mask` (all when null). The reference is a render
// too: its own noise, estimated per pixel from its halves as (a - b)^2 / 4, is taken off,
// so that the figure is the test image's error, not the reference's.
double error_against(const Image& test, const Halves& ref,
                     const std::vector<uint8_t>* mask = nullptr);

// Edge bands from the reference's features: geometry edges where the shading normal turns
// by more than 30 degrees or the depth jumps by more than 10 % between 4-neighbours;
// texture edges where only the albedo changes (by more than 0.15 in RGB length).
struct EdgeBands {
    std::vector<uint8_t> geometry, texture;
};
EdgeBands edge_bands(const Image& ref);

// Mean over the band of the largest luminance step from a pixel to a 4-neighbour: the
// edge's contrast, which blurring lowers.
double edge_contrast(const Image& image, const std::vector<uint8_t>& band);

int band_size(const std::vector<uint8_t>& band);

}  // namespace glint::test
