#pragma once
// A scalar forward pass of a NetworkGraph, written for clarity, not speed: the reference the
// oneDNN executor is tested against. Tensors are planar [channels][height][width].
#include <glint/denoise/unet.h>

#include <vector>

namespace glint::test {

struct PlanarTensor {
    int channels = 0, height = 0, width = 0;
    std::vector<float> values;
    float at(int c, int y, int x) const {
        return values[(static_cast<std::size_t>(c) * height + y) * width + x];
    }
};

/// Every layer's output for `input` (the graph's first layer); index i is layer i's.
std::vector<PlanarTensor> naive_forward(const NetworkGraph& graph, const PlanarTensor& input);

}  // namespace glint::test
