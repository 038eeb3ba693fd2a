#pragma once
// How to render: resolution, sampling, integrator and outputs. Filled from the script's
// glint.render{...} and then overridden by command-line flags.
#include <glint/core/params.h>

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
    std::string sampler = "stratified";
    std::string filter = "box";
    float filter_radius = 0.0f;  // 0 = the filter's default
    float exposure = 0.0f;       // stops, applied to PNG output
    bool aovs = false;           // albedo/normal/depth channels in EXR output
    std::vector<std::string> outputs;
    int threads = 0;            // 0 = all cores
    bool csg_shortcuts = true;  // bounding-box pruning inside CSG trees
    // Where the integrator, sampler and filter names came from, for error messages.
    std::string where = "render settings";
};

RenderSettings parse_render_settings(const Params* params);

}  // namespace glint
