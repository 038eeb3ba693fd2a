#pragma once
// A feature-guided denoiser of glint's own: non-local means on two half buffers, guided by
// the first-hit features (albedo, normal, depth) the film records.
//
// The film keeps two independent halves of each pixel's samples (even and odd sample
// indices, Film::has_halves()). Their difference estimates each pixel's variance, and
// each half is filtered with weights computed from the other half, so that a pixel's
// noise does not choose its own weights (the dual-buffer scheme of Rousselle, Manzi and
// Zwicker 2012, "Adaptive rendering with non-local means filtering", and of Bitterli et
// al. 2016, "Nonlinearly weighted first-order regression for denoising Monte Carlo
// renderings"). Before filtering:
//  - radiance is divided by the surface albedo ("demodulation"), so that texture detail
//    is never averaged away: the filter smooths illumination, and the albedo is
//    multiplied back afterwards;
//  - fireflies are clamped: a half's pixel more than 1.5 times as bright as every one of
//    its 16 neighbours in the two halves (3 x 3 windows, the pixel itself left out) is
//    scaled down to the brightest of them, and one more than 1.5 times as bright as the
//    other half's 3 x 3 window (its own pixel included) down to 1.5 times that.
// The weight of neighbour q for pixel p is the product of a colour weight (the patch
// distance of non-local means, with each pixel's variance subtracted, so that noise alone
// does not make two patches look different) and one weight per feature (albedo, normal,
// relative depth), each relaxed by that feature's own variance between the halves (a
// feature that is noisy, at an antialiased edge or out of focus, guides less).
#include <glint/film/image.h>

namespace glint {

class Film;

/// The denoiser's parameters; the defaults are what `--denoise` uses.
struct DenoiseSettings {
    int radius = 7;                ///< search window: (2 radius + 1)^2 neighbours, pixels
    int patch_radius = 2;          ///< colour patches of (2 patch_radius + 1)^2 pixels
    float color_strength = 0.45f;  ///< k of the colour weight: larger smooths more
    /// Feature differences that weigh a neighbour by 1/e (beyond the features' own noise):
    float albedo_sigma = 0.05f;  ///< albedo, length of the RGB difference
    float normal_sigma = 0.1f;   ///< shading normal, length of the difference
    float depth_sigma = 0.05f;   ///< depth, relative to the pixel's depth
    bool clamp_fireflies = true;
};

/// Denoises a render from its two halves. `half_a` and `half_b` are Film::resolve_half(0)
/// and (1) of a film with AOVs; `full` is its resolve() (for the albedo that remodulates
/// the result). Returns an image with channels R, G, B of the same size. Parallel over
/// rows with TBB; each output pixel depends only on the inputs, so the result is the same
/// bit for bit for any thread count. Throws glint::Error when the images differ in size or
/// lack the R, G, B, albedo, normal or depth channels, or a setting is out of range.
Image denoise(const Image& full, const Image& half_a, const Image& half_b,
              const DenoiseSettings& settings = {});

/// denoise() of a film's resolve() and two halves; throws glint::Error unless the film
/// has halves and AOVs.
Image denoise(const Film& film, const DenoiseSettings& settings = {});

}  // namespace glint
