#pragma once
// How to render: resolution, sampling, integrator and outputs. Filled from the script's
// glint.render{...} and then overridden by command-line flags.
#include <glint/core/params.h>
#include <glint/core/spectrum.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

struct RenderSettings {
    int width = 512;
    int height = 512;
    int spp = 64;
    uint64_t seed = 0;
    int max_depth = -1;  // bounces; -1 = unlimited (Russian roulette ends paths)
    std::string integrator = "path";
    std::string sampler = "sobol";
    std::string filter = "box";
    float filter_radius = 0.0f;  // 0 = the filter's default
    float exposure = 0.0f;       // stops, applied to PNG output
    bool aovs = false;           // albedo/normal/depth channels in EXR output
    std::vector<std::string> outputs;
    int threads = 0;            // 0 = all cores
    bool csg_shortcuts = true;  // bounding-box pruning inside CSG trees
    bool mipmapping = true;     // image textures filtered from mipmaps (false: full level only)

    // Classic ray tracing ("whitted").
    Spectrum ambient{0.0f};          // ambient light, times the surface albedo
    int shadow_samples = 4;          // N: area lights get N x N stratified shadow rays
    bool penumbra_shortcut = false;  // test 4 rays first; full set only in the penumbra
    bool caustics = false;           // add photon-mapped caustics (caustic_photons, photon_neighbours)

    // Photon mapping ("photon", "sppm"). For sppm, spp is the number of passes.
    int photons = 100000;          // photons per pass (sppm) or in the global map (photon)
    int caustic_photons = 100000;  // photons in the caustic map (photon)
    float photon_radius = 0.0f;    // sppm initial radius; 0 = 1/256 of the scene's size
    int intermediate = 0;          // sppm: also write the image every N passes (0 = never)
    int photon_neighbours = 50;    // photon: photons per radiance estimate
    int gather_rays = 16;          // photon: final-gathering rays per visible point
    bool projection_maps = true;   // photon: aim caustic photons at specular objects

    // Adaptive sampling, for every tile integrator.
    std::string adaptive = "none";  // "none", "sobel" (edge supersampling), "variance"
    float edge_threshold = 0.03f;   // sobel: gradient of tone-mapped luminance marking an edge
    int edge_radius = 1;            // sobel: dilation of the edge mask, in pixels
    int supersample = 4;            // sobel: edge pixels get N x N samples
    float target_error = 0.02f;     // variance: stop when the relative error falls below
    int max_spp = 0;                // variance: cap per pixel (0 = 8 x spp)
    std::vector<std::string> debug; // "edges": also write the edge mask
    // Where the integrator, sampler and filter names came from, for error messages.
    std::string where = "render settings";
};

RenderSettings parse_render_settings(const Params* params);

}  // namespace glint
