#pragma once
// What a render reports besides the film: counts, time, extra channels and debug images.
#include <glint/film/image.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

// A per-pixel channel an integrator adds to the image (e.g. samples taken per pixel).
struct ExtraChannel {
    std::string name;           // EXR channel name, e.g. "samples.Y"
    std::vector<float> values;  // width * height, row-major, top row first
};

// An image an integrator makes besides the render, for a debug view (bdpt's strategies):
// the command line writes it next to the first output as NAME.<name>.exr.
struct NamedImage {
    std::string name;
    Image image;
};

struct RenderStats {
    uint64_t samples = 0;
    uint64_t rays = 0;  // closest-hit plus shadow rays
    double seconds = 0.0;
    std::vector<ExtraChannel> channels;
    std::vector<std::string> notes;  // lines for the user (photon counts, ...)
    std::vector<NamedImage> images;  // debug views that are images of their own
};

}  // namespace glint
