// ReSTIR DI in the preview: plain RIS (no reuse) and the unbiased mode with temporal and
// spatial reuse both converge to the path tracer's direct light; the biased mode is darker,
// as documented; the indirect bounces make the preview converge to `path` on the Cornell box;
// the image is the same for any thread count; the previous pass's projection agrees with the
// camera's; bad settings are refused with the key's name.
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/realtime/restir_di.h>
#include <glint/scene/build.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace glint;

namespace {

// A floor with a box on it, lit by three area lights of different sizes and colours (one
// facing away from most of the floor), a point light and a spot light: shadows, penumbrae,
// and lights that matter in some places only.
std::string lights_scene(const std::string& render) {
    return fmt::format(R"(
        glint.render{{ width = 32, height = 24, {} }}
        glint.camera{{ eye = {{0, 3, 5}}, look_at = {{0, 0.3, 0}}, fov = 50 }}
        glint.quad{{ vertices = {{{{-4, 0, 4}}, {{4, 0, 4}}, {{4, 0, -4}}, {{-4, 0, -4}}}},
                    material = glint.diffuse{{ reflectance = 0.7 }} }}
        glint.box{{ min = {{-0.6, 0, -0.6}}, max = {{0.6, 1.0, 0.6}},
                   material = glint.diffuse{{ reflectance = {{0.6, 0.4, 0.3}} }} }}
        glint.quad{{ vertices = {{{{-2.5, 2, -1}}, {{-1.5, 2, -1}}, {{-1.5, 2, 0}}, {{-2.5, 2, 0}}}},
                    material = glint.emissive{{ radiance = {{6, 5, 4}}, two_sided = true }} }}
        glint.quad{{ vertices = {{{{1.5, 1.5, -0.2}}, {{1.7, 1.5, -0.2}}, {{1.7, 1.5, 0}}, {{1.5, 1.5, 0}}}},
                    material = glint.emissive{{ radiance = {{40, 60, 80}}, two_sided = true }} }}
        glint.quad{{ vertices = {{{{-1, 0.5, -2}}, {{1, 0.5, -2}}, {{1, 1.5, -2}}, {{-1, 1.5, -2}}}},
                    material = glint.emissive{{ radiance = {{1, 2, 1}}, two_sided = false }} }}
        glint.point_light{{ position = {{1.5, 2.5, 2}}, intensity = 4 }}
        glint.spot_light{{ position = {{-2, 3, 2}}, look_at = {{0, 0, 0}}, intensity = 10,
                          cone_angle = 25, falloff_start = 20 }}
    )",
                       render);
}

double rel_mse(const Image& a, const Image& b) {
    return compare_images(a, b).rel_mse;
}

double mean_luminance(const Image& image) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
        sum += test::mean_channel(image, c, 0, 0, image.width, image.height);
    return sum / 3.0;
}

struct Convergence {
    double error, noise, reference_noise;
};

// Relative MSE of `test(seed)` against `reference(seed)`, with each side's noise measured
// from a second, independent render: one image's relative variance is half the pair's
// relative MSE. Expected error = both noises + bias^2.
template <typename Test, typename Reference>
Convergence converge(const Test& test, const Reference& reference) {
    const Image ref_a = reference(11), ref_b = reference(12);
    const Image a = test(1), b = test(2);
    return {rel_mse(a, ref_a), rel_mse(a, b) / 2.0, rel_mse(ref_a, ref_b) / 2.0};
}

std::string direct_preview(const std::string& restir, int passes, int seed) {
    return lights_scene(fmt::format(
        "integrator = 'preview', spp = {}, seed = {}, preview_bounces = 0, preview_ambient = 0, "
        "preview_photons = 0, {}",
        passes, seed, restir));
}

Image direct_reference(int seed) {
    return test::render_lua(lights_scene(
        fmt::format("integrator = 'path', max_depth = 1, spp = 1024, seed = {}", seed)));
}

}  // namespace

// With temporal and spatial reuse off, ReSTIR is plain RIS: M candidates from the light
// tree, one shadow ray. Unbiased, so its error against `path`'s direct light is the two
// images' noise (the bound allows twice the measured noise, whose estimate fluctuates, and
// 2e-3 for what the float sums may differ by).
TEST(RestirDiSlow, PlainRisConvergesToPathDirectLight) {
    const Convergence c = converge(
        [](int seed) {
            return test::render_lua(
                direct_preview("preview_restir = 'unbiased', preview_restir_spatial = 0, "
                               "preview_restir_temporal = false",
                               64, seed));
        },
        direct_reference);
    std::printf("RIS: relative MSE %.5f (noise %.5f, reference noise %.5f)\n", c.error, c.noise,
                c.reference_noise);
    EXPECT_LT(c.error, 2.0 * (c.noise + c.reference_noise) + 2e-3);
}

// The unbiased mode with temporal and spatial reuse converges to the same image.
TEST(RestirDiSlow, UnbiasedReuseConvergesToPathDirectLight) {
    const Convergence c = converge(
        [](int seed) {
            return test::render_lua(
                direct_preview("preview_restir = 'unbiased', preview_restir_spatial = 3, "
                               "preview_restir_temporal = true",
                               64, seed));
        },
        direct_reference);
    std::printf("unbiased reuse: relative MSE %.5f (noise %.5f, reference noise %.5f)\n", c.error,
                c.noise, c.reference_noise);
    EXPECT_LT(c.error, 2.0 * (c.noise + c.reference_noise) + 2e-3);
}

// The biased mode's 1/M weights count neighbours that could not have produced the sample:
// its image is darker than the unbiased one (the documented bias). Both modes draw the same
// candidates from the same seed, so their difference has less noise than either image; over
// three seeds the mean darkening must exceed 1 % and three standard errors of itself.
// (Measured: 3 to 6 % darker.)
TEST(RestirDi, BiasedModeIsDarker) {
    const std::string reuse = "preview_restir_spatial = 3, preview_restir_temporal = true";
    std::vector<double> darkening;
    for (int seed = 1; seed <= 3; ++seed) {
        const double unbiased = mean_luminance(test::render_lua(
            direct_preview(fmt::format("preview_restir = 'unbiased', {}", reuse), 32, seed)));
        const double biased = mean_luminance(test::render_lua(
            direct_preview(fmt::format("preview_restir = 'biased', {}", reuse), 32, seed)));
        darkening.push_back(1.0 - biased / unbiased);
        std::printf("seed %d: mean unbiased %.4f, biased %.4f (%.1f %% darker)\n", seed, unbiased,
                    biased, 100.0 * darkening.back());
    }
    double mean = 0.0, variance = 0.0;
    for (double d : darkening) mean += d / 3.0;
    for (double d : darkening) variance += (d - mean) * (d - mean) / 2.0;
    const double standard_error = std::sqrt(variance / 3.0);
    EXPECT_GT(mean, 0.01);
    EXPECT_GT(mean, 3.0 * standard_error);
}

// With one indirect bounce (and next-event estimation there) the preview carries what
// `path` with two bounces carries on the Cornell box, which has no mirrors or glass.
TEST(RestirDiSlow, PreviewWithBouncesConvergesToPathOnCornellBox) {
    const Convergence c = converge(
        [](int seed) {
            return test::render_lua(test::example_with_settings(
                "cornell-box.lua",
                fmt::format("width = 24, height = 24, integrator = 'preview', spp = 128, "
                            "seed = {}, preview_bounces = 1",
                            seed)));
        },
        [](int seed) {
            return test::render_lua(test::example_with_settings(
                "cornell-box.lua",
                fmt::format("width = 24, height = 24, integrator = 'path', max_depth = 2, "
                            "spp = 1024, seed = {}",
                            seed)));
        });
    std::printf("Cornell box, one bounce: relative MSE %.5f (noise %.5f, reference noise %.5f)\n",
                c.error, c.noise, c.reference_noise);
    EXPECT_LT(c.error, 2.0 * (c.noise + c.reference_noise) + 2e-3);
}

// Every pixel's numbers come from (seed, pixel, pass), and spatial reuse reads only the
// first stage's results: 1 and 2 threads give the same bits, with reuse and bounces on.
TEST(RestirDi, SameImageForOneAndTwoThreads) {
    for (const char* mode : {"unbiased", "biased"}) {
        const std::string code = lights_scene(fmt::format(
            "integrator = 'preview', spp = 4, preview_restir = '{}', preview_restir_spatial = 3",
            mode));
        const Image one = test::render_lua(code, 1), two = test::render_lua(code, 2);
        ASSERT_EQ(one.pixels.size(), two.pixels.size());
        size_t differing = 0;
        for (size_t i = 0; i < one.pixels.size(); ++i) differing += one.pixels[i] != two.pixels[i];
        EXPECT_EQ(differing, 0u) << mode;
    }
}

TEST(RestirDi, BadSettingsNameTheKey) {
    for (const std::string& bad :
         {std::string("preview_restir = 'fast'"), std::string("preview_restir_candidates = 0"),
          std::string("preview_restir_spatial = 40"), std::string("preview_bounces = -1")}) {
        const test::BuiltScene b = test::build_lua(lights_scene("integrator = 'preview', " + bad));
        const std::string key = bad.substr(0, bad.find(' '));
        try {
            make_integrator(b.settings);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("test.lua"), std::string::npos) << e.what();
        }
    }
}
