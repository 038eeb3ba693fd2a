// The classic ray tracer: agreement with the path tracer where both are exact, the soft
// shadow penumbra shortcut, and refraction through glass.
#include <glint/film/image.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

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
    )", settings);
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
    )", shortcut ? "true" : "false",
        occluder ? "glint.box{ min = {-4, 1, -4}, max = {0.3, 1.2, 4}, material = glint.diffuse{ reflectance = 0.5 } }" : "");
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

// The shortcut changes nothing where the light is wholly visible or wholly hidden.
TEST(Whitted, PenumbraShortcutIsExactInUmbraAndFullLight) {
    const Image full = render_lua(soft_shadow_scene(false, true));
    const Image fast = render_lua(soft_shadow_scene(true, true));
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
    fmt::print("umbra {}, lit {}, penumbra {}: mean error {:.4f}, largest {:.4f}\n", umbra, lit, penumbra,
               penumbra_error / std::max(penumbra, 1), penumbra_max);
    EXPECT_GT(lit, 50);
    ASSERT_GT(penumbra, 20);
    // docs/integrators.md states these bounds for a straight-edged occluder.
    EXPECT_LT(penumbra_error / penumbra, 0.002) << "mean penumbra error";
    EXPECT_LT(penumbra_max, 0.05) << "largest penumbra error";
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
        )", caustics ? "true" : "false");
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
