// glTF animation: keyframe curves interpolated as the specification says (STEP, LINEAR with
// slerp for rotations, CUBICSPLINE Hermite), and a file's animated node imported as motion
// keys over the import's time window, or as a still pose at one time. The file is a small
// glTF JSON written by the test: a quad, and a node that moves it.
#include <glint/scene/import/import.h>
#include <glint/scene/import/keyframe_curve.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <fstream>
#include <string>

using namespace glint;

namespace {

KeyframeCurve curve(KeyframeCurve::Interpolation interpolation, int components,
                    std::vector<float> times, std::vector<float> values) {
    KeyframeCurve c;
    c.interpolation = interpolation;
    c.components = components;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

}  // namespace

TEST(KeyframeCurve, StepLinearAndClampedOutsideTheKeys) {
    using I = KeyframeCurve::Interpolation;
    const KeyframeCurve linear = curve(I::kLinear, 3, {1, 3}, {0, 0, 0, 4, 2, -2});
    float v[4];
    linear.evaluate(2.5f, v);
    EXPECT_FLOAT_EQ(v[0], 3.0f);
    EXPECT_FLOAT_EQ(v[1], 1.5f);
    EXPECT_FLOAT_EQ(v[2], -1.5f);
    linear.evaluate(0.0f, v);  // before the first key: its value
    EXPECT_FLOAT_EQ(v[0], 0.0f);
    linear.evaluate(9.0f, v);  // after the last: its value
    EXPECT_FLOAT_EQ(v[0], 4.0f);
    const KeyframeCurve step = curve(I::kStep, 3, {1, 3}, {0, 0, 0, 4, 2, -2});
    step.evaluate(2.9f, v);
    EXPECT_FLOAT_EQ(v[0], 0.0f);
    step.evaluate(3.0f, v);
    EXPECT_FLOAT_EQ(v[0], 4.0f);
}

TEST(KeyframeCurve, RotationsTurnAtAConstantRateTheShortWay) {
    using I = KeyframeCurve::Interpolation;
    const float s = std::sqrt(0.5f);
    // Identity to 90 degrees about y; the second key written as -q (the same rotation):
    // slerp must still take the short way, through 45 degrees.
    const KeyframeCurve turn = curve(I::kLinear, 4, {0, 1}, {0, 0, 0, 1, 0, -s, 0, -s});
    for (float t : {0.25f, 0.5f, 0.75f}) {
        float q[4];
        turn.evaluate(t, q);
        const glm::quat rotation(q[3], q[0], q[1], q[2]);
        EXPECT_NEAR(glm::length(rotation), 1.0f, 1e-6f);
        const float angle = glm::degrees(2.0f * std::acos(std::min(1.0f, std::abs(q[3]))));
        EXPECT_NEAR(angle, 90.0f * t, 1e-3f) << "at " << t;
    }
}

TEST(KeyframeCurve, CubicSplineFollowsTheHermiteCurve) {
    using I = KeyframeCurve::Interpolation;
    // One component (in x): values 0 and 1 at times 0 and 2, out-tangent 3 at the first key,
    // in-tangent -1 at the second (per second). Stored as (in, value, out) per key.
    const KeyframeCurve cubic =
        curve(I::kCubicSpline, 3, {0, 2}, {9, 9, 9, 0, 0, 0, 3, 0, 0, -1, 0, 0, 1, 0, 0, 9, 9, 9});
    const auto hermite = [](float u) {
        const float dt = 2.0f;
        return (u * u * u - 2 * u * u + u) * dt * 3.0f + (-2 * u * u * u + 3 * u * u) * 1.0f +
               (u * u * u - u * u) * dt * -1.0f;
    };
    for (float t : {0.0f, 0.5f, 1.0f, 1.5f, 2.0f}) {
        float v[3];
        cubic.evaluate(t, v);
        EXPECT_NEAR(v[0], hermite(t / 2.0f), 1e-5f) << "at " << t;
        EXPECT_NEAR(v[1], 0.0f, 1e-6f);
    }
}

TEST(KeyframeCurve, MalformedCurvesAreNamed) {
    using I = KeyframeCurve::Interpolation;
    const char* reason = nullptr;
    EXPECT_FALSE(curve(I::kLinear, 3, {0, 1}, {0, 0, 0}).valid(&reason));
    EXPECT_NE(std::string(reason).find("number of values"), std::string::npos);
    EXPECT_FALSE(curve(I::kLinear, 3, {1, 1}, {0, 0, 0, 1, 1, 1}).valid(&reason));
    EXPECT_NE(std::string(reason).find("increase"), std::string::npos);
    EXPECT_FALSE(curve(I::kCubicSpline, 3, {0, 1}, {0, 0, 0, 1, 1, 1}).valid(&reason));
    EXPECT_TRUE(curve(I::kLinear, 3, {0, 1}, {0, 0, 0, 1, 1, 1}).valid(&reason));
}

namespace {

// The quad of test_gltf_extensions.cpp (60 bytes), and an animation buffer: times {0, 1},
// translations {0, 0, 0} and {2, 0, 0}, rotations identity and 90 degrees about y (64 bytes).
const char* kQuadBuffer =
    "data:application/octet-stream;base64,"
    "AACAvwAAAAAAAIC/AACAvwAAAAAAAIA/AACAPwAAAAAAAIA/AACAPwAAAAAAAIC/AAABAAIAAAACAAMA";
const char* kAnimationBuffer =
    "data:application/octet-stream;base64,"
    "AAAAAAAAgD8AAAAAAAAAAAAAAAAAAABAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAIA/AAAAAPMENT8AAAAA8wQ1Pw==";

// A quad on a node that the first animation moves (`channels`, JSON) and a still copy.
std::string animated_gltf(const std::string& channels) {
    return fmt::format(R"({{
  "asset": {{"version": "2.0"}},
  "buffers": [{{"byteLength": 60, "uri": "{quad}"}}, {{"byteLength": 64, "uri": "{animation}"}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                  {{"buffer": 0, "byteOffset": 48, "byteLength": 12}},
                  {{"buffer": 1, "byteOffset": 0, "byteLength": 8}},
                  {{"buffer": 1, "byteOffset": 8, "byteLength": 24}},
                  {{"buffer": 1, "byteOffset": 32, "byteLength": 32}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
      "min": [-1, 0, -1], "max": [1, 0, 1]}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}},
    {{"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
      "min": [0], "max": [1]}},
    {{"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"}},
    {{"bufferView": 4, "componentType": 5126, "count": 2, "type": "VEC4"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1}}]}}],
  "nodes": [{{"mesh": 0, "translation": [0, 5, 0]}}, {{"mesh": 0, "translation": [0, -3, 0]}}],
  "animations": [{{"name": "slide", "samplers": [
      {{"input": 2, "output": 3, "interpolation": "LINEAR"}},
      {{"input": 2, "output": 4, "interpolation": "LINEAR"}}],
    "channels": [{channels}]}}],
  "scenes": [{{"nodes": [0, 1]}}]
}})",
                       fmt::arg("quad", kQuadBuffer), fmt::arg("animation", kAnimationBuffer),
                       fmt::arg("channels", channels));
}

const char* kSlide = R"({"sampler": 0, "target": {"node": 0, "path": "translation"}})";
const char* kTurn = R"({"sampler": 1, "target": {"node": 0, "path": "rotation"}})";

SceneDesc import(const test::TempDir& dir, const std::string& json, const std::string& options) {
    std::ofstream(dir.file("model.gltf")) << json;
    return load_scene_string(fmt::format("glint.import{{ file = 'model.gltf'{} }}", options),
                             "scene.lua", dir.file(""));
}

// The moving placements of the import: instances with motion keys.
std::vector<const InstanceDesc*> moving(const SceneDesc& desc) {
    std::vector<const InstanceDesc*> found;
    for (const InstanceDesc& instance : desc.groups[0].instances)
        if (!instance.motion.empty()) found.push_back(&instance);
    return found;
}

Vec3 translation_of(const Transform& xf) {
    return Vec3(xf.matrix()[3]);
}

}  // namespace

TEST(GltfAnimation, AnimatedNodeBecomesMotionKeysOverTheWindow) {
    const test::TempDir dir;
    const SceneDesc desc = import(dir, animated_gltf(kSlide), ", animation = {0, 1}");
    const auto placements = moving(desc);
    ASSERT_EQ(placements.size(), 1u);  // the still node stays still
    const std::vector<Transform>& keys = placements[0]->motion;
    ASSERT_GE(keys.size(), 2u);
    // The slide from x = 0 to x = 2 at y = 5 (the node's own y: only translation is animated
    // and the channel replaces it whole, so y comes from the curve: 0).
    EXPECT_NEAR(glm::length(translation_of(keys.front()) - Vec3(0, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(translation_of(keys.back()) - Vec3(2, 0, 0)), 0.0f, 1e-5f);
    const Transform& middle = keys[keys.size() / 2];
    EXPECT_NEAR(glm::length(translation_of(middle) - Vec3(1, 0, 0)), 0.0f, 1e-5f);
    // A window of half the animation, the second half.
    const SceneDesc later = import(dir, animated_gltf(kSlide), ", animation = {0.5, 1}");
    ASSERT_EQ(moving(later).size(), 1u);
    EXPECT_NEAR(translation_of(moving(later)[0]->motion.front()).x, 1.0f, 1e-5f);
}

TEST(GltfAnimation, OneTimeIsAStillPoseAndNoWindowTheFilesPlacement) {
    const test::TempDir dir;
    const SceneDesc pose =
        import(dir, animated_gltf(kSlide + std::string(", ") + kTurn), ", animation = {0.5, 0.5}");
    EXPECT_TRUE(moving(pose).empty());
    const SceneDesc plain = import(dir, animated_gltf(kSlide), "");
    EXPECT_TRUE(moving(plain).empty());
    // Rendered from above, the posed quad (turned 45 degrees, at x = 1) and the file's own
    // placement differ; the still file renders as without the animation.
    EXPECT_EQ(pose.groups[0].shapes.size() + pose.groups[0].instances.size(),
              plain.groups[0].shapes.size() + plain.groups[0].instances.size());
}

TEST(GltfAnimation, TurningNodeKeysFollowTheSlerp) {
    const test::TempDir dir;
    const SceneDesc desc = import(dir, animated_gltf(kTurn), ", animation = {0, 1}");
    const auto placements = moving(desc);
    ASSERT_EQ(placements.size(), 1u);
    const std::vector<Transform>& keys = placements[0]->motion;
    for (size_t k = 0; k < keys.size(); ++k) {
        const float t = static_cast<float>(k) / static_cast<float>(keys.size() - 1);
        // The node's x axis turned by 90 t degrees about y, at the node's translation.
        const Vec3 x_axis = glm::normalize(Vec3(keys[k].matrix()[0]));
        const float angle = glm::degrees(std::atan2(-x_axis.z, x_axis.x));
        EXPECT_NEAR(angle, 90.0f * t, 1e-2f) << "key " << k;
        EXPECT_NEAR(glm::length(translation_of(keys[k]) - Vec3(0, 5, 0)), 0.0f, 1e-5f);
    }
}

TEST(GltfAnimation, MalformedAnimationsAndWindowsAreErrors) {
    const test::TempDir dir;
    const std::string bad_path = test::error_of([&] {
        import(dir, animated_gltf(R"({"sampler": 0, "target": {"node": 0, "path": "size"}})"),
               ", animation = {0, 1}");
    });
    EXPECT_NE(bad_path.find("size"), std::string::npos) << bad_path;
    EXPECT_NE(bad_path.find("scene.lua:1"), std::string::npos) << bad_path;
    const std::string reversed =
        test::error_of([&] { import(dir, animated_gltf(kSlide), ", animation = {1, 0}"); });
    EXPECT_NE(reversed.find("'animation'"), std::string::npos) << reversed;
    std::ofstream(dir.file("quad.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string obj = test::error_of([&] {
        load_scene_string("glint.import{ file = 'quad.obj', animation = {0, 1} }", "scene.lua",
                          dir.file(""));
    });
    EXPECT_NE(obj.find("glTF"), std::string::npos) << obj;
}

// The imported slide renders as the same quad moved by glint's own motion keys.
TEST(GltfAnimation, ImportedMotionRendersAsScriptedMotion) {
    const test::TempDir dir;
    std::ofstream(dir.file("model.gltf")) << animated_gltf(kSlide);
    const auto scene = [&](bool imported, int seed) {
        const std::string quad =
            imported
                ? "glint.import{ file = '" + dir.file("model.gltf") +
                      "', animation = {0, 1}, material = grey }"
                : "glint.quad{ vertices = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, "
                  "material = grey, motion = { glint.translate(0, 0, 0), "
                  "glint.translate(2, 0, 0) } }\n"
                  "glint.quad{ vertices = {{-1, -3, -1}, {-1, -3, 1}, {1, -3, 1}, {1, -3, -1}}, "
                  "material = grey }";
        return fmt::format(R"(
glint.camera{{ eye = {{1, 4, 0.01}}, look_at = {{1, 0, 0}}, fov = 50, shutter = {{0, 1}} }}
glint.render{{ width = 24, height = 24, spp = 32, seed = {}, max_depth = 1 }}
glint.background{{ radiance = 1 }}
local grey = glint.diffuse{{ reflectance = 0.5 }}
{}
)",
                           seed, quad);
    };
    double largest = 0.0;
    const Image a = test::render_lua(scene(true, 1), 2);
    const Image b = test::render_lua(scene(false, 2), 2);
    // Per 4 x 4 block: each sample sees the grey quad lit by the white sky (0.5) or the sky
    // (1): the block means of two independent renders differ by a few standard errors at most.
    for (int by = 0; by < 6; ++by) {
        for (int bx = 0; bx < 6; ++bx) {
            const double ma = test::mean_channel(a, 1, bx * 4, by * 4, bx * 4 + 4, by * 4 + 4);
            const double mb = test::mean_channel(b, 1, bx * 4, by * 4, bx * 4 + 4, by * 4 + 4);
            largest = std::max(largest, std::abs(ma - mb));
        }
    }
    // A sample's standard deviation is at most 0.25; a block holds 16 x 32 of them.
    const double se = 0.25 / std::sqrt(16.0 * 32.0) * std::sqrt(2.0);
    EXPECT_LT(largest, 5.0 * se);
}
