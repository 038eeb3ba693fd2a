// The light tracer in participating media: single scattering from a point light matches its
// integral over the film (chromatic, anisotropic: the hero-channel weights and the phase
// function at the lens connection); a fog box lit from inside, with a glass sphere whose
// volumetric caustic both must see, converges to volpath's image; a light finds the medium
// around it; a glowing slab matches its closed form; the same bits for one and two threads
// (with a glowing gas too).
#include <glint/integrator/transport/media.h>
#include <glint/medium/henyey_greenstein.h>
#include <glint/scene/build.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/image_comparison.h>
#include <support/media_scenes.h>
#include <support/render_helpers.h>
#include <support/single_scattering.h>

#include <cmath>
#include <string>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kFilmSize = 8;

// A point light in an infinite medium the camera stands in, seen over the whole film, single
// scattering only (max_depth = 1): the image mean is the film average of
//   L(ray) = int_0^inf exp(-sigma_t t) sigma_s p(theta(t)) I exp(-sigma_t r(t)) / r(t)^2 dt.
std::string point_light_in_air(const Rgb& sigma_s, float sigma_a, float g, float intensity,
                               const Vec3& light, int spp, int seed) {
    return fmt::format(R"(
        local air = glint.medium{{ sigma_a = {}, sigma_s = {{{}, {}, {}}}, g = {} }}
        glint.camera{{ eye = {{0, 0, 0}}, look_at = {{0, 0, -1}}, fov = 30, medium = air }}
        glint.render{{ width = {}, height = {}, spp = {}, seed = {}, integrator = 'light',
                      max_depth = 1 }}
        glint.point_light{{ position = {{{}, {}, {}}}, intensity = {} }}
    )",
                       sigma_a, sigma_s.r, sigma_s.g, sigma_s.b, g, kFilmSize, kFilmSize, spp, seed,
                       light.x, light.y, light.z, intensity);
}

}  // namespace

TEST(LightTracerMedia, SingleScatteringFromAPointLightMatchesItsIntegral) {
    const Rgb sigma_s(0.1f, 0.5f, 2.0f);
    const float sigma_a = 0.1f, g = 0.3f, intensity = 10.0f;
    const Vec3 light(0.3f, 0.4f, -2.0f);
    auto scene = [&](int seed) {
        return point_light_in_air(sigma_s, sigma_a, g, intensity, light, 512, seed);
    };
    const BuiltScene built = build_lua(scene(0));
    for (int c = 0; c < 3; ++c) {
        const double s = c == 0 ? sigma_s.r : c == 1 ? sigma_s.g : sigma_s.b;
        const double exact = single_scattering_film_mean(
            built.scene->camera(), kFilmSize, s, s + sigma_a, g, intensity, light, 48, 4000);
        const Estimate e = image_mean(scene, 6, c);
        EXPECT_LT(4.0 * e.se, 0.05 * exact) << "channel " << c;
        EXPECT_NEAR(e.mean, exact, 4.0 * e.se + 0.005 * exact) << "channel " << c;
    }
}

// A slab of gas that absorbs and glows (no scattering, no light) seen straight through: each
// pixel is Le (1 - exp(-sigma_a d / cos theta)), its film mean found by integrating over the
// film. The light tracer sees it only through the paths that start in the gas
// (MediumEmitters: points uniform in the box the interface bounds).
TEST(LightTracerMedia, GlowingSlabMatchesItsClosedForm) {
    const float fov_degrees = 10.0f, sigma_a = 1.0f, depth = 1.0f;
    auto scene = [&](int seed) {
        return fmt::format(R"(
            local gas = glint.medium{{ sigma_a = {}, sigma_s = 0, emission = 1 }}
            glint.camera{{ eye = {{0, 0, 5}}, look_at = {{0, 0, 0}}, fov = {} }}
            glint.render{{ width = {}, height = {}, spp = 1024, seed = {}, integrator = 'light' }}
            glint.box{{ min = {{-1, -1, {}}}, max = {{1, 1, {}}},
                       material = glint.interface{{ interior = gas }} }}
        )",
                           sigma_a, fov_degrees, kFilmSize, kFilmSize, seed, -0.5f * depth,
                           0.5f * depth);
    };
    double exact = 0.0;
    const int n = 256;
    const double half = std::tan(0.5 * fov_degrees * kPi / 180.0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double x = (2.0 * (i + 0.5) / n - 1.0) * half,
                         y = (2.0 * (j + 0.5) / n - 1.0) * half;
            exact += 1.0 - std::exp(-sigma_a * depth * std::sqrt(1.0 + x * x + y * y));
        }
    }
    exact /= n * n;
    const Estimate e = image_mean(scene, 6, 0);
    EXPECT_LT(4.0 * e.se, 0.02 * exact);
    EXPECT_NEAR(e.mean, exact, 4.0 * e.se);
}

TEST(LightTracerMedia, FindsTheMediumAroundALight) {
    const BuiltScene built = build_lua(fog_box("light", 1, 1));
    const Scene& scene = *built.scene;
    ASSERT_EQ(scene.media().size(), 1u);
    const Medium* fog = scene.media()[0].get();
    EXPECT_EQ(medium_containing(scene, Vec3(0.0f, 1.9f, 0.0f)), fog);      // the lamp
    EXPECT_EQ(medium_containing(scene, Vec3(0.0f, 0.8f, 0.0f)), fog);      // inside the glass
    EXPECT_EQ(medium_containing(scene, Vec3(0.0f, 1.0f, 4.0f)), nullptr);  // the camera
    // Unbounded fog that the camera stands in fills everything outside closed media.
    const BuiltScene air =
        build_lua(point_light_in_air(Rgb(0.5f), 0.1f, 0.0f, 1.0f, Vec3(0.0f, 0.0f, -2.0f), 1, 1));
    EXPECT_EQ(medium_containing(*air.scene, Vec3(0.0f, 0.0f, -2.0f)), air.scene->media()[0].get());
}

// The fog, the floor through it and the caustic the sphere focuses: light tracing agrees
// with volpath over the pixels that do not see the glass itself (a specular vertex cannot
// connect to the lens), and rejects its own image scaled by 1.03.
TEST(LightTracerMediaSlow, ConvergesToVolpathInAFogBox) {
    constexpr int kImages = 6;
    constexpr int kBlock = 4;
    const std::vector<uint8_t> mask = non_delta_mask(fog_box("path", 1, 1));
    const auto light = render_seeds([](int seed) { return fog_box("light", 128, seed); }, kImages);
    const auto volpath =
        render_seeds([](int seed) { return fog_box("volpath", 512, seed); }, kImages);
    const Comparison same = compare(light, volpath, mask, kBlock);
    const Comparison biased = compare(light, volpath, mask, kBlock, 1.03);
    fmt::print("light vs volpath: {}\nlight x 1.03 vs volpath: {}\n", same.describe(),
               biased.describe());
    ASSERT_GT(same.pixels, static_cast<int>(mask.size() / 4));
    EXPECT_TRUE(same.mse_agrees()) << same.describe();
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same.means_agree(c)) << "channel " << c;
    EXPECT_FALSE(biased.agrees()) << "a 3 % bias passes: " << biased.describe();
}

// In spectral mode (the fog's coefficients uplifted at each path's wavelengths) the two agree
// on the image's means over the same pixels.
TEST(LightTracerMediaSlow, SpectralMeansAgreeWithVolpathInAFogBox) {
    constexpr int kImages = 4;
    const std::vector<uint8_t> mask = non_delta_mask(fog_box("path", 1, 1));
    const auto light =
        render_seeds([](int seed) { return fog_box("light", 64, seed, true); }, kImages);
    const auto volpath =
        render_seeds([](int seed) { return fog_box("volpath", 256, seed, true); }, kImages);
    const Comparison same = compare(light, volpath, mask, 4);
    fmt::print("spectral light vs volpath: {}\n", same.describe());
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same.means_agree(c)) << "channel " << c;
}

TEST(LightTracerMedia, SameBitsForOneAndTwoThreads) {
    const std::string glowing_gas = R"(
        local gas = glint.medium{ sigma_a = {1, 1.5, 2}, sigma_s = 0.6, emission = {2, 1, 0.4} }
        glint.camera{ eye = {0, 1, 4}, look_at = {0, 0.8, 0}, fov = 40 }
        glint.render{ width = 16, height = 16, spp = 48, integrator = 'light' }
        glint.sphere{ center = {0, 0.9, 0}, radius = 0.7,
                      material = glint.interface{ interior = gas } }
        glint.point_light{ position = {1, 2, 1}, intensity = 5 }
    )";
    for (const std::string& scene : {fog_box("light", 16, 3), glowing_gas}) {  // 3 chunks
        const Image one = render_lua(scene, 1);
        const Image two = render_lua(scene, 2);
        ASSERT_EQ(one.pixels.size(), two.pixels.size());
        EXPECT_TRUE(one.pixels == two.pixels);
    }
}
