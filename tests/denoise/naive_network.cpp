#include "naive_network.h"

#include <algorithm>

namespace glint::test {

namespace {

PlanarTensor zeros(int channels, int height, int width) {
    return {channels, height, width,
            std::vector<float>(static_cast<std::size_t>(channels) * height * width, 0.f)};
}

float& at(PlanarTensor& t, int c, int y, int x) {
    return t.values[(static_cast<std::size_t>(c) * t.height + y) * t.width + x];
}

// out[o][y][x] = bias[o] + sum over i, dy, dx of w[o][i][dy][dx] * in[i][y+dy-1][x+dx-1],
// with zeros outside the image; accumulated in double.
PlanarTensor convolve(const Layer& layer, const PlanarTensor& in) {
    PlanarTensor out = zeros(layer.channels, in.height, in.width);
    for (int o = 0; o < layer.channels; ++o) {
        for (int y = 0; y < in.height; ++y) {
            for (int x = 0; x < in.width; ++x) {
                double sum = layer.bias[static_cast<std::size_t>(o)];
                for (int i = 0; i < in.channels; ++i) {
                    for (int dy = 0; dy < 3; ++dy) {
                        for (int dx = 0; dx < 3; ++dx) {
                            const int sy = y + dy - 1, sx = x + dx - 1;
                            if (sy < 0 || sy >= in.height || sx < 0 || sx >= in.width) continue;
                            const std::size_t w =
                                ((static_cast<std::size_t>(o) * in.channels + i) * 3 + dy) * 3 + dx;
                            sum += static_cast<double>(layer.weights[w]) * in.at(i, sy, sx);
                        }
                    }
                }
                const float value = static_cast<float>(sum);
                at(out, o, y, x) = layer.relu ? std::max(value, 0.f) : value;
            }
        }
    }
    return out;
}

PlanarTensor max_pool(const PlanarTensor& in) {
    PlanarTensor out = zeros(in.channels, in.height / 2, in.width / 2);
    for (int c = 0; c < in.channels; ++c)
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x)
                at(out, c, y, x) =
                    std::max({in.at(c, 2 * y, 2 * x), in.at(c, 2 * y, 2 * x + 1),
                              in.at(c, 2 * y + 1, 2 * x), in.at(c, 2 * y + 1, 2 * x + 1)});
    return out;
}

PlanarTensor upsample(const PlanarTensor& in) {
    PlanarTensor out = zeros(in.channels, in.height * 2, in.width * 2);
    for (int c = 0; c < in.channels; ++c)
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x) at(out, c, y, x) = in.at(c, y / 2, x / 2);
    return out;
}

PlanarTensor concatenate(const PlanarTensor& a, const PlanarTensor& b) {
    PlanarTensor out = a;
    out.channels += b.channels;
    out.values.insert(out.values.end(), b.values.begin(), b.values.end());
    return out;
}

}  // namespace

std::vector<PlanarTensor> naive_forward(const NetworkGraph& graph, const PlanarTensor& input) {
    std::vector<PlanarTensor> outputs;
    for (const Layer& layer : graph.layers) {
        auto in = [&](int k) -> const PlanarTensor& {
            return outputs[static_cast<std::size_t>(layer.inputs[static_cast<std::size_t>(k)])];
        };
        switch (layer.kind) {
            case LayerKind::Input:
                outputs.push_back(input);
                break;
            case LayerKind::Conv:
                outputs.push_back(convolve(layer, in(0)));
                break;
            case LayerKind::Pool:
                outputs.push_back(max_pool(in(0)));
                break;
            case LayerKind::Upsample:
                outputs.push_back(upsample(in(0)));
                break;
            case LayerKind::Concat:
                outputs.push_back(concatenate(in(0), in(1)));
                break;
        }
    }
    return outputs;
}

}  // namespace glint::test
