// The network denoiser on glint's own scenes: its error against a converged reference
// compared with the noisy image's and with the non-local means filter's, the contrast it
// keeps at geometry and texture edges, and an image with no noise coming back unchanged.
#include <glint/denoise/network_denoiser.h>
#include <glint/film/denoise.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/denoise_metrics.h>
#include <support/render_helpers.h>

#include <cmath>

#include "weights.h"

namespace glint {
namespace {

using test::example_with_settings;
using test::Halves;

struct Scene {
    const char* file;
    const char* settings;  // glint.render{...} without spp and seed
    bool texture_edges;
};

const Scene cornell{"cornell-box.lua", "width = 64, height = 64, integrator = 'path'", false};
// Textures under an environment light: the IBL scene too.
const Scene textures{"textures.lua", "width = 160, height = 90, crop = {16, 24, 144, 84}, max_depth = 8", true};
const Scene spheres{"cornell-spheres.lua", "width = 64, height = 64, integrator = 'path'", false};

std::string code(const Scene& scene, int spp, int seed) {
    return example_with_settings(scene.file, fmt::format("{}, spp = {}, seed = {}", scene.settings, spp, seed));
}

struct Errors {
    double noisy, nlm, network;
};

// The whole-image errors at `spp`, and the network's edge contrast against the reference's
// (at least `min_contrast` of it on each band).
Errors measure(const Scene& scene, const Halves& ref, int spp, double min_contrast) {
    const Halves noisy = test::render_halves(code(scene, spp, 1));
    NetworkDenoiseSettings settings;
    settings.threads = 2;
    const Image network = denoise_network(noisy.full, settings);
    const Image nlm = denoise(noisy.full, noisy.a, noisy.b);
    const Errors errors{test::error_against(noisy.full, ref), test::error_against(nlm, ref),
                        test::error_against(network, ref)};
    fmt::print("{} at {} spp: relative MSE noisy {:.5f}, non-local means {:.5f}, network {:.5f} ({:.2f} x lower)\n",
               scene.file, spp, errors.noisy, errors.nlm, errors.network, errors.nlm / errors.network);
    const test::EdgeBands bands = test::edge_bands(ref.full);
    std::vector<std::pair<const char*, const std::vector<uint8_t>*>> checks = {{"geometry", &bands.geometry}};
    if (scene.texture_edges) checks.push_back({"texture", &bands.texture});
    for (const auto& [name, band] : checks) {
        EXPECT_GT(test::band_size(*band), 50) << name;
        const double ref_contrast = test::edge_contrast(ref.full, *band);
        const double contrast = test::edge_contrast(network, *band);
        fmt::print("  {} edges: contrast {:.1f} % of the reference's\n", name, 100.0 * contrast / ref_contrast);
        EXPECT_GE(contrast, min_contrast * ref_contrast) << scene.file << " " << name << " edges at " << spp;
    }
    return errors;
}

void check_scene(const Scene& scene, double min_gain_over_nlm, double min_contrast) {
    test::installed_weights("rt_hdr_alb_nrm");
    const Halves ref = test::render_halves(code(scene, 512, 2));
    for (int spp : {4, 16}) {
        const Errors e = measure(scene, ref, spp, min_contrast);
        EXPECT_LT(10.0 * e.network, e.noisy) << scene.file << " at " << spp;
        EXPECT_LT(min_gain_over_nlm * e.network, e.nlm) << scene.file << " at " << spp;
    }
}

TEST(NetworkDenoiserQuality, CornellBox) { check_scene(cornell, 1.3, 0.95); }
TEST(NetworkDenoiserQuality, TexturesUnderEnvironmentLight) { check_scene(textures, 1.0, 0.95); }
TEST(NetworkDenoiserQuality, GlassAndMirrorSpheres) { check_scene(spheres, 1.3, 0.95); }

// A checkerboard albedo under a smooth light, with matching features and no noise: the
// network must give it back within 1 % (it must not invent or remove detail).
TEST(NetworkDenoiserQuality, NoiseFreeImageComesBackWithinOnePercent) {
    const int w = 96, h = 64;
    Image image = make_image(w, h, {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y",
                                    "normal.Z"});
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float albedo = ((x / 8 + y / 8) % 2) ? 0.8f : 0.2f;
            const float light = 1.0f + 0.5f * std::sin(0.05f * x) * std::cos(0.07f * y);
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) = albedo * light * (0.6f + 0.2f * c);
                image.at(x, y, 3 + c) = albedo;
            }
            image.at(x, y, 8) = 1.0f;
        }
    }
    NetworkDenoiseSettings settings;
    settings.threads = 2;
    test::installed_weights("rt_hdr_alb_nrm");
    const Image result = denoise_network(image, settings);
    double sum = 0.0, worst = 0.0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double relative = std::abs(result.at(x, y, c) - image.at(x, y, c)) / image.at(x, y, c);
                sum += relative;
                worst = std::max(worst, relative);
            }
        }
    }
    const double mean = sum / (3.0 * w * h);
    fmt::print("noise-free image: mean relative change {:.4f}, largest {:.4f}\n", mean, worst);
    EXPECT_LT(mean, 0.01);
}

}  // namespace
}  // namespace glint
