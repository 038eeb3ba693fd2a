#pragma once
// glint's network denoiser: Open Image Denoise's trained U-Net ("RT" filter, HDR colour with
// albedo and normal), run by glint's own code on oneDNN. The weights are Intel's, published
// under Apache-2.0 and installed by scripts/install-deps.sh (docs/denoiser.md); nothing is
// downloaded at build or run time.
//
// The colour is scaled by autoexposure and mapped by the PU curve (denoise/transfer.h), the
// albedo clamped to [0, 1] and the normal mapped from [-1, 1] to [0, 1]; the network runs
// tile by tile (denoise/tiling.h); its output is clamped to >= 0, mapped back and divided by
// the exposure. With clean_aux (always for High) the albedo and normal are first denoised by
// networks of their own, and the colour network trained on clean features is used, which
// keeps edges seen through glass, in defocus or in motion from being taken for noise.
#include <glint/film/image.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// The network size: small ("fast", about 3x quicker), default ("balanced"), large ("high",
/// about 4x slower; it needs clean features, so it prefilters them).
enum class DenoiseQuality { Fast, Balanced, High };

/// "fast", "balanced" or "high"; nullopt for anything else.
std::optional<DenoiseQuality> parse_denoise_quality(const std::string& name);

struct NetworkDenoiseSettings {
    DenoiseQuality quality = DenoiseQuality::Balanced;
    bool clean_aux = false;   ///< prefilter albedo and normal (implied by High)
    int threads = 1;          ///< OpenMP threads of the network; the result is the same for any
    int max_tile = 1024;      ///< tile side in pixels (a multiple of 16 above 192): memory bound
    std::string weights_dir;  ///< empty: denoise_weights_dir()
    /// Called after each tile of each network pass with (done, total) passes.
    std::function<void(int, int)> on_progress;
};

/// Where the weights are: $GLINT_DENOISE_WEIGHTS if set, else the directory CMake compiled
/// in (GLINT_DENOISE_WEIGHTS_DIR, /usr/local/share/glint/denoise by default).
std::string denoise_weights_dir();

/// The weight files `settings` uses, as paths.
std::vector<std::string> denoise_weight_files(const NetworkDenoiseSettings& settings);

/// Throws glint::Error naming the first missing weight file and the install step; call it
/// before rendering, so that a long render does not end in this error.
void check_denoise_weights(const NetworkDenoiseSettings& settings);

/// Denoises a film's resolve() with AOVs (channels R, G, B, albedo.R/G/B, normal.X/Y/Z);
/// returns R, G, B of the same size. Throws glint::Error when a channel or a weight file is
/// missing or a weight file is not valid.
Image denoise_network(const Image& image, const NetworkDenoiseSettings& settings);

/// Bytes denoise_network() holds at its peak for an image of this size, besides the image
/// itself: the colour network for one tile (activations, weights, scratch), the tile's
/// planar input and output, and the whole image's features and result.
std::size_t denoise_network_memory(int width, int height, const NetworkDenoiseSettings& settings);

}  // namespace glint
