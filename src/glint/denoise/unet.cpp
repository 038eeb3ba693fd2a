#include <glint/core/error.h>
#include <glint/denoise/unet.h>

#include <fmt/format.h>

#include <algorithm>

namespace glint {

int NetworkGraph::add_input(int channels) {
    Layer layer;
    layer.kind = LayerKind::Input;
    layer.name = "input";
    layer.channels = channels;
    layers.push_back(std::move(layer));
    return static_cast<int>(layers.size()) - 1;
}

int NetworkGraph::add_conv(const std::string& name, int input, std::vector<float> weights,
                           std::vector<float> bias, bool relu) {
    const Layer& source = layers.at(static_cast<std::size_t>(input));
    const std::size_t out = bias.size();
    if (out == 0 || weights.size() != out * static_cast<std::size_t>(source.channels) * 9)
        throw Error(fmt::format(
            "convolution '{}': {} weights and {} biases do not fit {} input channels (expected "
            "[out][{}][3][3] and [out])",
            name, weights.size(), bias.size(), source.channels, source.channels));
    Layer layer;
    layer.kind = LayerKind::Conv;
    layer.name = name;
    layer.inputs = {input};
    layer.channels = static_cast<int>(out);
    layer.level = source.level;
    layer.relu = relu;
    layer.weights = std::move(weights);
    layer.bias = std::move(bias);
    layers.push_back(std::move(layer));
    return static_cast<int>(layers.size()) - 1;
}

int NetworkGraph::add_pool(int input) {
    Layer layer;
    layer.kind = LayerKind::Pool;
    layer.name = layers.at(static_cast<std::size_t>(input)).name + ".pool";
    layer.inputs = {input};
    layer.channels = layers[static_cast<std::size_t>(input)].channels;
    layer.level = layers[static_cast<std::size_t>(input)].level + 1;
    layers.push_back(std::move(layer));
    return static_cast<int>(layers.size()) - 1;
}

int NetworkGraph::add_upsample(int input) {
    const Layer& source = layers.at(static_cast<std::size_t>(input));
    if (source.level == 0) throw Error("cannot upsample a tensor at the input's resolution");
    Layer layer;
    layer.kind = LayerKind::Upsample;
    layer.name = source.name + ".upsample";
    layer.inputs = {input};
    layer.channels = source.channels;
    layer.level = source.level - 1;
    layers.push_back(std::move(layer));
    return static_cast<int>(layers.size()) - 1;
}

int NetworkGraph::add_concat(int first, int second) {
    const Layer& a = layers.at(static_cast<std::size_t>(first));
    const Layer& b = layers.at(static_cast<std::size_t>(second));
    if (a.level != b.level) throw Error("cannot concatenate tensors of different resolutions");
    Layer layer;
    layer.kind = LayerKind::Concat;
    layer.name = a.name + "+" + b.name;
    layer.inputs = {first, second};
    layer.channels = a.channels + b.channels;
    layer.level = a.level;
    layers.push_back(std::move(layer));
    return static_cast<int>(layers.size()) - 1;
}

int NetworkGraph::max_level() const {
    int level = 0;
    for (const Layer& layer : layers) level = std::max(level, layer.level);
    return level;
}

namespace {

// Adds convolution `name` from the archive, checking its tensors' shapes against the
// input's channels and each other.
int add_archive_conv(NetworkGraph& graph, const TensorArchive& archive, const std::string& origin,
                     const std::string& name, int input, bool relu) {
    const auto weight = archive.find(name + ".weight");
    const auto bias = archive.find(name + ".bias");
    if (weight == archive.end() || bias == archive.end())
        throw Error(fmt::format("{}: the network has no tensor '{}.{}'", origin, name,
                                weight == archive.end() ? "weight" : "bias"));
    const int in = graph.layers[static_cast<std::size_t>(input)].channels;
    const std::vector<int>& w = weight->second.dims;
    const std::vector<int>& b = bias->second.dims;
    if (w.size() != 4 || w[1] != in || w[2] != 3 || w[3] != 3 || b.size() != 1 || b[0] != w[0])
        throw Error(fmt::format(
            "{}: tensor '{}.weight' has shape [{}] and '{}.bias' [{}]; the network expects "
            "[out, {}, 3, 3] and [out]",
            origin, name, fmt::join(w, ", "), name, fmt::join(b, ", "), in));
    return graph.add_conv(name, input, weight->second.values, bias->second.values, relu);
}

}  // namespace

NetworkGraph make_unet(const TensorArchive& archive, int input_channels,
                       const std::string& origin) {
    NetworkGraph graph;
    const bool large = archive.count("enc_conv1a.weight") > 0;
    auto conv = [&](const std::string& name, int input) {
        return add_archive_conv(graph, archive, origin, name, input, true);
    };
    const int input = graph.add_input(input_channels);
    // Encoder: the skip tensors are the pooled outputs of levels 1 to 3.
    int x = large ? conv("enc_conv1b", conv("enc_conv1a", input))
                  : conv("enc_conv1", conv("enc_conv0", input));
    const int pool1 = graph.add_pool(x);
    x = large ? conv("enc_conv2b", conv("enc_conv2a", pool1)) : conv("enc_conv2", pool1);
    const int pool2 = graph.add_pool(x);
    x = large ? conv("enc_conv3b", conv("enc_conv3a", pool2)) : conv("enc_conv3", pool2);
    const int pool3 = graph.add_pool(x);
    x = large ? conv("enc_conv4b", conv("enc_conv4a", pool3)) : conv("enc_conv4", pool3);
    x = graph.add_pool(x);
    x = conv("enc_conv5b", conv("enc_conv5a", x));
    // Decoder.
    x = conv("dec_conv4b", conv("dec_conv4a", graph.add_concat(graph.add_upsample(x), pool3)));
    x = conv("dec_conv3b", conv("dec_conv3a", graph.add_concat(graph.add_upsample(x), pool2)));
    x = conv("dec_conv2b", conv("dec_conv2a", graph.add_concat(graph.add_upsample(x), pool1)));
    x = conv("dec_conv1b", conv("dec_conv1a", graph.add_concat(graph.add_upsample(x), input)));
    // The output convolution: OIDN clamps its result to >= 0 afterwards, so a ReLU here or
    // not gives the same image; leaving it out keeps the raw output visible to tests.
    const int out =
        add_archive_conv(graph, archive, origin, large ? "dec_conv1c" : "dec_conv0", x, false);
    if (graph.layers[static_cast<std::size_t>(out)].channels != 3)
        throw Error(fmt::format("{}: the network's output has {} channels (expected 3)", origin,
                                graph.layers[static_cast<std::size_t>(out)].channels));
    return graph;
}

}  // namespace glint
