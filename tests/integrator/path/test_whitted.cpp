// The classic ray tracer: agreement with the path tracer where both are exact, the soft
// shadow penumbra shortcut, and refraction through glass.
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/path/whitted.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <cmath>

using namespace glint;
using glint::test::mean_channel;
using glint::test::render_lua;

namespace {

// A point light over a diffuse floor, a Phong block and a mirror, and no sky (the path
// tracer would gather it as indirect light); `settings` completes glint.render.
std::string point_lit_scene(const std::string& settings) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 2, 6}}, look_at = {{0, 0.5, 0}}, fov = 45 }}
        glint.render{{ width = 32, height = 24, spp = 4, {} }}
        glint.point_light{{ position = {{1, 4, 2}}, intensity = 20 }}
        glint.quad{{ vertices = {{ {{-5, 0, 5}}, {{5, 0, 5}}, {{5, 0, -5}}, {{-5, 0, -5}} }},
                     material = glint.diffuse{{ reflectance = 0.6 }} }}
        glint.box{{ min = {{0.5, 0, -0.5}}, max = {{1.5, 1, 0.5}}, material = glint.phong{{ diffuse = 0.5, specular = 0.3, exponent = 40 }} }}
        glint.box{{ min = {{-2, 0, -1}}, max = {{-0.5, 2, -0.9}}, material = glint.mirror{{}} }}
    )",
                       settings);
}

// A quad light over a floor with a large occluder casting umbra, penumbra and full light.
std::string soft_shadow_scene(bool shortcut, bool occluder) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 6, 0.01}}, look_at = {{0, 0, 0}}, fov = 60 }}
        glint.render{{ width = 48, height = 48, spp = 4, integrator = 'whitted', shadow_samples = 6,
                       penumbra_shortcut = {}, aovs = true }}
        glint.quad{{ vertices = {{ {{-5, 0, 5}}, {{5, 0, 5}}, {{5, 0, -5}}, {{-5, 0, -5}} }},
                     material = glint.diffuse{{ reflectance = 0.5 }} }}
        glint.quad{{ vertices = {{ {{-0.5, 3, -0.5}}, {{0.5, 3, -0.5}}, {{0.5, 3, 0.5}}, {{-0.5, 3, 0.5}} }},
                     material = glint.emissive{{ radiance = 20 }} }}
        {}
    )",
                       shortcut ? "true" : "false",
                       occluder ? "glint.box{ min = {-4, 1, -4}, max = {0.3, 1.2, 4}, material = "
                                  "glint.diffuse{ reflectance = 0.5 } }"
                                : "");
}

}  // namespace

// With a point light, diffuse, glossy and mirror surfaces and one scattering event both
// integrators compute the same sum, sample for sample.
TEST(Whitted, MatchesPathWhereBothAreExact) {
    const Image path = render_lua(point_lit_scene("integrator = 'path', max_depth = 1"));
    const Image whitted = render_lua(point_lit_scene("integrator = 'whitted', max_depth = 1"));
    const CompareResult r = compare_images(whitted, path);
    EXPECT_LT(r.rel_mse, 1e-10);
    EXPECT_GT(r.ref_mean[0], 0.01);  // not trivially black
}

// At one scattering event a mirror shows nothing (the floor it reflects is lit at the second
// vertex), so the test above compares black mirror pixels. With two, the mirror shows the lit
// floor and block, and both integrators compute the same sum there: mirror, then direct
// light at the surface seen in it. (Elsewhere the path tracer now adds one bounce of
// indirect light that Whitted's method has not.) Pixels wholly on the mirror's front face
// are those whose every sample's normal is +z and albedo 1 (the mirror's tint; the Phong
// block's front face, also facing +z, has albedo 0.8).
TEST(Whitted, MatchesPathInTheMirror) {
    const Image path =
        render_lua(point_lit_scene("integrator = 'path', max_depth = 2, aovs = true"));
    const Image whitted =
        render_lua(point_lit_scene("integrator = 'whitted', max_depth = 2, aovs = true"));
    const int albedo = whitted.channel_index("albedo.R"), nz = whitted.channel_index("normal.Z");
    ASSERT_GE(albedo, 0);
    ASSERT_GE(nz, 0);
    int mirror = 0, lit = 0;
    for (int y = 0; y < whitted.height; ++y) {
        for (int x = 0; x < whitted.width; ++x) {
            if (whitted.at(x, y, nz) != 1.0f || whitted.at(x, y, albedo) != 1.0f) continue;
            ++mirror;
            for (int c = 0; c < 3; ++c) {
                const float expected = path.at(x, y, c);
                EXPECT_NEAR(whitted.at(x, y, c), expected, 1e-5f * expected + 1e-7f)
                    << "mirror pixel " << x << ", " << y << " channel " << c;
            }
            lit += whitted.at(x, y, 1) > 0.05f;
        }
    }
    EXPECT_GT(mirror, 40);
    // The mirror's lower half shows the lit floor (its upper half the black sky): over 20 of
    // the compared pixels are clearly not black (all are black at max_depth = 1).
    EXPECT_GT(lit, 20) << lit << " of " << mirror << " mirror pixels lit";
}

// The ambient term adds exactly `ambient` times the albedo at each non-specular hit. Where
// every sample of a pixel hits the floor (albedo 0.6; no sample escapes, which the albedo
// channel would not count: the pixel and its eight neighbours all have normal +y), the
// difference between renders with and without it is ambient times the pixel's albedo
// channel, in light and in shadow alike.
TEST(Whitted, AmbientAddsAmbientTimesAlbedo) {
    // (A later key in a Lua table constructor wins: this is 96 x 72.)
    const std::string settings = "integrator = 'whitted', aovs = true, width = 96, height = 72";
    const Image plain = render_lua(point_lit_scene(settings));
    const Image ambient = render_lua(point_lit_scene(settings + ", ambient = {0.05, 0.1, 0.2}"));
    const int ny = plain.channel_index("normal.Y"), albedo = plain.channel_index("albedo.R");
    ASSERT_GE(ny, 0);
    ASSERT_GE(albedo, 0);
    const float added[3] = {0.05f, 0.1f, 0.2f};
    auto horizontal = [&](int x, int y) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int u = std::clamp(x + dx, 0, plain.width - 1);
                const int v = std::clamp(y + dy, 0, plain.height - 1);
                if (!(plain.at(u, v, ny) > 1.0f - 1e-6f)) return false;
            }
        }
        return true;
    };
    int checked = 0, shadowed = 0, wrong = 0;
    for (int y = 0; y < plain.height; ++y) {
        for (int x = 0; x < plain.width; ++x) {
            if (!horizontal(x, y)) continue;
            ++checked;
            shadowed += plain.at(x, y, 1) < 0.02f;
            for (int c = 0; c < 3; ++c) {
                const float expected = added[c] * plain.at(x, y, albedo + c);
                const float difference = ambient.at(x, y, c) - plain.at(x, y, c);
                if (std::abs(difference - expected) > 1e-5f && wrong++ < 5) {
                    ADD_FAILURE() << "pixel " << x << ", " << y << " channel " << c << ": added "
                                  << difference << ", expected " << expected;
                }
            }
        }
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(checked, 3000);
    EXPECT_GT(shadowed, 20);  // the shadows get the ambient term too
}

// The shortcut changes nothing where the light is wholly visible or wholly hidden.
TEST(Whitted, PenumbraShortcutIsExactInUmbraAndFullLight) {
    const auto [full, full_stats] =
        glint::test::render_lua_with_stats(soft_shadow_scene(false, true));
    const auto [fast, fast_stats] =
        glint::test::render_lua_with_stats(soft_shadow_scene(true, true));
    const Image unshadowed = render_lua(soft_shadow_scene(false, false));
    const int depth = full.channel_index("depth.Z");
    ASSERT_GE(depth, 0);
    int umbra = 0, lit = 0, penumbra = 0;
    double penumbra_error = 0.0, penumbra_max = 0.0;
    for (int y = 0; y < full.height; ++y) {
        for (int x = 0; x < full.width; ++x) {
            const float f = full.at(x, y, 0), s = fast.at(x, y, 0), open = unshadowed.at(x, y, 0);
            if (f == 0.0f) {
                EXPECT_EQ(s, 0.0f) << "umbra pixel " << x << ", " << y;
                ++umbra;
            } else if (f == open) {
                EXPECT_EQ(s, f) << "lit pixel " << x << ", " << y;
                ++lit;
            } else if (full.at(x, y, depth) > 5.5f) {  // the floor, not the occluder's top
                penumbra_error += std::abs(s - f) / open;
                penumbra_max = std::max(penumbra_max, std::abs(static_cast<double>(s - f)) / open);
                ++penumbra;
            }
        }
    }
    EXPECT_GT(umbra, 50);
    fmt::print("umbra {}, lit {}, penumbra {}: mean error {:.4f}, largest {:.4f}\n", umbra, lit,
               penumbra, penumbra_error / std::max(penumbra, 1), penumbra_max);
    EXPECT_GT(lit, 50);
    ASSERT_GT(penumbra, 20);
    // docs/integrators.md states these bounds for a straight-edged occluder.
    EXPECT_LT(penumbra_error / penumbra, 0.002) << "mean penumbra error";
    EXPECT_LT(penumbra_max, 0.05) << "largest penumbra error";

    // The point of the shortcut: umbra and fully lit points trace 4 shadow rays instead of
    // 6 x 6 = 36. With over half of the floor in umbra or full light, the shortcut must
    // trace well under 60 % of full sampling's rays (a setting that is ignored traces 100 %).
    fmt::print("rays: full sampling {}, shortcut {}\n", full_stats.rays, fast_stats.rays);
    EXPECT_LT(static_cast<double>(fast_stats.rays), 0.6 * static_cast<double>(full_stats.rays));
    // And the image as a whole is the same within a small fraction of its noise-free value.
    EXPECT_LT(compare_images(fast, full).rel_mse, 1e-4);
}

// Whitted follows both Fresnel branches exactly, so the glass slab test has no noise.
TEST(Whitted, GlassSlabTransmittance) {
    const Image image = render_lua(R"(
        glint.camera{ eye = {0, 0, 10}, look_at = {0, 0, 0}, fov = 2 }
        glint.render{ width = 4, height = 4, spp = 1, integrator = 'whitted', max_depth = 40 }
        glint.box{ min = {-100, -100, -1}, max = {100, 100, 0}, material = glint.dielectric{ ior = 1.5 } }
        glint.quad{ vertices = { {-500, -500, -5}, {500, -500, -5}, {500, 500, -5}, {-500, 500, -5} },
                    material = glint.emissive{ radiance = 1 } }
    )");
    const double R = std::pow(0.5 / 2.5, 2.0);
    const double expected = (1.0 - R) * (1.0 - R) / (1.0 - R * R);
    EXPECT_NEAR(mean_channel(image, 0, 0, 0, 4, 4), expected, 1e-4);
}

// The classic ray tracer cannot find light focused by glass onto a diffuse floor; with
// `caustics = true` the caustic photon map adds it, under the sphere where its shadow is.
TEST(Whitted, PhotonMappedCausticsBrightenTheShadowOfGlass) {
    auto scene = [](bool caustics) {
        return fmt::format(R"(
            glint.camera{{ eye = {{0, 6, 0.01}}, look_at = {{0, 0, 0}}, fov = 30 }}
            glint.render{{ width = 32, height = 32, spp = 4, integrator = 'whitted', caustics = {},
                           caustic_photons = 200000, photon_neighbours = 40 }}
            glint.quad{{ vertices = {{ {{-5, 0, 5}}, {{5, 0, 5}}, {{5, 0, -5}}, {{-5, 0, -5}} }},
                         material = glint.diffuse{{ reflectance = 0.7 }} }}
            glint.sphere{{ center = {{0, 1.5, 0}}, radius = 0.5, material = glint.dielectric{{ ior = 1.5 }} }}
            glint.point_light{{ position = {{0, 5, 0}}, intensity = 30 }}
        )",
                           caustics ? "true" : "false");
    };
    const Image plain = render_lua(scene(false));
    const Image with_caustics = render_lua(scene(true));
    // The centre of the image looks straight down through the sphere at its shadow.
    const double shadow_plain = mean_channel(plain, 1, 13, 13, 19, 19);
    const double shadow_caustic = mean_channel(with_caustics, 1, 13, 13, 19, 19);
    EXPECT_GT(shadow_caustic, shadow_plain + 0.5) << shadow_plain << " -> " << shadow_caustic;
    // Far from the sphere only the faint light the sphere reflects onto the floor is added.
    const double corner = mean_channel(plain, 1, 0, 0, 4, 4);
    EXPECT_NEAR(mean_channel(with_caustics, 1, 0, 0, 4, 4), corner, 0.02 * corner);
}

namespace {

// A glass ball inside a closed mirror sphere, with the camera, a point light and a small
// diffuse ball: every hit on the glass reflects and refracts, and every ray that leaves it
// comes back, so without the ray budget a camera sample traces about 2^(max_depth / 1.5)
// rays (70000 per sample at max_depth 24).
std::string closed_glass_scene(int max_depth) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 0.5, 3}}, look_at = {{0, 0, 0}}, fov = 60 }}
        glint.render{{ width = 4, height = 4, spp = 1, integrator = 'whitted', max_depth = {} }}
        glint.point_light{{ position = {{0, 3, 0}}, intensity = 10 }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 5, material = glint.mirror{{}} }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 1, material = glint.dielectric{{ ior = 1.5 }} }}
        glint.sphere{{ center = {{2.5, 0, 0}}, radius = 0.3, material = glint.diffuse{{ reflectance = 0.5 }} }}
    )",
                       max_depth);
}

}  // namespace

// The budget bounds the rays per camera sample: kWhittedRayBudget, plus at most one chain
// of max_depth rays for each branch still open when the budget ran out; each ray may add one
// shadow ray where it reaches the diffuse ball.
TEST(Whitted, ClosedGlassRaysPerSampleAreBounded) {
    for (int max_depth : {24, 64}) {
        const glint::test::RenderResult r =
            glint::test::render_lua_with_stats(closed_glass_scene(max_depth));
        ASSERT_EQ(r.stats.samples, 16u);
        const double rays_per_sample = static_cast<double>(r.stats.rays) / r.stats.samples;
        ASSERT_LE(rays_per_sample, 2 * (kWhittedRayBudget + max_depth * max_depth))
            << "max_depth " << max_depth;
        // Something is seen: the diffuse ball, directly or through glass and mirror.
        EXPECT_GT(mean_channel(r.image, 1, 0, 0, 4, 4), 0.0) << "max_depth " << max_depth;
        for (int y = 0; y < r.image.height; ++y) {
            for (int x = 0; x < r.image.width; ++x) {
                for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(r.image.at(x, y, c)));
            }
        }
    }
}
