// The oneDNN executor (denoise/network.h) against the scalar reference (naive_network.h):
// each kind of layer on random tensors, then whole published networks on a small image.
#include <glint/core/error.h>
#include <glint/denoise/network.h>
#include <glint/denoise/tza.h>
#include <glint/denoise/unet.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "naive_network.h"
#include "weights.h"

namespace glint {
namespace {

using test::naive_forward;
using test::PlanarTensor;

std::vector<float> random_values(std::size_t count, std::mt19937& rng, float scale = 1.f) {
    std::uniform_real_distribution<float> u(-scale, scale);
    std::vector<float> values(count);
    for (float& v : values) v = u(rng);
    return values;
}

PlanarTensor random_tensor(int channels, int height, int width, std::mt19937& rng) {
    return {channels, height, width,
            random_values(static_cast<std::size_t>(channels) * height * width, rng)};
}

// Adds a convolution with random weights scaled so that outputs stay of order 1.
int add_random_conv(NetworkGraph& graph, int input, int channels, bool relu, std::mt19937& rng) {
    const int in = graph.layers[static_cast<std::size_t>(input)].channels;
    const float scale = 1.f / std::sqrt(9.f * static_cast<float>(in));
    return graph.add_conv("conv" + std::to_string(graph.layers.size()), input,
                          random_values(static_cast<std::size_t>(channels) * in * 9, rng, scale),
                          random_values(static_cast<std::size_t>(channels), rng, 0.5f), relu);
}

// The largest difference between oneDNN's output and the reference's, relative to the
// reference's largest magnitude (at least 1).
double run_and_compare(const NetworkGraph& graph, const PlanarTensor& input, int threads = 2) {
    NetworkExecutor executor(graph, input.height, input.width, threads);
    const PlanarTensor expected = naive_forward(graph, input).back();
    EXPECT_EQ(executor.output_channels(), expected.channels);
    EXPECT_EQ(executor.output_height(), expected.height);
    EXPECT_EQ(executor.output_width(), expected.width);
    std::vector<float> output(expected.values.size());
    executor.run(input.values.data(), output.data());
    double scale = 1.0, worst = 0.0;
    for (float v : expected.values) scale = std::max(scale, static_cast<double>(std::abs(v)));
    for (std::size_t i = 0; i < output.size(); ++i)
        worst = std::max(worst, std::abs(static_cast<double>(output[i]) - expected.values[i]));
    return worst / scale;
}

TEST(NetworkLayers, ConvolutionWithAndWithoutReluMatchesReference) {
    std::mt19937 rng(1);
    for (const auto& [in, out, relu] : {std::tuple{9, 32, true}, std::tuple{32, 48, false},
                                        std::tuple{3, 3, false}, std::tuple{41, 17, true}}) {
        NetworkGraph graph;
        add_random_conv(graph, graph.add_input(in), out, relu, rng);
        EXPECT_LT(run_and_compare(graph, random_tensor(in, 16, 32, rng)), 1e-4)
            << in << " -> " << out;
    }
}

TEST(NetworkLayers, MaxPoolingMatchesReference) {
    std::mt19937 rng(2);
    for (int channels : {3, 16, 48}) {
        NetworkGraph graph;
        graph.add_pool(graph.add_input(channels));
        EXPECT_EQ(run_and_compare(graph, random_tensor(channels, 32, 16, rng)), 0.0) << channels;
    }
}

TEST(NetworkLayers, NearestUpsamplingMatchesReference) {
    std::mt19937 rng(3);
    for (int channels : {9, 32, 40}) {
        NetworkGraph graph;
        graph.add_upsample(graph.add_pool(graph.add_input(channels)));
        EXPECT_EQ(run_and_compare(graph, random_tensor(channels, 16, 48, rng)), 0.0) << channels;
    }
}

// A concatenation is read by the convolution after it in two parts; channel counts that are
// not multiples of oneDNN's blocks (9, 41) check that the parts' weights line up.
TEST(NetworkLayers, ConcatenationThenConvolutionMatchesReference) {
    std::mt19937 rng(4);
    for (const auto& [a, b] : {std::pair{32, 9}, std::pair{64, 48}, std::pair{41, 7}}) {
        NetworkGraph graph;
        const int input = graph.add_input(b);
        const int first = add_random_conv(graph, input, a, true, rng);
        add_random_conv(graph, graph.add_concat(first, input), 24, true, rng);
        EXPECT_LT(run_and_compare(graph, random_tensor(b, 32, 32, rng)), 1e-4) << a << " + " << b;
    }
}

TEST(NetworkLayers, BadSizesAndGraphsAreClearErrors) {
    NetworkGraph graph;
    graph.add_pool(graph.add_input(3));
    EXPECT_THROW(NetworkExecutor(graph, 15, 16, 1), Error);  // not a multiple of 2
    EXPECT_THROW(NetworkExecutor(graph, 16, 16, 0), Error);
    EXPECT_THROW(graph.add_conv("c", 0, std::vector<float>(5), std::vector<float>(1), true), Error);
    NetworkGraph concat_out;
    const int in = concat_out.add_input(3);
    concat_out.add_concat(in, in);
    EXPECT_THROW(NetworkExecutor(concat_out, 16, 16, 1), Error);
}

// A smooth random image in the networks' input ranges: colour and albedo in [0, 1], normals
// around 0.5 (mapped from [-1, 1]).
PlanarTensor network_input(int channels, int height, int width, std::mt19937& rng) {
    PlanarTensor t = random_tensor(channels, height, width, rng);
    for (float& v : t.values) v = 0.5f + 0.5f * v;
    return t;
}

// The whole published network, every layer of it, equals the scalar forward pass. (Slow: half
// a minute under the sanitizers, where the per-layer suites and NetworkWhole.SameBits keep
// the kernels checked.)
TEST(NetworkWholeSlow, PublishedNetworksMatchScalarForwardPass) {
    std::mt19937 rng(5);
    for (const auto& [name, channels] :
         {std::pair{"rt_hdr_alb_nrm", 9}, std::pair{"rt_hdr_alb_nrm_small", 9},
          std::pair{"rt_nrm_large", 3}}) {
        const std::string path = test::installed_weights(name);
        const NetworkGraph graph = make_unet(read_tza(path), channels, path);
        EXPECT_LT(run_and_compare(graph, network_input(channels, 32, 48, rng)), 1e-4) << name;
    }
}

TEST(NetworkWhole, SameBitsForOneAndTwoThreads) {
    std::mt19937 rng(6);
    const std::string path = test::installed_weights("rt_hdr_alb_nrm");
    const NetworkGraph graph = make_unet(read_tza(path), 9, path);
    const PlanarTensor input = network_input(9, 64, 80, rng);
    std::vector<float> one(3 * 64 * 80), two(one.size());
    NetworkExecutor(graph, 64, 80, 1).run(input.values.data(), one.data());
    NetworkExecutor(graph, 64, 80, 2).run(input.values.data(), two.data());
    EXPECT_EQ(one, two);
    // And running again reuses the buffers without leftovers.
    NetworkExecutor again(graph, 64, 80, 2);
    again.run(input.values.data(), two.data());
    again.run(input.values.data(), two.data());
    EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace glint
