// CSG solids in rendered images: a white furnace with a non-convex CSG solid (normals and
// sides of cut faces lose no energy), a CSG sphere that renders like the analytic sphere
// under a point light and an area light (shadows), and glass slabs made by CSG that
// transmit what the Fresnel series and Beer-Lambert predict.
#include <glint/film/image.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cmath>
#include <string>

using namespace glint;
using glint::test::mean_channel;
using glint::test::render_lua;

// A unit sphere with a bite out of the side facing the camera: the camera sees the convex
// outside and the concave cut face, whose normals are the subtracted sphere's turned
// around. In a uniform environment an albedo-1 diffuse solid must vanish, and so must a
// clear glass one: each path then carries exactly the background back, so any lost or
// gained energy shows. Glass is the sharper check of normals and sides: a path that
// leaves through a cut face taken for an entry is scaled by the radiance factor eta^2 of
// refraction twice in the same direction. (A two-sided diffuse surface does not care
// which way its normal points.)
TEST(CsgRender, WhiteFurnaceWithADifferenceDisappears) {
    for (const char* material :
         {"glint.diffuse{ reflectance = 1 }", "glint.dielectric{ ior = 1.5 }"}) {
        SCOPED_TRACE(material);
        const Image image = render_lua(fmt::format(R"(
            glint.background{{ radiance = {{0.5, 0.5, 0.5}} }}
            glint.camera{{ eye = {{0, 0, 4}}, look_at = {{0, 0, 0}}, fov = 30 }}
            glint.render{{ width = 24, height = 24, spp = 16, seed = 3 }}
            glint.add(glint.difference{{
                glint.solid.sphere{{ radius = 1 }},
                glint.solid.sphere{{ center = {{0.3, 0.2, 0.9}}, radius = 0.7 }},
                material = {} }})
        )",
                                                   material));
        int failures = 0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                for (int c = 0; c < 3; ++c) {
                    const double v = image.at(x, y, c);
                    if (std::abs(v - 0.5) > 0.005 && failures++ < 5)
                        ADD_FAILURE() << fmt::format("pixel ({}, {}) channel {}: {}", x, y, c, v);
                }
            }
        }
        EXPECT_EQ(failures, 0);
    }
}

namespace {

// A red ball on a floor, lit by a point light and a square area light above; `ball` is
// the statement that adds the ball.
std::string lit_ball(const std::string& integrator, int spp, const std::string& ball) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 2.5, 6}}, look_at = {{0, 0.6, 0}}, fov = 40 }}
        glint.render{{ width = 48, height = 32, spp = {}, seed = 5, integrator = "{}" }}
        local grey = glint.diffuse{{ reflectance = 0.6 }}
        local red = glint.diffuse{{ reflectance = {{0.8, 0.2, 0.2}} }}
        glint.quad{{ vertices = {{{{-6, 0, -6}}, {{-6, 0, 6}}, {{6, 0, 6}}, {{6, 0, -6}}}},
                     material = grey }}
        glint.point_light{{ position = {{2.5, 4, 1}}, intensity = 15 }}
        glint.quad{{ vertices = {{{{-2.5, 3, -1.5}}, {{-1.5, 3, -1.5}}, {{-1.5, 3, -0.5}},
                                  {{-2.5, 3, -0.5}}}},
                     material = glint.emissive{{ radiance = 8 }} }}
        {}
    )",
                       spp, integrator, ball);
}

const char* kPlainBall = "glint.sphere{ center = {0, 1, 0}, radius = 1, material = red }";
const char* kSolidBall =
    "glint.add(glint.solid.sphere{ center = {0, 1, 0}, radius = 1, material = red })";

}  // namespace

// The CSG sphere and the analytic sphere give the same image, shadows included. With
// Whitted's integrator (direct light only, stratified shadow rays) the same samples are
// drawn for both, so only silhouette pixels may differ; the path tracer's frames differ
// on the sphere, so its images agree only to their noise. Without the ball the image
// is far off, so the comparison has teeth.
TEST(CsgRender, SolidSphereRendersLikeTheAnalyticSphere) {
    struct Run {
        const char* integrator;
        int spp;
        double tolerance;
    };
    for (const Run& run : {Run{"whitted", 4, 1e-5}, Run{"path", 64, 1e-3}}) {
        SCOPED_TRACE(run.integrator);
        const Image plain = render_lua(lit_ball(run.integrator, run.spp, kPlainBall));
        const Image solid = render_lua(lit_ball(run.integrator, run.spp, kSolidBall));
        const Image empty = render_lua(lit_ball(run.integrator, run.spp, ""));
        EXPECT_LT(compare_images(solid, plain).rel_mse, run.tolerance);
        EXPECT_GT(compare_images(empty, plain).rel_mse, 0.05);
        // The ball's shadow: the floor just behind it (from the point light) is darker
        // than open floor in both images.
        for (const Image* image : {&plain, &solid}) {
            const double shade = mean_channel(*image, 1, 14, 24, 18, 28);
            const double open = mean_channel(*image, 1, 40, 24, 44, 28);
            EXPECT_LT(shade, 0.8 * open);
        }
    }
}

namespace {

// A slab in front of a uniform emitter, seen at normal incidence; `slab` adds it.
Image render_slab(const std::string& slab) {
    return render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 10}}, look_at = {{0, 0, 0}}, fov = 2 }}
        glint.render{{ width = 8, height = 8, spp = 1024, seed = 11 }}
        glint.quad{{ vertices = {{ {{-500, -500, -5}}, {{500, -500, -5}}, {{500, 500, -5}}, {{-500, 500, -5}} }},
                     material = glint.emissive{{ radiance = 1 }} }}
        {}
    )",
                                  slab));
}

const double kR = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);  // Fresnel at normal incidence

}  // namespace

// A CSG box of glass transmits (1-R)^2 (1 + R^2 + R^4 + ...) = (1-R)^2 / (1-R^2): the
// sides of its faces (entering or leaving the glass) must be right for that.
TEST(CsgRender, GlassSlabTransmittance) {
    const Image image = render_slab(R"(
        glint.add(glint.solid.box{ min = {-100, -100, -1}, max = {100, 100, 0},
                                   material = glint.dielectric{ ior = 1.5 } }))");
    const double expected = (1.0 - kR) * (1.0 - kR) / (1.0 - kR * kR);
    const double measured = mean_channel(image, 0, 0, 0, image.width, image.height);
    EXPECT_NEAR(measured, expected, 0.01 * expected);
}

// The same slab cut out of a thicker block by subtracting a second block: its back face
// is a subtracted surface, turned around. With absorption inside, each crossing multiplies
// by a = exp(-sigma d), giving (1-R)^2 a / (1 - R^2 a^2) only if every segment inside the
// glass is known to be inside.
TEST(CsgRender, TintedSlabCutByADifferenceFollowsBeerLambert) {
    const double sigma = 0.5, d = 1.0, a = std::exp(-sigma * d);
    const Image image = render_slab(R"(
        local glass = glint.dielectric{ ior = 1.5, absorption = 0.5 }
        glint.add(glint.difference{
            glint.solid.box{ min = {-100, -100, -3}, max = {100, 100, 0} },
            glint.solid.box{ min = {-200, -200, -4}, max = {200, 200, -1} },
            material = glass }))");
    const double expected = (1.0 - kR) * (1.0 - kR) * a / (1.0 - kR * kR * a * a);
    const double measured = mean_channel(image, 1, 0, 0, image.width, image.height);
    EXPECT_NEAR(measured, expected, 0.01 * expected);
}
