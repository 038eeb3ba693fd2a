#pragma once
// glint's network denoiser: Open Image Denoise's trained U-Net ("RT" filter, HDR colour with
// albedo and normal), run by glint's own code on oneDNN. The weights are Intel's, published
// under Apache-2.0 and installed by scripts/install-deps.sh (docs/denoiser.md); nothing is
// downloaded at build or run time.
//
// The colour is scaled by autoexposure and mapped by the PU curve (denoise/transfer.h), the
// albedo clamped to [0, 1] and the normal mapped from [-1, 1] to [0, 1]; the network runs
// tile by tile (denoise/tiling.h) over the image extended by a mirrored border margin; its
// output is clamped to >= 0, mapped back and divided by the exposure. With clean_aux (always
// for High) the albedo and normal are first denoised by networks of their own, and the
// colour network trained on clean features is used, which keeps edges seen through glass,
// in defocus or in motion from being taken for noise.
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
    bool clean_aux = false;  ///< prefilter albedo and normal (implied by High)
    int threads = 1;         ///< OpenMP threads of the network; the result is the same for any
    /// Tile side in pixels (a multiple of 16 above 192): the memory bound. 1088 = 1024 plus
    /// the border margins on both sides, so that a 1024-pixel image is one tile.
    int max_tile = 1088;
    /// The image is extended by this many pixels on every side, mirrored (the edge pixel not
    /// repeated), before the network sees it; only the image's own pixels are kept. OIDN feeds
    /// zeros beyond the border instead (0 here does that), which the network takes for a dark
    /// edge: a noise-free image then comes back changed by up to 46 % within a few pixels of
    /// a corner, 1.6 % with a margin of 32.
    int border_margin = 32;
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

/// The tiles one network pass runs on an image of this size (with its margins).
int denoise_network_tiles(int width, int height, const NetworkDenoiseSettings& settings);

/// Bytes denoise_network() holds at its peak for an image of this size, besides the image
/// itself: the colour network for one tile (activations, weights, scratch), the tile's
/// planar input and output, and the whole image's features and result.
std::size_t denoise_network_memory(int width, int height, const NetworkDenoiseSettings& settings);

}  // namespace glint
