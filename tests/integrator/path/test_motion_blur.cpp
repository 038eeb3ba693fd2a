// Motion blur through the path tracer: a moving sphere (and its moving shadow) renders as
// the average of still renders at uniformly drawn times; a still scene with a shutter
// renders bit for bit as without; a spinning square's blur at a ring of pixels matches
// the fraction of the shutter it covers them (slerp turns it at a constant rate);
// integrators that cannot carry a path's time refuse moving scenes, and moving emitters
// and malformed motion are errors naming the line.
#include <glint/core/error.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

using namespace glint;
using test::render_lua;

namespace {

// A sphere moving right and up over the times [0, 1] above a floor it shadows, lit by a
// point light and a uniform sky; `camera_extra` adds to glint.camera, `sphere_motion`
// replaces the sphere's motion keys.
std::string moving_sphere(const std::string& camera_extra, int seed, int spp,
                          const std::string& integrator = "path") {
    return fmt::format(R"(
glint.camera{{ eye = {{0, 1, 5}}, look_at = {{0, 0, 0}}, fov = 32{} }}
glint.render{{ width = 24, height = 24, spp = {}, seed = {}, max_depth = 2,
               integrator = "{}" }}
glint.background{{ radiance = {{0.4, 0.5, 0.6}} }}
glint.point_light{{ position = {{1, 4, 3}}, intensity = 20 }}
local red = glint.diffuse{{ reflectance = {{0.8, 0.3, 0.2}} }}
local grey = glint.diffuse{{ reflectance = 0.5 }}
glint.quad{{ vertices = {{{{-3, -0.6, -3}}, {{-3, -0.6, 3}}, {{3, -0.6, 3}}, {{3, -0.6, -3}}}},
             material = grey }}
glint.sphere{{ radius = 0.5, material = red,
               motion = {{ glint.translate(-0.7, 0, 0), glint.translate(0.7, 0.4, 0) }} }}
)",
                       camera_extra, spp, seed, integrator);
}

struct BlockStats {
    std::vector<double> mean, variance_of_mean;  // per block and channel
};

// Means of 6 x 6 pixel blocks over K renders, and the variance of their average over the
// renders (from the renders' own spread): the noise the comparison's bound comes from.
BlockStats block_stats(const std::vector<Image>& images) {
    const int blocks = images.front().width / 6;
    const double k = static_cast<double>(images.size());
    BlockStats stats;
    for (int by = 0; by < blocks; ++by) {
        for (int bx = 0; bx < blocks; ++bx) {
            for (int c = 0; c < 3; ++c) {
                std::vector<double> values;
                for (const Image& image : images)
                    values.push_back(
                        test::mean_channel(image, c, bx * 6, by * 6, bx * 6 + 6, by * 6 + 6));
                double sum = 0.0, sum_squares = 0.0;
                for (double v : values) {
                    sum += v;
                    sum_squares += v * v;
                }
                const double mean = sum / k;
                stats.mean.push_back(mean);
                stats.variance_of_mean.push_back((sum_squares / k - mean * mean) / (k - 1.0));
            }
        }
    }
    return stats;
}

// The largest |difference| / standard error over the blocks.
double largest_z(const BlockStats& a, const BlockStats& b) {
    double largest = 0.0;
    for (size_t i = 0; i < a.mean.size(); ++i) {
        const double se = std::sqrt(a.variance_of_mean[i] + b.variance_of_mean[i]);
        largest = std::max(largest, std::abs(a.mean[i] - b.mean[i]) / std::max(se, 1e-9));
    }
    return largest;
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

}  // namespace

// K blurred renders (seeds 1..K) against K stills at times drawn uniformly: both are K
// independent estimates of each block's time-averaged radiance. For the path tracer, and for
// the viewer's preview (direct light and its ambient term: the scene has no caustics, where
// its photons of every time would meet camera rays of another).
class MotionBlurStills : public ::testing::TestWithParam<std::string> {};

TEST_P(MotionBlurStills, MovingSphereIsTheAverageOfStillsAtDrawnTimes) {
    const std::string integrator = GetParam();
    if (test::kSanitizerBuild && integrator == "preview")
        GTEST_SKIP()
            << "36 preview renders take 20 s under the sanitizers: the normal tree runs it";
    constexpr int kRenders = 12;
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<Image> blurred, stills, at_opening;
    for (int k = 0; k < kRenders; ++k) {
        blurred.push_back(render_lua(moving_sphere(", shutter = {0, 1}", k + 1, 16, integrator)));
        const float t = uniform(rng);
        stills.push_back(render_lua(
            moving_sphere(fmt::format(", shutter = {{{0}, {0}}}", t), k + 101, 16, integrator)));
        at_opening.push_back(render_lua(moving_sphere("", k + 201, 16, integrator)));
    }
    const BlockStats blurred_stats = block_stats(blurred);
    // 48 block-channel comparisons of two 12-render means: 5 standard errors.
    EXPECT_LT(largest_z(blurred_stats, block_stats(stills)), 5.0);
    // The comparison can fail: the sphere held at its opening position is far off.
    EXPECT_GT(largest_z(blurred_stats, block_stats(at_opening)), 10.0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, MotionBlurStills, ::testing::Values("path", "preview"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

TEST(MotionBlur, BlurredImageIsTheSameForAnyThreadCount) {
    const std::string scene = moving_sphere(", shutter = {0, 1}", 3, 8);
    EXPECT_TRUE(same_pixels(render_lua(scene, 1), render_lua(scene, 2)));
    EXPECT_TRUE(same_pixels(render_lua(scene, 1), render_lua(scene, 3)));
}

TEST(MotionBlur, StillSceneWithAShutterIsBitIdentical) {
    const std::string scene = R"(
glint.camera{ eye = {0, 1, 5}, look_at = {0, 0, 0}, fov = 32 SHUTTER }
glint.render{ width = 20, height = 16, spp = 8, max_depth = 3, sampler = "SAMPLER" }
glint.point_light{ position = {1, 4, 3}, intensity = 20 }
glint.quad{ vertices = {{-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}},
            material = glint.emissive{ radiance = 4 } }
local m = glint.diffuse{ reflectance = {0.8, 0.3, 0.2} }
local g = glint.group()
g:sphere{ radius = 0.5, material = m }
glint.place(g, glint.translate(0.3, 0, 0))
glint.box{ min = {-2, -1, -2}, max = {2, -0.6, 2}, material = m }
)";
    for (const std::string sampler : {"independent", "stratified", "sobol"}) {
        const auto with = [&](const std::string& shutter) {
            std::string code = scene;
            code.replace(code.find("SHUTTER"), 7, shutter);
            code.replace(code.find("SAMPLER"), 7, sampler);
            return code;
        };
        const Image without_shutter = render_lua(with(""));
        EXPECT_TRUE(same_pixels(render_lua(with(", shutter = {0, 1}")), without_shutter))
            << sampler;
        EXPECT_TRUE(same_pixels(render_lua(with(", shutter = {0.3, 0.8}")), without_shutter))
            << sampler;
    }
}

namespace {

// A grey (0.5) shape under a white sky, `shape` (Lua), moving over the shutter {0, 1}, seen
// from above by an orthographic camera 2.4 units high at `size` x `size` pixels and `spp`
// samples: each pixel whose centre (x, y) `measured` selects must see 1 - 0.5 c, with c the
// fraction of the pixel and of the shutter that the shape covers, `covers(x, y, t)`
// averaged on a fine grid.
void expect_covered_fraction(const std::string& shape, int size, int spp,
                             const std::function<bool(float, float)>& measured,
                             const std::function<bool(float, float, float)>& covers) {
    constexpr float kHeight = 2.4f;
    const Image image = render_lua(fmt::format(R"(
glint.camera{{ type = "orthographic", eye = {{0, 0, 5}}, look_at = {{0, 0, 0}}, scale = {},
               shutter = {{0, 1}} }}
glint.render{{ width = {}, height = {}, spp = {}, max_depth = 1, filter = "box" }}
glint.background{{ radiance = 1 }}
local grey = glint.diffuse{{ reflectance = 0.5 }}
{}
)",
                                               kHeight, size, size, spp, shape));
    const float pixel = kHeight / static_cast<float>(size);
    double worst = 0.0, sum_error = 0.0;
    int count = 0;
    for (int py = 0; py < size; ++py) {
        for (int px = 0; px < size; ++px) {
            const float cx = (px + 0.5f) * pixel - 0.5f * kHeight;
            const float cy = 0.5f * kHeight - (py + 0.5f) * pixel;
            if (!measured(cx, cy)) continue;
            int covered = 0, total = 0;
            for (int sy = 0; sy < 8; ++sy)
                for (int sx = 0; sx < 8; ++sx)
                    for (int t = 0; t < 300; ++t, ++total)
                        covered += covers(cx + ((sx + 0.5f) / 8 - 0.5f) * pixel,
                                          cy - ((sy + 0.5f) / 8 - 0.5f) * pixel, (t + 0.5f) / 300);
            const double expected = 1.0 - 0.5 * covered / total;
            const double error = image.at(px, py, 1) - expected;
            worst = std::max(worst, std::abs(error));
            sum_error += error;
            ++count;
        }
    }
    ASSERT_GT(count, 100);
    // Each sample is 0.5 or 1: standard deviation at most 0.25 (stratified time and pixel
    // positions only lower it), so a pixel's mean is within 0.25 / sqrt(spp) per standard
    // error; 5 of them per pixel, and 5 for the measured pixels' mean error.
    const double se = 0.25 / std::sqrt(static_cast<double>(spp));
    EXPECT_LT(worst, 5.0 * se);
    EXPECT_LT(std::abs(sum_error / count), 5.0 * se / std::sqrt(static_cast<double>(count)));
}

}  // namespace

TEST(MotionBlur, SpinningSquareMatchesTheCoveredFractionOfTheShutter) {
    // The square [0, 1] x [-1, 1] turns about the view axis by 150 degrees over the shutter
    // (slerp turns it at a constant rate); the pixels at radius 0.85 are inside its reach at
    // every angle.
    constexpr float kTurn = 150.0f, kPixel = 2.4f / 48;
    expect_covered_fraction(
        fmt::format("glint.quad{{ vertices = {{{{0, -1, 0}}, {{1, -1, 0}}, {{1, 1, 0}}, "
                    "{{0, 1, 0}}}}, material = grey, motion = {{ glint.rotate(0, {{0, 0, 1}}), "
                    "glint.rotate({}, {{0, 0, 1}}) }} }}",
                    kTurn),
        48, 512,
        [&](float x, float y) { return std::abs(std::hypot(x, y) - 0.85f) <= 0.5f * kPixel; },
        [&](float x, float y, float t) {
            const float a = -kTurn * t * std::numbers::pi_v<float> / 180.0f;
            const float u = std::cos(a) * x - std::sin(a) * y;
            const float v = std::sin(a) * x + std::cos(a) * y;
            return u >= 0.0f && u <= 1.0f && std::abs(v) <= 1.0f;
        });
}

TEST(MotionBlur, IntegratorsWithoutTimeRefuseMovingScenes) {
    for (const char* integrator : {"radiosity"}) {
        try {
            render_lua(moving_sphere(", shutter = {0, 1}", 1, 1, integrator));
            ADD_FAILURE() << integrator << " rendered a moving scene";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("moving"), std::string::npos) << e.what();
        }
    }
    // A still scene renders with them as before.
    EXPECT_NO_THROW(render_lua(R"(
glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0}, shutter = {0, 1} }
glint.render{ width = 8, height = 8, spp = 1, integrator = "radiosity" }
glint.point_light{ position = {1, 4, 3}, intensity = 20 }
glint.sphere{ radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
)"));
}

namespace {

// The moving sphere lit by an area light alone (light paths start at lights; the sky of
// moving_sphere is a background, which they cannot start from).
std::string moving_sphere_under_a_lamp(const std::string& integrator, const std::string& shutter,
                                       int seed, int spp, const std::string& camera_motion = "") {
    return fmt::format(R"(
glint.camera{{ eye = {{0, 1, 5}}, look_at = {{0, 0, 0}}, fov = 32, shutter = {} {} }}
glint.render{{ width = 24, height = 24, spp = {}, seed = {}, max_depth = 3,
               integrator = "{}" }}
glint.quad{{ vertices = {{{{-1, 3, -1}}, {{1, 3, -1}}, {{1, 3, 1}}, {{-1, 3, 1}}}},
             material = glint.emissive{{ radiance = 4 }} }}
glint.quad{{ vertices = {{{{-3, -0.6, -3}}, {{-3, -0.6, 3}}, {{3, -0.6, 3}}, {{3, -0.6, -3}}}},
             material = glint.diffuse{{ reflectance = 0.5 }} }}
glint.sphere{{ radius = 0.5, material = glint.diffuse{{ reflectance = {{0.8, 0.3, 0.2}} }},
               motion = {{ glint.translate(-0.7, 0, 0), glint.translate(0.7, 0.4, 0) }} }}
)",
                       shutter, camera_motion, spp, seed, integrator);
}

}  // namespace

// Light paths carry one time each, the camera subpath's where one joins them: the blurred
// sphere and its shadow of every method that traces light paths agree with the path
// tracer's, block by block, and the sphere held at its opening position does not. With a
// moving camera too: light paths join the lens where the camera stands at their time.
class MotionBlurLightPathsSlow : public ::testing::TestWithParam<std::string> {};

// `integrator`'s blurred images of the moving sphere (the camera moved by `camera_motion`)
// agree with path's, block by block, and its images with the sphere held at its opening
// position do not.
void expect_blur_agrees_with_path(const std::string& integrator, const std::string& camera_motion) {
    constexpr int kRenders = 8;
    std::vector<Image> moving, path, still;
    for (int k = 0; k < kRenders; ++k) {
        const auto render = [&](const std::string& with, const char* shutter, int seed) {
            return render_lua(moving_sphere_under_a_lamp(with, shutter, seed, 16, camera_motion));
        };
        moving.push_back(render(integrator, "{0, 1}", k + 1));
        path.push_back(render("path", "{0, 1}", k + 101));
        still.push_back(render(integrator, "{0, 0}", k + 201));
    }
    EXPECT_LT(largest_z(block_stats(moving), block_stats(path)), 5.0);
    EXPECT_GT(largest_z(block_stats(still), block_stats(path)), 10.0);
}

TEST_P(MotionBlurLightPathsSlow, AgreeWithPathOnAMovingSphere) {
    expect_blur_agrees_with_path(GetParam(), "");
}

TEST_P(MotionBlurLightPathsSlow, AgreeWithPathThroughAMovingCamera) {
    expect_blur_agrees_with_path(GetParam(),
                                 ", motion = { glint.translate(-0.4, 0, 0), "
                                 "glint.rotate(8, {0, 1, 0}) * glint.translate(0.4, 0.1, 0) }");
}

INSTANTIATE_TEST_SUITE_P(Integrators, MotionBlurLightPathsSlow,
                         ::testing::Values("light", "bdpt", "vcm", "mlt", "photon"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

// A camera whose motion scales it would need densities on the lens that change with time:
// the methods that join light paths to the lens refuse it, naming the setting.
TEST(MotionBlur, LightPathsRefuseACameraMotionThatScales) {
    for (const char* integrator : {"light", "bdpt", "vcm", "mlt"}) {
        try {
            render_lua(moving_sphere_under_a_lamp(
                integrator, "{0, 1}", 1, 1,
                ", motion = { glint.scale(1, 1, 1), glint.scale(1.5, 1.5, 1.5) }"));
            ADD_FAILURE() << integrator << " rendered a camera motion that scales";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("scale"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(integrator), std::string::npos) << e.what();
        }
    }
}

TEST(MotionBlur, MalformedMotionIsAnErrorNamingTheLine) {
    const std::string head = "glint.camera{ shutter = {0, 1} }\n";
    const auto message_of = [&](const std::string& line) {
        try {
            render_lua(head + line);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string one_key = message_of(
        "glint.sphere{ radius = 1, material = glint.diffuse{}, "
        "motion = { glint.translate(1, 0, 0) } }");
    EXPECT_NE(one_key.find(":2:"), std::string::npos) << one_key;
    EXPECT_NE(one_key.find("motion"), std::string::npos) << one_key;
    const std::string not_transform =
        message_of("glint.place(glint.group(), { glint.translate(1, 0, 0), 3 })");
    EXPECT_NE(not_transform.find(":2:"), std::string::npos) << not_transform;
    const std::string too_many = message_of(
        "local keys = {} for i = 1, 130 do keys[i] = glint.translate(i, 0, 0) end "
        "glint.place(glint.group(), keys)");
    EXPECT_NE(too_many.find(":2:"), std::string::npos) << too_many;
    EXPECT_NE(too_many.find("129"), std::string::npos) << too_many;
    const std::string emitter = message_of(
        "glint.sphere{ radius = 1, material = glint.emissive{ radiance = 1 }, "
        "motion = { glint.translate(0, 0, 0), glint.translate(1, 0, 0) } }");
    EXPECT_NE(emitter.find(":2:"), std::string::npos) << emitter;
    EXPECT_NE(emitter.find("cannot move"), std::string::npos) << emitter;
}

// Deformation blur: a quad whose right edge sweeps from x = 0.2 to x = 1 over the shutter
// (vertex keys), seen from above: a pixel at x is covered while the edge is past it, a
// fraction 1 - (x - 0.2) / 0.8 of the shutter, and sees 1 - 0.5 c as the spinning square.
TEST(MotionBlur, DeformingMeshMatchesTheCoveredFractionOfTheShutter) {
    constexpr float kPixel = 2.4f / 40;
    expect_covered_fraction(
        "glint.mesh{ vertices = {{0, -1, 0}, {0.2, -1, 0}, {0.2, 1, 0}, {0, 1, 0}}, "
        "indices = {1, 2, 3, 1, 3, 4}, "
        "vertex_keys = { {0, -1, 0,  1, -1, 0,  1, 1, 0,  0, 1, 0} }, material = grey }",
        40, 512,
        // Pixels wholly inside the band the edge sweeps, away from the top and bottom.
        [&](float x, float y) {
            return x - 0.5f * kPixel >= 0.2f && x + 0.5f * kPixel <= 1.0f && std::abs(y) <= 0.8f;
        },
        [](float x, float, float t) { return x <= 0.2f + 0.8f * t; });
}

// A mesh whose keys translate every vertex blurs as the same mesh moved by motion keys.
TEST(MotionBlur, DeformingMeshAgreesWithTheSameRigidMotion) {
    const auto scene = [](bool deform, int seed) {
        const std::string motion =
            deform ? "vertex_keys = { { 0.6, -0.5, 0,  1.6, -0.5, 0,  1.6, 0.5, 0,  0.6, 0.5, 0,"
                     "  0.6, -0.5, 1,  1.6, -0.5, 1,  1.6, 0.5, 1,  0.6, 0.5, 1 } }"
                   : "motion = { glint.translate(0, 0, 0), glint.translate(1.2, 0, 0) }";
        return fmt::format(R"(
glint.camera{{ eye = {{0, 1, 5}}, look_at = {{0, 0, 0}}, fov = 32, shutter = {{0, 1}} }}
glint.render{{ width = 24, height = 24, spp = 16, seed = {}, max_depth = 2 }}
glint.background{{ radiance = {{0.4, 0.5, 0.6}} }}
glint.point_light{{ position = {{1, 4, 3}}, intensity = 20 }}
glint.quad{{ vertices = {{{{-3, -0.6, -3}}, {{-3, -0.6, 3}}, {{3, -0.6, 3}}, {{3, -0.6, -3}}}},
             material = glint.diffuse{{ reflectance = 0.5 }} }}
-- Two faces of a slab, as one mesh.
glint.mesh{{ vertices = {{{{-0.6, -0.5, 0}}, {{0.4, -0.5, 0}}, {{0.4, 0.5, 0}}, {{-0.6, 0.5, 0}},
                          {{-0.6, -0.5, 1}}, {{0.4, -0.5, 1}}, {{0.4, 0.5, 1}}, {{-0.6, 0.5, 1}}}},
             indices = {{1, 2, 3, 1, 3, 4, 5, 7, 6, 5, 8, 7}}, {},
             material = glint.diffuse{{ reflectance = {{0.8, 0.3, 0.2}} }} }}
)",
                           seed, motion);
    };
    // The rigid motion's keys translate by 1.2, the vertex keys by 1.2 in x too (and the
    // second face stays 1 behind the first): the same sweep.
    std::vector<Image> deformed, rigid;
    for (int k = 0; k < 8; ++k) {
        deformed.push_back(render_lua(scene(true, k + 1)));
        rigid.push_back(render_lua(scene(false, k + 101)));
    }
    EXPECT_LT(largest_z(block_stats(deformed), block_stats(rigid)), 5.0);
}

TEST(MotionBlur, MalformedVertexKeysAreErrorsNamingTheLine) {
    const auto message_of = [](const std::string& extra) {
        try {
            render_lua(
                "glint.camera{ shutter = {0, 1} }\n"
                "glint.mesh{ vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "
                "indices = {1, 2, 3}, " +
                extra + " }");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string grey = "material = glint.diffuse{}, ";
    const std::string short_key = message_of(grey + "vertex_keys = { {0, 0, 0, 1, 0, 0} }");
    EXPECT_NE(short_key.find(":2:"), std::string::npos) << short_key;
    EXPECT_NE(short_key.find("need 9"), std::string::npos) << short_key;
    const std::string with_normals = message_of(
        grey +
        "normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, vertex_keys = { {0, 0, 0, 1, 0, 0, 0, 1, 1} "
        "}");
    EXPECT_NE(with_normals.find("normals"), std::string::npos) << with_normals;
    EXPECT_NE(with_normals.find(":2:"), std::string::npos) << with_normals;
    const std::string emitting = message_of(
        "material = glint.emissive{ radiance = 1 }, vertex_keys = { {0, 0, 0, 1, 0, 0, 0, 1, 1} "
        "}");
    EXPECT_NE(emitting.find("deform"), std::string::npos) << emitting;
    EXPECT_NE(emitting.find(":2:"), std::string::npos) << emitting;
}
