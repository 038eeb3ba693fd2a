// What a scene controls cannot recurse without bound, and every value from the script is
// checked where it enters, with the script line in the message.
#include <glint/core/error.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <chrono>

using namespace glint;
using glint::test::error_of;

namespace {

// Loads and builds `code` as scene.lua; the error message, or "" when there is none.
std::string build_error(const std::string& code) {
    return error_of([&] {
        const SceneDesc desc = load_scene_string(code, "scene.lua");
        build_scene(desc, parse_render_settings(desc.render ? &*desc.render : nullptr));
    });
}

constexpr const char* kScene = R"(
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
)";

// A camera inside a closed, lossless mirror: no path ever leaves and none loses throughput,
// so Russian roulette never ends one.
constexpr const char* kClosedMirror = R"(
glint.sphere{ radius = 5, material = glint.mirror{} }
glint.camera{ eye = {0, 0, 0}, look_at = {0, 0, -1} }
glint.point_light{ position = {0, 1, 0}, intensity = 1 }
)";

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST(Limits, ParameterTablesNestedWithoutEndAreErrors) {
    const std::string deep = build_error(
        "local t = {}\nlocal c = t\nfor i = 1, 150 do c[1] = {}; c = c[1] end\n"
        "glint.sphere{ center = t }\n");
    EXPECT_NE(deep.find("scene.lua:4: sphere: 'center' holds tables nested more than 64 deep"),
              std::string::npos)
        << deep;
    const std::string itself = build_error("local t = {}\nt[1] = t\nglint.sphere{ center = t }\n");
    EXPECT_NE(itself.find("scene.lua:3: sphere: 'center' contains itself"), std::string::npos)
        << itself;
}

// 100 000 nested unions or groups, built by a loop: an error naming the line, quickly.
TEST(Limits, DeepCsgTreesAndGroupsAreErrors) {
    const auto start = std::chrono::steady_clock::now();
    const std::string unions = build_error(std::string(kScene) + R"(
local s = glint.solid.sphere{}
for i = 1, 100000 do s = glint.union{ s } end
glint.add(s, { material = m })
)");
    EXPECT_NE(unions.find("scene.lua:7: glint.union: this CSG tree would be 1001 nodes deep"),
              std::string::npos)
        << unions;
    const std::string groups = build_error(std::string(kScene) + R"(
local g = glint.group()
g:sphere{ radius = 1, material = m }
for i = 1, 100000 do local h = glint.group(); h:place(g); g = h end
glint.place(g)
)");
    EXPECT_NE(groups.find("scene.lua:8: groups are placed inside each other more than 1000 deep"),
              std::string::npos)
        << groups;
    EXPECT_LT(seconds_since(start), 5.0);
    // The limits themselves are allowed.
    EXPECT_EQ(build_error(std::string(kScene) + R"(
local s = glint.solid.sphere{}
for i = 1, 999 do s = glint.union{ s } end
glint.add(s, { material = m })
local g = glint.group()
g:sphere{ radius = 1, material = m }
for i = 1, 999 do local h = glint.group(); h:place(g); g = h end
glint.place(g)
)"),
              "");
}

TEST(Limits, MaxDepthHasHardMaxima) {
    EXPECT_NE(build_error("glint.render{ max_depth = 2e9 }")
                  .find("scene.lua:1: render: 'max_depth' must be -1 (until Russian roulette"),
              std::string::npos);
    EXPECT_NE(build_error("glint.render{ max_depth = 1025 }").find("max_depth"), std::string::npos);
    EXPECT_EQ(build_error("glint.render{ max_depth = 1024 }"), "");
    // The script is built outside the lambda: GCC 12 warns falsely (-Warray-bounds) about
    // a string concatenation inlined into it.
    std::string script = kClosedMirror;
    script +=
        "glint.render{ integrator = 'whitted', max_depth = 65, width = 2, height = 2, "
        "spp = 1 }\n";
    const std::string whitted = error_of([&script] { test::render_lua(script); });
    EXPECT_NE(whitted.find("test.lua:5: whitted follows mirrors and glass by recursion: "
                           "'max_depth' must be at most 64"),
              std::string::npos)
        << whitted;
}

// Whitted at its maximum depth, and the path tracer with max_depth = -1, end in a closed
// mirror; the path tracer follows each path to exactly the hard cap of 1024 bounces.
TEST(Limits, ClosedMirrorRendersEnd) {
    const auto start = std::chrono::steady_clock::now();
    const test::RenderResult whitted = test::render_lua_with_stats(
        std::string(kClosedMirror) +
        "glint.render{ integrator = 'whitted', max_depth = 64, width = 4, height = 4, spp = 1 }");
    EXPECT_EQ(whitted.stats.rays, 16u * 65u);  // a camera ray and 64 reflections per pixel
    const test::RenderResult path = test::render_lua_with_stats(
        std::string(kClosedMirror) +
        "glint.render{ integrator = 'path', max_depth = -1, width = 4, height = 4, spp = 1 }");
    EXPECT_EQ(path.stats.rays, 16u * (kMaxPathDepth + 1));
    EXPECT_LT(seconds_since(start), 5.0);
}

// Each bad value is refused with the script's line (line 5, after kScene) and its name.
TEST(Limits, ValuesAreCheckedWhereTheyEnter) {
    const std::pair<const char*, const char*> cases[] = {
        {"glint.camera{ aperture = 1e30 }", "'aperture' must be at most 1e+12"},
        {"glint.camera{ aperture = -1 }", "'aperture' must not be negative"},
        {"glint.camera{ eye = {1e30, 0, 0} }", "'eye' must lie within 1e+12"},
        {"glint.camera{ focus_distance = 1e39 }", "'focus_distance' must be a finite number"},
        {"glint.camera{ fov = 0/0 }", "'fov' must be a finite number"},
        {"glint.add(glint.solid.ellipsoid{ a = 1e-30 }, { material = m })",
         "ellipsoid: 'a' must be in [1e-06, 1e+06]"},
        {"glint.add(glint.solid.cylinder{ radius = 1e9 }, { material = m })",
         "cylinder: 'radius' must be in [1e-06, 1e+06]"},
        {"glint.sphere{ radius = 1e308, material = m }", "'radius' must be a finite number"},
        {"glint.sphere{ radius = 1e30, material = m }", "'radius' must be in (0, 1e12]"},
        {"glint.sphere{ center = {0, 1/0, 0}, material = m }", "'center' must be a finite"},
        {"glint.place(glint.group(), glint.translate(0/0, 0, 0))", "glint.translate: 'x'"},
        {"glint.rotate(1e39, {0, 1, 0})", "glint.rotate: 'angle' must be a finite number"},
        {"glint.scale(1, 1, 1e-30)", "glint.scale: the transform is singular"},
        {"local _ = glint.scale(1e30) * glint.scale(1e30)",
         "transform * transform: the transform is not"},
        {"glint.matrix{1,0,0,0, 0,1,0,0, 0,0,1e-30,0, 0,0,0,1}", "glint.matrix: the transform"},
        {"glint.render{ exposure = 0/0 }", "render: 'exposure' must be a finite number"},
        {"glint.render{ exposure = 1000 }", "'exposure' must be in [-100, 100]"},
        {"glint.render{ integrator = 'sppm', photon_radius = 1/0 }", "'photon_radius' must be"},
        {"glint.render{ integrator = 'sppm', photon_radius = 1e30 }", "'photon_radius' must be"},
        {"glint.background{ radiance = -1 }", "'radiance' must not be negative"},
        {"glint.add(glint.solid.sphere{}, glint.diffuse{})",
         "glint.add(solid, settings): the settings must be a table such as {material = m}, got "
         "a material"},
        {"glint.add(glint.diffuse{})",
         "glint.add expects a solid (made by glint.solid.* or a "
         "CSG node), got a material"},
        {"glint.sphere(glint.diffuse{})",
         "sphere expects a table of named parameters, e.g. {radius = 1}, got a material"},
    };
    for (const auto& [code, expected] : cases) {
        const std::string message = error_of([&] {
            const SceneDesc desc = load_scene_string(std::string(kScene) + code, "scene.lua");
            const RenderSettings settings =
                parse_render_settings(desc.render ? &*desc.render : nullptr);
            make_integrator(settings, nullptr);
            build_scene(desc, settings);
        });
        EXPECT_NE(message.find("scene.lua:5:"), std::string::npos) << code << ": " << message;
        EXPECT_NE(message.find(expected), std::string::npos) << code << ": " << message;
    }
}
