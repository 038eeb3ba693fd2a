#pragma once
// How to render: the settings every integrator shares (resolution, sampling, filter,
// outputs, adaptive sampling, max_depth). Filled from the script's glint.render{...}, with
// command-line flags written into that table first (each with its own location).
// Settings of one integrator (whitted's shadow_samples, the photon counts, ...) are read by
// that integrator's create() from `params`; see integrator/registry.cpp.
#include <glint/core/params.h>
#include <glint/core/spectrum.h>
#include <glint/film/tonemap.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glint {

/// The longest path any integrator follows, in bounces: `max_depth` may not exceed it, and
/// `max_depth = -1` ("until Russian roulette ends the path") stops there too, so that a path
/// trapped between lossless mirrors, where roulette never fires, still ends.
inline constexpr int kMaxPathDepth = 1024;

struct RenderSettings {
    int width = 512;
    int height = 512;
    int spp = 64;
    uint64_t seed = 0;
    int max_depth = -1;  // bounces; -1 = until Russian roulette ends paths (at most 1024)
    std::string integrator = "path";
    std::string sampler = "sobol";
    std::string filter = "box";
    float filter_radius = 0.0f;       // 0 = the filter's default
    float exposure = 0.0f;            // stops, applied to PNG output
    Tonemap tonemap = Tonemap::clip;  // display curve of PNG output (film/tonemap.h)
    bool aovs = false;                // albedo/normal/depth channels in EXR output
    // Spectral mode: paths carry four wavelengths (hero wavelength sampling) instead of RGB,
    // the film turns them into colour (integrator/transport/spectral_model.h).
    bool spectral = false;
    bool denoise = false;  // also write NAME.denoised.EXT
    // Which denoiser: "network" (OIDN's trained U-Net, denoise/network_denoiser.h) or "nlm"
    // (glint's non-local means filter, film/denoise.h).
    std::string denoiser = "network";
    std::string denoise_quality = "balanced";  // network: "fast", "balanced" or "high"
    bool denoise_clean_aux = false;            // network: prefilter albedo and normal first
    std::vector<std::string> outputs;
    int threads = 0;            // 0 = all cores
    bool csg_shortcuts = true;  // bounding-box pruning inside CSG trees
    bool mipmapping = true;     // image textures filtered from mipmaps (false: full level only)
    // How next-event estimation chooses a light: "tree" (a light BVH, by each light's
    // estimated contribution at the receiving point) or "power" (by emitted power alone).
    std::string light_sampler = "tree";

    // Adaptive sampling, for every tile integrator.
    std::string adaptive = "none";   // "none", "sobel" (edge supersampling), "variance"
    float edge_threshold = 0.03f;    // sobel: gradient of tone-mapped luminance marking an edge
    int edge_radius = 1;             // sobel: dilation of the edge mask, in pixels
    int supersample = 4;             // sobel: edge pixels get N x N samples
    float target_error = 0.02f;      // variance: stop when the relative error falls below
    int max_spp = 0;                 // variance: cap per pixel (0 = 8 x spp)
    std::vector<std::string> debug;  // "edges": also write the edge mask

    // Crop window {x0, y0, x1, y1}: render only pixels [x0, x1) x [y0, y1) of the
    // width x height image, and output just those (an image of the window's size). Each
    // of its pixels is bit for bit the full render's. Empty (all 0) = the whole image.
    std::array<int, 4> crop{0, 0, 0, 0};
    bool has_crop() const { return crop[2] > 0; }
    /// The output image's size and its top-left pixel in the full image: the crop window,
    /// or the whole image.
    int output_width() const { return has_crop() ? crop[2] - crop[0] : width; }
    int output_height() const { return has_crop() ? crop[3] - crop[1] : height; }
    Vec2i output_origin() const { return has_crop() ? Vec2i(crop[0], crop[1]) : Vec2i(0, 0); }

    // The glint.render{...} table with the flags' values in it. Records which keys the
    // common settings read; integrators read their own keys from a copy.
    Params params{"render", "render settings"};

    /// How display (PNG) outputs map radiance: the tone curve and the exposure.
    ToneMapping tone_mapping() const { return {tonemap, exposure}; }

    /// Bounces a path may take: max_depth, or kMaxPathDepth when it is -1.
    int depth_limit() const { return max_depth >= 0 ? max_depth : kMaxPathDepth; }

    /// Where the value of setting `key` came from, for error messages: a flag such as
    /// "--integrator", or the scene's "file:line" of its glint.render{...}.
    const std::string& where_of(const std::string& key) const { return params.where_of(key); }
};

/// Reads the common settings from `params` (the glint.render{...} table, or null for all
/// defaults) and validates them; throws glint::Error naming the key's location. Keys it
/// does not know are left for the integrator: make_integrator() reports them.
RenderSettings parse_render_settings(const Params* params);

}  // namespace glint
