#pragma once
// Spatiotemporal variance-guided filtering (SVGF, Schied et al. 2017), the viewer's real-time
// denoiser: the temporally accumulated colour is demodulated by the albedo (so texture detail
// is not blurred away), filtered by five à-trous wavelet passes (5x5 B-spline kernel with
// holes 1, 2, 4, 8, 16 pixels apart) whose edge-stopping functions compare depth (relative to
// its local gradient), normals and luminance (relative to the luminance's standard deviation,
// itself estimated from the accumulated moments, or spatially for pixels with a short
// history), then remodulated. Applied in the viewer only: rendered images are never filtered
// unless the user asks for a denoiser (film/denoise.h, denoise/film_denoiser.h).
#include <glint/core/rgb.h>
#include <glint/math/vector.h>

#include <span>
#include <vector>

namespace glint {

struct SvgfSettings {
    int levels = 5;  ///< à-trous passes (hole 2^i at pass i)
    /// 2: the 5x5 B3-spline kernel of the paper; 1: a 3x3 kernel (A-SVGF's), about 2.5 times
    /// faster, a little less smooth.
    int kernel_radius = 2;
    float sigma_luminance = 4.0f;  ///< luminance stopping, in standard deviations
    float normal_power = 128.0f;   ///< normal stopping: max(0, n_p . n_q)^power
    float sigma_depth = 1.0f;      ///< depth stopping, in units of the local depth gradient
    /// Pixels with a shorter history estimate their variance from a 7x7 neighbourhood.
    float min_temporal_history = 4.0f;
    /// The à-trous taps eight pixels at a time (AVX2) where the processor can, else four
    /// (SSE2): the same bits either way; false only to test that.
    bool wide_lanes = true;
    /// Pixels whose taps all lie inside the image go through every tap at once, their sums
    /// in registers (with the power of 128): the same bits; false only to test that.
    bool blocked_taps = true;
};

/// One frame's inputs, one value per pixel, row-major, top row first.
struct SvgfInput {
    int width = 0, height = 0;
    std::span<const Rgb> colour;   ///< temporally accumulated linear radiance
    std::span<const Rgb> albedo;   ///< first-hit albedo (1 where there is nothing to demodulate)
    std::span<const Vec3> normal;  ///< first-hit world normal
    /// Distance along the camera ray; 0 where the ray escaped, or wherever the pixel is to
    /// pass through unfiltered and out of its neighbours' sums (the viewer's lamps).
    std::span<const float> depth;
    /// Accumulated means of the demodulated luminance Y and of Y^2 (moments()), and how many
    /// frames each pixel's accumulation holds.
    std::span<const Vec2> moments;
    std::span<const float> history_length;
};

/// The albedo a colour is divided by to demodulate it (and multiplied by again): the albedo,
/// with channels near zero taken as 1 (nothing to demodulate there).
Rgb svgf_demodulation(const Rgb& albedo);
/// The moments (Y, Y^2) of one frame's colour demodulated by `albedo`, for accumulation.
Vec2 svgf_moments(const Rgb& colour, const Rgb& albedo);

/// The filtered colour. Pixels whose ray escaped (depth 0) pass through unchanged and are
/// nobody's neighbour. Runs in parallel (TBB); the same result for any thread count. Throws
/// glint::Error when the inputs' sizes do not match width x height or the settings are out of
/// range.
std::vector<Rgb> svgf_filter(const SvgfInput& input, const SvgfSettings& settings = {});

}  // namespace glint
