#pragma once
// The graph of Open Image Denoise's U-Net, as plain data that both the oneDNN executor
// (denoise/network.h) and the tests' scalar reference run.
//
// Every convolution is 3 x 3 with stride 1 and zero padding 1, followed by a ReLU. The
// encoder halves the resolution four times with 2 x 2 max pooling; the decoder doubles it
// back with nearest-neighbour upsampling and concatenates, on the channel axis, the encoder's
// tensor of the same resolution (the upsampled tensor first), so that fine detail skips the
// bottleneck. Two sizes of the same shape are published:
//  - the default and "small" networks: enc_conv0, then enc_conv1..4 each followed by a pool,
//    enc_conv5a/b, dec_conv4a/b, 3a/b, 2a/b, 1a/b and dec_conv0 (the 3 output channels);
//  - the "large" networks: two convolutions per level (enc_conv1a/b .. enc_conv5a/b), the
//    same decoder, and dec_conv1c as the output.
// The channel counts come from the archive's tensors, checked against each other.
#include <glint/denoise/tza.h>

#include <string>
#include <vector>

namespace glint {

enum class LayerKind { Input, Conv, Pool, Upsample, Concat };

/// One node of the graph; its inputs are earlier nodes, by index.
struct Layer {
    LayerKind kind = LayerKind::Input;
    std::string name;            ///< Conv: the tensors' prefix ("enc_conv0")
    std::vector<int> inputs;     ///< Conv, Pool, Upsample: one; Concat: two (concatenated in order)
    int channels = 0;            ///< output channels
    int level = 0;               ///< resolution: the input's size divided by 2^level
    bool relu = false;           ///< Conv: a ReLU after the bias
    std::vector<float> weights;  ///< Conv: [channels][input channels][3][3]
    std::vector<float> bias;     ///< Conv: [channels]
};

/// A feed-forward graph in topological order; the last layer is the output.
struct NetworkGraph {
    std::vector<Layer> layers;
    int add_input(int channels);
    /// Adds a 3 x 3 convolution of `input` with weights [out][in][3][3] and bias [out];
    /// throws glint::Error when their shapes do not fit the input's channels.
    int add_conv(const std::string& name, int input, std::vector<float> weights,
                 std::vector<float> bias, bool relu);
    int add_pool(int input);
    int add_upsample(int input);
    int add_concat(int first, int second);
    /// The deepest level: the input's sides must be multiples of 2^max_level().
    int max_level() const;
    const Layer& output() const { return layers.back(); }
};

/// Builds OIDN's U-Net from the tensors of an archive, for `input_channels` input channels
/// (9 for colour, albedo and normal; 3 for an albedo or normal prefilter). Throws
/// glint::Error naming `origin` when a tensor is missing or has a shape that does not fit.
NetworkGraph make_unet(const TensorArchive& archive, int input_channels, const std::string& origin);

}  // namespace glint
