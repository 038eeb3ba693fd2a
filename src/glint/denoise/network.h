#pragma once
// Runs a NetworkGraph (denoise/unet.h) on oneDNN: the only file of glint that sees oneDNN.
//
// Everything is set up once for one input size: every primitive is created, every weight is
// reordered into the layout oneDNN's kernels want, and the activations live in a few buffers
// reused as tensors die (planned from each tensor's last use), so that run() allocates
// nothing. Activations are float32 in oneDNN's channel-blocked layout (8 or 16 channels per
// block, what its AVX2 / AVX-512 kernels read). A concatenation is never copied: the
// convolution after it runs as two convolutions over the two parts, the second adding its
// result onto the first's (oneDNN's "sum" post-op) before the ReLU.
#include <glint/denoise/unet.h>

#include <cstddef>
#include <memory>

namespace glint {

class NetworkExecutor {
public:
    /// Prepares `graph` for inputs of `height` x `width` pixels, both multiples of
    /// 2^graph.max_level(); throws glint::Error otherwise or when oneDNN cannot run a layer.
    /// `threads` (>= 1) OpenMP threads run each layer; the result is the same for any count.
    NetworkExecutor(const NetworkGraph& graph, int height, int width, int threads);
    ~NetworkExecutor();
    NetworkExecutor(const NetworkExecutor&) = delete;
    NetworkExecutor& operator=(const NetworkExecutor&) = delete;

    /// Runs the graph on `input`, planar [channels][height][width] floats, and writes the
    /// output layer planar into `output` (output_channels() x output_height() x
    /// output_width() floats).
    void run(const float* input, float* output);

    int output_channels() const;
    int output_height() const;
    int output_width() const;
    /// Bytes held: activations, oneDNN's scratchpads and the reordered weights.
    std::size_t memory_bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace glint
