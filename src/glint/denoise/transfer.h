#pragma once
// The transforms between image values and what OIDN's networks were trained on.
//  - HDR colour is scaled by an exposure that brings the image's mean log luminance to a
//    middle grey (autoexposure), then mapped by the "perceptually uniform" (PU) curve: linear
//    near black, a power law, then logarithmic, normalised so that 65504 (the largest half
//    float) maps to 1. The network thus sees noise the way a viewer does across the range.
//  - Albedo (for the albedo prefilter) is mapped by the sRGB curve; normals from [-1, 1] to
//    [0, 1] linearly.
// The curve's coefficients are those OIDN's networks were trained with.
#include <glint/film/image.h>

namespace glint {

/// PU curve, normalised to [0, 1] over [0, 65504]; pu_inverse(pu_forward(y)) = y.
float pu_forward(float y);
float pu_inverse(float x);

/// The sRGB transfer curve, linear to encoded, in float as OIDN computes it; its inverse is
/// srgb_to_linear (film/image_io.h).
float srgb_forward(float y);

/// The scale that brings the image's channels 0..2 (linear RGB) to a mean log2 luminance
/// of log2(0.18): the luminance is averaged in bins of at most 16 x 16 pixels, and the bins
/// darker than 1e-8 are left out; 1 for an image with no such bin. Non-finite and negative
/// values count as 0.
float autoexposure(const Image& image);

}  // namespace glint
