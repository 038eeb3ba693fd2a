#include <glint/core/error.h>
#include <glint/denoise/network.h>
#include <glint/denoise/network_denoiser.h>
#include <glint/denoise/tiling.h>
#include <glint/denoise/transfer.h>
#include <glint/denoise/tza.h>
#include <glint/denoise/unet.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#ifndef GLINT_DENOISE_WEIGHTS_DIR
#define GLINT_DENOISE_WEIGHTS_DIR "/usr/local/share/glint/denoise"
#endif

namespace glint {

namespace {

struct WeightNames {
    std::string color, albedo, normal;  // albedo and normal: empty without prefiltering
};

bool cleans_aux(const NetworkDenoiseSettings& settings) {
    return settings.clean_aux || settings.quality == DenoiseQuality::High;
}

WeightNames weight_names(const NetworkDenoiseSettings& settings) {
    const bool clean = cleans_aux(settings);
    WeightNames names;
    switch (settings.quality) {
        case DenoiseQuality::Fast:
            names.color = clean ? "rt_hdr_calb_cnrm_small" : "rt_hdr_alb_nrm_small";
            break;
        case DenoiseQuality::Balanced:
            names.color = clean ? "rt_hdr_calb_cnrm" : "rt_hdr_alb_nrm";
            break;
        case DenoiseQuality::High:
            names.color = "rt_hdr_calb_cnrm_large";
            break;
    }
    if (clean) {
        const bool large = settings.quality == DenoiseQuality::High;
        names.albedo = large ? "rt_alb_large" : "rt_alb";
        names.normal = large ? "rt_nrm_large" : "rt_nrm";
    }
    return names;
}

std::string weight_path(const NetworkDenoiseSettings& settings, const std::string& name) {
    const std::string dir =
        settings.weights_dir.empty() ? denoise_weights_dir() : settings.weights_dir;
    return (std::filesystem::path(dir) / (name + ".tza")).string();
}

NetworkGraph load_network(const NetworkDenoiseSettings& settings, const std::string& name,
                          int channels) {
    const std::string path = weight_path(settings, name);
    return make_unet(read_tza(path), channels, path);
}

// The three-channel features at 3 consecutive channels starting at `first`.
int channel_or_throw(const Image& image, const std::string& name) {
    const int index = image.channel_index(name);
    if (index < 0)
        throw Error(
            fmt::format("the network denoiser needs channel '{}' (a film with AOVs)", name));
    return index;
}

// A coordinate outside [0, size) mirrored back into it about the edge pixels (which are
// not repeated), as often as needed for margins wider than the image.
int mirrored(int i, int size) {
    if (size == 1) return 0;
    const int period = 2 * (size - 1);
    i %= period;
    if (i < 0) i += period;
    return i < size ? i : period - i;
}

TilePlan plan_with_margins(int width, int height, const NetworkDenoiseSettings& settings) {
    if (settings.border_margin < 0)
        throw Error(fmt::format("denoiser border margin of {} pixels: expected 0 or more",
                                settings.border_margin));
    return plan_denoise_tiles(width + 2 * settings.border_margin,
                              height + 2 * settings.border_margin, settings.max_tile);
}

// Runs one network over the image tile by tile: `fill(x, y, values)` writes a pixel's
// input channels, `store(x, y, values)` takes its three output channels. The tiles cover
// the image extended by the border margin on every side; fill() is asked for the mirrored
// pixel there, and store() gets the image's own pixels only.
class TiledPass {
public:
    TiledPass(int width, int height, const NetworkDenoiseSettings& settings)
        : m_width(width),
          m_height(height),
          m_margin(settings.border_margin),
          m_settings(settings),
          m_plan(plan_with_margins(width, height, settings)) {}

    int tiles() const { return static_cast<int>(m_plan.tiles.size()); }

    template <typename Fill, typename Store>
    void run(const NetworkGraph& graph, Fill fill, Store store, int& done, int total) {
        NetworkExecutor network(graph, m_plan.height, m_plan.width, m_settings.threads);
        const int channels = graph.layers.front().channels;
        const std::size_t plane = static_cast<std::size_t>(m_plan.width) * m_plan.height;
        std::vector<float> input(plane * channels), output(plane * 3);
        std::array<float, 16> values{};
        for (const DenoiseTile& tile : m_plan.tiles) {
            std::fill(input.begin(), input.end(), 0.f);
            const int rows = std::min(m_plan.height, m_height + 2 * m_margin - tile.y);
            const int columns = std::min(m_plan.width, m_width + 2 * m_margin - tile.x);
            for (int j = 0; j < rows; ++j) {
                const int y = mirrored(tile.y + j - m_margin, m_height);
                for (int i = 0; i < columns; ++i) {
                    fill(mirrored(tile.x + i - m_margin, m_width), y, values.data());
                    const std::size_t at = static_cast<std::size_t>(j) * m_plan.width + i;
                    for (int c = 0; c < channels; ++c) input[c * plane + at] = values[c];
                }
            }
            network.run(input.data(), output.data());
            const int y0 = std::max(tile.keep_y0, m_margin),
                      y1 = std::min(tile.keep_y1, m_margin + m_height);
            const int x0 = std::max(tile.keep_x0, m_margin),
                      x1 = std::min(tile.keep_x1, m_margin + m_width);
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const std::size_t at =
                        static_cast<std::size_t>(y - tile.y) * m_plan.width + (x - tile.x);
                    store(x - m_margin, y - m_margin,
                          std::array<float, 3>{output[at], output[plane + at],
                                               output[2 * plane + at]});
                }
            }
            ++done;
            if (m_settings.on_progress) m_settings.on_progress(done, total);
        }
    }

private:
    int m_width, m_height, m_margin;
    const NetworkDenoiseSettings& m_settings;
    TilePlan m_plan;
};

float finite_or_zero(float v) {
    return std::isfinite(v) ? v : 0.f;
}

}  // namespace

std::optional<DenoiseQuality> parse_denoise_quality(const std::string& name) {
    if (name == "fast") return DenoiseQuality::Fast;
    if (name == "balanced") return DenoiseQuality::Balanced;
    if (name == "high") return DenoiseQuality::High;
    return std::nullopt;
}

std::string denoise_weights_dir() {
    const char* dir = std::getenv("GLINT_DENOISE_WEIGHTS");
    return dir && *dir ? std::string(dir) : std::string(GLINT_DENOISE_WEIGHTS_DIR);
}

std::vector<std::string> denoise_weight_files(const NetworkDenoiseSettings& settings) {
    const WeightNames names = weight_names(settings);
    std::vector<std::string> files{weight_path(settings, names.color)};
    if (!names.albedo.empty()) files.push_back(weight_path(settings, names.albedo));
    if (!names.normal.empty()) files.push_back(weight_path(settings, names.normal));
    return files;
}

void check_denoise_weights(const NetworkDenoiseSettings& settings) {
    for (const std::string& file : denoise_weight_files(settings)) {
        if (!std::filesystem::is_regular_file(file))
            throw Error(fmt::format(
                "{}: the network denoiser's weights are not installed; run scripts/install-deps.sh "
                "(it fetches Open Image Denoise's trained weights, Apache-2.0), or set "
                "GLINT_DENOISE_WEIGHTS to the directory that holds them, or use '--denoise nlm' "
                "for glint's own filter",
                file));
    }
}

Image denoise_network(const Image& image, const NetworkDenoiseSettings& settings) {
    const int r = channel_or_throw(image, "R"), g = channel_or_throw(image, "G"),
              b = channel_or_throw(image, "B");
    const int albedo = channel_or_throw(image, "albedo.R"),
              normal = channel_or_throw(image, "normal.X");
    if (image.channel_index("albedo.G") != albedo + 1 ||
        image.channel_index("albedo.B") != albedo + 2 ||
        image.channel_index("normal.Y") != normal + 1 ||
        image.channel_index("normal.Z") != normal + 2)
        throw Error(
            "the network denoiser needs albedo.R/G/B and normal.X/Y/Z as consecutive channels");
    check_denoise_weights(settings);
    const WeightNames names = weight_names(settings);
    const NetworkGraph color_net = load_network(settings, names.color, 9);

    TiledPass pass(image.width, image.height, settings);
    const bool clean = cleans_aux(settings);
    const int total = pass.tiles() * (clean ? 3 : 1);
    int done = 0;

    // The features the colour network reads, prefiltered or as rendered.
    Image features =
        make_image(image.width, image.height,
                   {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z"});
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                features.at(x, y, c) =
                    std::clamp(finite_or_zero(image.at(x, y, albedo + c)), 0.f, 1.f);
                features.at(x, y, 3 + c) =
                    std::clamp(finite_or_zero(image.at(x, y, normal + c)), -1.f, 1.f);
            }
        }
    }
    if (clean) {
        // Albedo in the sRGB encoding the albedo network was trained on, normals in [0, 1].
        const NetworkGraph albedo_net = load_network(settings, names.albedo, 3);
        const NetworkGraph normal_net = load_network(settings, names.normal, 3);
        Image filtered = features;
        pass.run(
            albedo_net,
            [&](int x, int y, float* v) {
                for (int c = 0; c < 3; ++c) v[c] = srgb_forward(features.at(x, y, c));
            },
            [&](int x, int y, const std::array<float, 3>& v) {
                for (int c = 0; c < 3; ++c)
                    filtered.at(x, y, c) =
                        std::min(srgb_to_linear(std::max(finite_or_zero(v[c]), 0.f)), 1.f);
            },
            done, total);
        pass.run(
            normal_net,
            [&](int x, int y, float* v) {
                for (int c = 0; c < 3; ++c) v[c] = features.at(x, y, 3 + c) * 0.5f + 0.5f;
            },
            [&](int x, int y, const std::array<float, 3>& v) {
                for (int c = 0; c < 3; ++c)
                    filtered.at(x, y, 3 + c) =
                        std::clamp(std::max(finite_or_zero(v[c]), 0.f) * 2.f - 1.f, -1.f, 1.f);
            },
            done, total);
        features = std::move(filtered);
    }

    const float exposure = autoexposure(image);
    const float unexposure = exposure != 0.f ? 1.f / exposure : 0.f;
    Image result = make_image(image.width, image.height, {"R", "G", "B"});
    const int rgb[3] = {r, g, b};
    pass.run(
        color_net,
        [&](int x, int y, float* v) {
            for (int c = 0; c < 3; ++c)
                v[c] = pu_forward(std::max(finite_or_zero(image.at(x, y, rgb[c]) * exposure), 0.f));
            for (int c = 0; c < 3; ++c) v[3 + c] = features.at(x, y, c);
            for (int c = 0; c < 3; ++c) v[6 + c] = features.at(x, y, 3 + c) * 0.5f + 0.5f;
        },
        [&](int x, int y, const std::array<float, 3>& v) {
            for (int c = 0; c < 3; ++c)
                result.at(x, y, c) = pu_inverse(std::max(finite_or_zero(v[c]), 0.f)) * unexposure;
        },
        done, total);
    return result;
}

int denoise_network_tiles(int width, int height, const NetworkDenoiseSettings& settings) {
    return static_cast<int>(plan_with_margins(width, height, settings).tiles.size());
}

std::size_t denoise_network_memory(int width, int height, const NetworkDenoiseSettings& settings) {
    const TilePlan plan = plan_with_margins(width, height, settings);
    const NetworkGraph net = load_network(settings, weight_names(settings).color, 9);
    const NetworkExecutor executor(net, plan.height, plan.width, settings.threads);
    const std::size_t plane = static_cast<std::size_t>(plan.width) * plan.height;
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    // The tile's planar input (9) and output (3); the whole image's features (6, twice while
    // they are prefiltered) and result (3).
    const std::size_t image_floats = (cleans_aux(settings) ? 12 : 6) + 3;
    return executor.memory_bytes() + (plane * 12 + pixels * image_floats) * sizeof(float);
}

}  // namespace glint
