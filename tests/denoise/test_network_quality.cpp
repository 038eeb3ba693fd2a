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
#include <tuple>
#include <vector>

#include "weights.h"

namespace glint {
namespace {

using test::example_with_settings;
using test::Halves;

// What the network must do on a scene at one sample count: its error lower than the
// non-local means filter's by `gain_over_nlm`, and the edges' contrast at least these
// fractions of the reference's. The renders are seeded and the denoisers deterministic, so
// the figures are too; the bounds sit about 10 % below what was measured (docs/denoiser.md
// lists the figures) and guard against regressions. They are not the issue's targets (2x
// over non-local means, 95 % contrast), which glint's network meets only on the spheres at
// 16 spp: it agrees with OIDN's network to float rounding (test_network_reference.cpp), and
// the filter with its two half buffers and its firefly clamp is already close.
struct Expectation {
    int spp;
    double gain_over_nlm, geometry_contrast, texture_contrast;
};

struct Scene {
    const char* file;
    const char* settings;  // glint.render{...} without spp and seed
    std::vector<Expectation> expectations;
};

// The images are 128 pixels or more across: at 64, most pixels are within reach of the
// zero padding at the border and the figures swing with the size (at 64x64 the gains over
// non-local means were 2.88 and 1.35 on the Cornell box, 2.40 and 1.28 on the spheres).
//
// Measured gain over non-local means / geometry contrast: 1.68 / 0.94 at 4 spp, 1.32 / 0.95
// at 16.
const Scene cornell{"cornell-box.lua",
                    "width = 128, height = 128, integrator = 'path'",
                    {{4, 1.5, 0.9, 0.0}, {16, 1.2, 0.9, 0.0}}};
// Textures under an environment light: the IBL scene too. Measured 1.07 / 0.80 / 0.91 (gain
// / geometry / texture contrast) at 4 spp, 0.91 / 0.87 / 0.97 at 16: non-local means' error
// is lower there. Its geometry edges include the rough glass and metal spheres' silhouettes
// against a reference that is itself noisy there.
const Scene textures{"textures.lua",
                     "width = 320, height = 180, crop = {32, 48, 288, 168}, max_depth = 8",
                     {{4, 1.0, 0.75, 0.85}, {16, 0.8, 0.8, 0.9}}};
// A glass and a mirror sphere, their features those of what they show: measured 1.05 / 0.91
// at 4 spp, 2.18 / 0.85 at 16 (the caustic and the refracted room are what the network
// smooths).
const Scene spheres{"cornell-spheres.lua",
                    "width = 128, height = 128, integrator = 'path'",
                    {{4, 0.95, 0.8, 0.0}, {16, 2.0, 0.75, 0.0}}};

std::string code(const Scene& scene, int spp, int seed) {
    return example_with_settings(scene.file,
                                 fmt::format("{}, spp = {}, seed = {}", scene.settings, spp, seed));
}

struct Errors {
    double noisy, nlm, network;
};

// The whole-image errors at `e.spp`, and the network's edge contrast against the
// reference's (at least e's fraction of it on each band that is checked).
Errors measure(const Scene& scene, const Halves& ref, const Expectation& e) {
    const int spp = e.spp;
    const Halves noisy = test::render_halves(code(scene, spp, 1));
    NetworkDenoiseSettings settings;
    settings.threads = 2;
    const Image network = denoise_network(noisy.full, settings);
    const Image nlm = denoise(noisy.full, noisy.a, noisy.b);
    const Errors errors{test::error_against(noisy.full, ref), test::error_against(nlm, ref),
                        test::error_against(network, ref)};
    fmt::print(
        "{} at {} spp: relative MSE noisy {:.5f}, non-local means {:.5f}, network {:.5f} ({:.2f} x "
        "lower)\n",
        scene.file, spp, errors.noisy, errors.nlm, errors.network, errors.nlm / errors.network);
    const test::EdgeBands bands = test::edge_bands(ref.full);
    std::vector<std::tuple<const char*, const std::vector<uint8_t>*, double>> checks = {
        {"geometry", &bands.geometry, e.geometry_contrast}};
    if (e.texture_contrast > 0.0) checks.push_back({"texture", &bands.texture, e.texture_contrast});
    for (const auto& [name, band, min_contrast] : checks) {
        EXPECT_GT(test::band_size(*band), 50) << name;
        const double ref_contrast = test::edge_contrast(ref.full, *band);
        const double contrast = test::edge_contrast(network, *band);
        fmt::print("  {} edges: contrast {:.1f} % of the reference's\n", name,
                   100.0 * contrast / ref_contrast);
        EXPECT_GE(contrast, min_contrast * ref_contrast)
            << scene.file << " " << name << " edges at " << spp;
    }
    return errors;
}

// The three scenes render 128-pixel references at 512 spp: about a minute in all, ten
// under the sanitizers, whose run leaves them out (suite name ending in Slow); the network
// itself runs there in NetworkDenoiserQuality, NetworkWhole and NetworkDenoiser.
void check_scene(const Scene& scene) {
    test::installed_weights("rt_hdr_alb_nrm");
    const Halves ref = test::render_halves(code(scene, 512, 2));
    for (const Expectation& expectation : scene.expectations) {
        const Errors e = measure(scene, ref, expectation);
        EXPECT_LT(5.0 * e.network, e.noisy) << scene.file << " at " << expectation.spp;
        EXPECT_LT(expectation.gain_over_nlm * e.network, e.nlm)
            << scene.file << " at " << expectation.spp;
    }
}

TEST(NetworkDenoiserQualitySlow, CornellBox) {
    check_scene(cornell);
}
TEST(NetworkDenoiserQualitySlow, TexturesUnderEnvironmentLight) {
    check_scene(textures);
}
TEST(NetworkDenoiserQualitySlow, GlassAndMirrorSpheres) {
    check_scene(spheres);
}

// A checkerboard albedo under a smooth light, with matching features and no noise: the
// network must give it back within 1 % on average, all but a few per cent of the values
// away from the border within 1 % each (it must not invent or remove detail), and every
// value within 5 %. The last needs the mirrored border margin: with zeros beyond the border,
// as OIDN feeds, a value in a corner changed by 46 % (docs/denoiser.md).
TEST(NetworkDenoiserQuality, NoiseFreeImageComesBackWithinOnePercent) {
    const int w = 96, h = 64;
    Image image = make_image(
        w, h,
        {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z"});
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
    int far = 0, interior = 0, wx = 0, wy = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double relative =
                    std::abs(result.at(x, y, c) - image.at(x, y, c)) / image.at(x, y, c);
                sum += relative;
                if (x >= 8 && y >= 8 && x < w - 8 && y < h - 8) {
                    ++interior;
                    far += relative > 0.01;
                }
                if (relative > worst) {
                    worst = relative;
                    wx = x;
                    wy = y;
                }
            }
        }
    }
    const double mean = sum / (3.0 * w * h);
    const double far_share = static_cast<double>(far) / interior;
    fmt::print(
        "noise-free image: mean relative change {:.4f}, largest {:.4f} at ({}, {}); {:.1f} % of "
        "the "
        "values 8 pixels or more inside changed by more than 1 %\n",
        mean, worst, wx, wy, 100.0 * far_share);
    EXPECT_LT(mean, 0.01);
    EXPECT_LT(far_share, 0.05);
    EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace glint
