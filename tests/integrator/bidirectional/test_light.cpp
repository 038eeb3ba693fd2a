// The light tracer ("light"): it converges to the path tracer wherever both can see, finds
// the caustic of a point light behind glass that the path tracer cannot, and gives the
// same bits for any thread count.
//
// Comparisons between Monte Carlo images use bounds taken from the images' own noise:
// each integrator renders K images with independent seeds; the spread of the K values of
// a statistic (a block mean, a region mean) gives its standard error, with every
// correlation between pixels included (one light path splats to several pixels, so the
// pixels of a light-traced image are not independent).
#include <glint/core/arena.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/material/bsdf.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/image_comparison.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace glint;
using glint::test::read_text;
using glint::test::render_lua;
using namespace glint::test;

namespace {

// An example scene with its glint.render{...} call (output list included) replaced by
// `settings`: a second glint.render would be an error.
std::string example_with(const char* file, const std::string& settings) {
    const std::string code = read_text(std::string(GLINT_SOURCE_DIR "/examples/") + file);
    const size_t start = code.find("glint.render{");
    const size_t end = code.find('}', code.find('}', code.find("output", start)) + 1);
    return code.substr(0, start) + "glint.render{ " + settings + " }" + code.substr(end + 1);
}

// Light and path tracing of `scene(integrator, spp, seed)` agree over the non-delta mask,
// and the same check rejects the light-traced images scaled by 1.03 (a 3 % bias).
void expect_light_converges_to_path(
    const std::function<std::string(const std::string&, int, int)>& scene, int light_spp,
    int path_spp) {
    constexpr int kImages = 8;
    constexpr int kBlock = 4;
    const std::vector<uint8_t> mask = non_delta_mask(scene("path", 1, 1));
    const auto light =
        render_seeds([&](int seed) { return scene("light", light_spp, seed); }, kImages);
    const auto path =
        render_seeds([&](int seed) { return scene("path", path_spp, seed); }, kImages);
    const Comparison same = compare(light, path, mask, kBlock);
    const Comparison biased = compare(light, path, mask, kBlock, 1.03);
    fmt::print("light vs path: {}\nlight x 1.03 vs path: {}\n", same.describe(), biased.describe());
    ASSERT_GT(same.pixels, static_cast<int>(mask.size() / 4));
    EXPECT_TRUE(same.mse_agrees()) << same.describe();
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same.means_agree(c)) << "channel " << c;
    EXPECT_FALSE(biased.agrees()) << "a 3 % bias passes: " << biased.describe();
}

}  // namespace

// (a) The Cornell box: diffuse everywhere, the light seen directly (its one emitting side).
TEST(LightTracerSlow, ConvergesToPathOnTheCornellBox) {
    expect_light_converges_to_path(
        [](const std::string& integrator, int spp, int seed) {
            return example_with("cornell-box.lua",
                                fmt::format("width = 32, height = 32, spp = {}, seed = {}, "
                                            "integrator = '{}'",
                                            spp, seed, integrator));
        },
        128, 64);
}

// (b) A two-sided area light shines through a smooth glass slab onto a diffuse floor; the
// camera, under the slab, sees the floor directly (not through the glass), the slab's edge
// (masked out) and the light's lower side beside the slab. Light paths reach the floor
// through both faces of the slab (importance-mode refraction) and the two-sided light
// connects to the lens from the side sample_le chose.
TEST(LightTracerSlow, ConvergesToPathUnderAGlassSlab) {
    expect_light_converges_to_path(
        [](const std::string& integrator, int spp, int seed) {
            return fmt::format(R"(
                glint.camera{{ eye = {{0, 0.7, 3.5}}, look_at = {{0, 0.25, 0}}, fov = 60 }}
                glint.render{{ width = 32, height = 32, spp = {}, seed = {}, integrator = '{}' }}
                glint.quad{{ vertices = {{ {{-4, 0, 4}}, {{4, 0, 4}}, {{4, 0, -4}}, {{-4, 0, -4}} }},
                             material = glint.diffuse{{ reflectance = {{0.7, 0.6, 0.5}} }} }}
                glint.box{{ min = {{-1.2, 0.8, -1.2}}, max = {{1.2, 1.0, 1.2}},
                            material = glint.dielectric{{ ior = 1.5 }} }}
                glint.quad{{ vertices = {{ {{-0.8, 1.6, -0.8}}, {{0.8, 1.6, -0.8}}, {{0.8, 1.6, 0.8}},
                                           {{-0.8, 1.6, 0.8}} }},
                             material = glint.emissive{{ radiance = {{3, 2.5, 2}}, two_sided = true }} }}
            )",
                               spp, seed, integrator);
        },
        64, 256);
}

// (c) The Cornell box with a glass and a mirror sphere: the spheres are masked out, but
// the walls and floor keep the caustic and the light reflected off the mirror.
TEST(LightTracerSlow, ConvergesToPathOnTheCornellSpheres) {
    expect_light_converges_to_path(
        [](const std::string& integrator, int spp, int seed) {
            return example_with("cornell-spheres.lua",
                                fmt::format("width = 32, height = 32, spp = {}, seed = {}, "
                                            "integrator = '{}'",
                                            spp, seed, integrator));
        },
        128, 64);
}

// The caustic of a point light behind glass: invisible to the path tracer, seen by the light
// tracer and by SPPM, which must agree on it. SPPM is biased by its finite radius, which
// blurs the caustic (and the shadow's edge): over this region its mean moves by about 5 %
// between initial radii of 0.04 and 0.01 (0.099 -> 0.104 in red, 32 passes of 30000
// photons), so it may differ from the unbiased light tracer by 8 % of its value plus four
// standard errors of the difference.
TEST(LightTracerSlow, SeesThePointLightCausticBehindGlassLikeSppm) {
    constexpr int kImages = 6;
    const Vec3 light(0.0f, 2.0f, 0.0f);
    const std::vector<bool> mask = shadow_mask(point_light_behind_glass("spp = 1"), light);
    const int pixels = static_cast<int>(std::count(mask.begin(), mask.end(), true));
    ASSERT_GE(pixels, 50);
    auto render = [&](const std::string& settings) {
        return region_means(
            render_seeds(
                [&](int seed) {
                    return point_light_behind_glass(fmt::format("seed = {}, {}", seed, settings));
                },
                kImages),
            mask);
    };
    const auto path = render("spp = 16, integrator = 'path'");
    const auto light_traced = render("spp = 256, integrator = 'light'");
    const auto sppm =
        render("spp = 32, integrator = 'sppm', photons = 30000, photon_radius = 0.01");
    for (int c = 0; c < 3; ++c) {
        const double noise = 4.0 * std::hypot(light_traced[c].se, sppm[c].se);
        fmt::print(
            "channel {} over {} pixels: path {:.4g}, light {:.4g} +- {:.2g}, sppm {:.4g} "
            "+- {:.2g}\n",
            c, pixels, path[c].mean, light_traced[c].mean, light_traced[c].se, sppm[c].mean,
            sppm[c].se);
        EXPECT_NEAR(light_traced[c].mean, sppm[c].mean, noise + 0.08 * sppm[c].mean)
            << "channel " << c;
        // "Black" for the path tracer: what reaches the shadow by way of the ball's
        // reflection is below 1 % of the caustic.
        EXPECT_GT(light_traced[c].mean, 100.0 * path[c].mean) << "channel " << c;
        EXPECT_GT(sppm[c].mean, 100.0 * path[c].mean) << "channel " << c;
    }
}
