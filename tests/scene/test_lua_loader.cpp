#include <glint/core/error.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/test_util.h>

using namespace glint;
using glint::test::error_of;

namespace {

std::unique_ptr<Scene> build(const std::string& code) {
    const SceneDesc desc = load_scene_string(code, "scene.lua", GLINT_SOURCE_DIR "/tests/scenes");
    return build_scene(desc, parse_render_settings(desc.render ? &*desc.render : nullptr));
}

}  // namespace

TEST(LuaLoader, LoopsAndFunctionsBuildScenes) {
    const auto scene = build(R"(
        local m = glint.diffuse{ reflectance = 0.5 }
        local function ball(x) glint.sphere{ center = {x, 0, 0}, radius = 0.5, material = m } end
        for i = 1, 5 do ball(i) end
    )");
    EXPECT_EQ(scene->stats().shapes, 5u);
    EXPECT_NEAR(scene->stats().bounds.min.x, 0.5f, 1e-5f);
    EXPECT_NEAR(scene->stats().bounds.max.x, 5.5f, 1e-5f);
}

TEST(LuaLoader, RequireReturnsTheModule) {
    const auto scene = build(R"(
        local g = require("glint")
        g.box{ min = {0, 0, 0}, max = {1, 1, 1}, material = g.mirror{} }
    )");
    EXPECT_EQ(scene->stats().triangles, 12u);
}

// A group placed three times is built once and instanced; nested placements compose.
TEST(LuaLoader, GroupsAreInstancedWithNestedTransforms) {
    const auto scene = build(R"(
        local m = glint.diffuse{}
        local leaf = glint.group()
        leaf:box{ min = {0, 0, 0}, max = {1, 1, 1}, material = m }
        local branch = glint.group()
        branch:place(leaf, glint.translate(10, 0, 0))
        branch:place(leaf, glint.translate(20, 0, 0))
        glint.place(branch, glint.translate(0, 100, 0) * glint.scale(2))
        glint.place(leaf)
    )");
    const SceneStats& s = scene->stats();
    EXPECT_EQ(s.instances, 3u);
    EXPECT_EQ(s.groups, 1u);  // only `leaf` holds shapes
    EXPECT_EQ(s.triangles, 36u);
    EXPECT_NEAR(s.bounds.max.x, 42.0f, 1e-4f);   // (20 + 1) * 2
    EXPECT_NEAR(s.bounds.max.y, 102.0f, 1e-4f);  // 100 + 1 * 2
    EXPECT_NEAR(s.bounds.min.y, 0.0f, 1e-4f);

    // A ray down onto the second placement of the scaled branch hits its top at y = 102.
    const auto hit = scene->intersect(Ray{Vec3(41.0f, 200.0f, 1.0f), Vec3(0, -1, 0)});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->p.y, 102.0f, 1e-3f);
    EXPECT_NEAR(hit->ng.y, 1.0f, 1e-5f);
}

TEST(LuaLoader, GroupCannotContainItself) {
    const std::string message = error_of([] {
        build(
            "local a = glint.group()\nlocal b = glint.group()\na:box{ material = glint.diffuse{} "
            "}\n"
            "a:place(b)\nb:place(a)\nglint.place(a)\n");
    });
    EXPECT_NE(message.find("contain itself"), std::string::npos) << message;
}

TEST(LuaLoader, EmissiveShapesInGroupsBecomeOneLightPerPlacement) {
    const auto scene = build(R"(
        local lamp = glint.emissive{ radiance = 1 }
        local g = glint.group()
        g:sphere{ radius = 0.1, material = lamp }
        for i = 1, 4 do glint.place(g, glint.translate(i, 0, 0)) end
        glint.point_light{ position = {0, 1, 0}, intensity = 1 }
    )");
    EXPECT_EQ(scene->lights().size(), 5u);
}

TEST(LuaLoader, InlineMeshUsesOneBasedIndices) {
    const auto scene = build(R"(
        glint.mesh{ vertices = {{0,0,0}, {1,0,0}, {0,1,0}}, indices = {1, 2, 3}, material = glint.diffuse{} }
    )");
    EXPECT_EQ(scene->stats().triangles, 1u);
    const std::string message = error_of([] {
        build(
            "glint.mesh{ vertices = {{0,0,0}, {1,0,0}, {0,1,0}}, indices = {0, 1, 2}, material = "
            "glint.diffuse{} }");
    });
    EXPECT_NE(message.find("scene.lua:1"), std::string::npos) << message;
}

TEST(LuaLoader, ObjFileIsLoadedRelativeToTheScript) {
    const auto scene = build("glint.mesh{ file = 'triangle.obj', material = glint.diffuse{} }");
    EXPECT_EQ(scene->stats().triangles, 3u);
}

TEST(LuaLoader, DegenerateTrianglesAreDropped) {
    const auto scene = build(R"(
        glint.mesh{ vertices = {{0,0,0}, {1,0,0}, {2,0,0}, {0,1,0}}, indices = {1, 2, 3, 1, 2, 4},
                    material = glint.diffuse{} }
    )");
    EXPECT_EQ(scene->stats().triangles, 1u);
}

// Every error names the script and the line of the offending statement.
TEST(LuaLoader, ErrorsNameFileAndLine) {
    struct Case {
        const char* code;
        const char* expected;
    };
    const Case cases[] = {
        {"local x = 1\nglint.sphere{ radius = 1 material = 2 }", "scene.lua:2:"},
        {"local m = glint.diffuse{}\n\nglint.sphere{ radius = 1, materail = m }", "scene.lua:3:"},
        {"glint.diffuse{ reflectance = 'red' }", "scene.lua:1:"},
        {"glint.camera{ eye = {0, 0} }", "scene.lua:1:"},
        {"\nglint.sphere{ radius = -1, material = glint.diffuse{} }", "scene.lua:2:"},
        {"glint.render{ spp = 0 }", "scene.lua:1:"},
        {"glint.render{}\nglint.render{}", "scene.lua:2:"},
        {"glint.sphere{ 1, 2 }", "scene.lua:1:"},
        {"glint.rotate(45)", "scene.lua:1:"},
        {"glint.mesh{ file = 'nope.obj', material = glint.diffuse{} }", "scene.lua:1:"},
        {"glint.translate(1, 2, 3) * 4", "scene.lua:1:"},
        {"glint.sphere{ material = glint.diffuse{ reflectance = 2 } }", "scene.lua:1:"},
        {"glint.matrix{1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1}", "scene.lua:1:"},
        {"\nglint.point_light{ position = {0,0,0}, intensity = -1 }", "scene.lua:2:"},
        {"glint.background{ radiance = 0/0 }", "scene.lua:1:"},
    };
    for (const Case& c : cases) {
        const std::string message = error_of([&] { build(c.code); });
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.code << "\n  gave: " << message;
    }
}

TEST(LuaLoader, UnknownParameterListsTheKnownOnes) {
    const std::string message = error_of([] { build("glint.dielectric{ iorr = 1.5 }"); });
    EXPECT_NE(message.find("unknown parameter 'iorr'"), std::string::npos) << message;
    EXPECT_NE(message.find("ior"), std::string::npos) << message;
    EXPECT_NE(message.find("absorption"), std::string::npos) << message;
}

TEST(LuaLoader, MissingSceneFileIsAnError) {
    EXPECT_THROW(load_scene_file("/nonexistent/scene.lua"), Error);
}

// A one-sided quad light wound away from everything renders black: building says so, with
// the line that made it; wound towards the floor, or two-sided, it says nothing.
TEST(LuaLoader, OneSidedLightFacingAwayIsWarnedOf) {
    auto warnings_for = [](const std::string& corners, const std::string& extra) {
        const auto scene = build(R"(
            glint.quad{ vertices = {{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}},
                        material = glint.diffuse{} }
            glint.quad{ vertices = )" +
                                 corners + R"(,
                        material = glint.emissive{ radiance = 5)" +
                                 extra + R"( } }
        )");
        return scene->stats().warnings;
    };
    const std::string towards_floor = "{{-1, 4, -1}, {1, 4, -1}, {1, 4, 1}, {-1, 4, 1}}";
    const std::string towards_sky = "{{-1, 4, -1}, {-1, 4, 1}, {1, 4, 1}, {1, 4, -1}}";
    const auto sky = warnings_for(towards_sky, "");
    const auto floor = warnings_for(towards_floor, "");
    // Which winding faces the floor is the renderer's convention: exactly one of the two
    // must be warned of, and it must name the emitter's line.
    ASSERT_EQ(sky.size() + floor.size(), 1u);
    const std::string warning = sky.empty() ? floor.front() : sky.front();
    EXPECT_NE(warning.find("scene.lua:4"), std::string::npos) << warning;
    EXPECT_NE(warning.find("faces away"), std::string::npos) << warning;
    EXPECT_TRUE(
        warnings_for(sky.empty() ? towards_floor : towards_sky, ", two_sided = true").empty());
}
