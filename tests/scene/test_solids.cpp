// Solids and CSG through the scene language: bad input gives a clear error naming the
// script line; primitives keep their own materials (or inherit them), and CSG solids are
// transformed, bounded and instanced like any other object.
#include <glint/core/error.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <cmath>
#include <functional>
#include <string>

using namespace glint;
using glint::test::error_of;

namespace {

std::unique_ptr<Scene> build_scene(const std::string& code) {
    const SceneDesc desc = load_scene_string(code, "scene.lua", GLINT_SOURCE_DIR "/tests/scenes");
    return build_scene(desc, parse_render_settings(desc.render ? &*desc.render : nullptr));
}

// The reflectance of what the ray hits first, or -1 when it hits nothing.
Spectrum albedo_hit(const Scene& scene, const Vec3& origin, const Vec3& direction) {
    const auto hit = scene.intersect(Ray{origin, direction});
    if (!hit) return Spectrum(-1.0f);
    return hit->material->albedo(*hit);
}

const char* kMaterials = R"(local red = glint.diffuse{ reflectance = {0.9, 0.1, 0.1} }
local green = glint.diffuse{ reflectance = {0.1, 0.9, 0.1} }
local blue = glint.diffuse{ reflectance = {0.1, 0.1, 0.9} }
)";

bool is_red(const Spectrum& s) {
    return to_rgb(s).r > 0.5f && to_rgb(s).g < 0.5f && to_rgb(s).b < 0.5f;
}
bool is_green(const Spectrum& s) {
    return to_rgb(s).g > 0.5f && to_rgb(s).r < 0.5f && to_rgb(s).b < 0.5f;
}
bool is_blue(const Spectrum& s) {
    return to_rgb(s).b > 0.5f && to_rgb(s).r < 0.5f && to_rgb(s).g < 0.5f;
}

}  // namespace

// Each error names the line of the offending statement (not where the solid was added) and
// says what was wrong.
TEST(Solids, BadInputGivesClearErrorsWithTheLine) {
    struct Case {
        const char* code;
        const char* line;
        std::vector<const char*> words;
    };
    const Case cases[] = {
        {"local m = glint.diffuse{}\n"
         "local q = glint.solid.quadric{ matrix = {1,0,0,0, 0.5,1,0,0, 0,0,1,0, 0,0,0,-1} }\n"
         "glint.add(q, { material = m })",
         "scene.lua:2:",
         {"symmetric", "(1, 2)", "(2, 1)"}},
        {"local m = glint.diffuse{}\n\n"
         "local q = glint.solid.quadric{ matrix = {1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0}, material = m "
         "}\n"
         "glint.add(glint.intersection{ q, glint.solid.box{} })",
         "scene.lua:3:",
         {"16 numbers"}},
        {"local m = glint.diffuse{}\n"
         "local q = glint.solid.quadric{ matrix = {0,0,0,1, 0,0,0,0, 0,0,0,0, 1,0,0,-1}, material "
         "= m }\n"
         "glint.add(q)",
         "scene.lua:2:",
         {"no quadratic terms"}},
        {"local m = glint.diffuse{}\nlocal u = glint.union{}\nglint.add(u, { material = m })",
         "scene.lua:2:",
         {"union", "at least one solid"}},
        {"local d = glint.difference{ material = glint.diffuse{} }",
         "scene.lua:1:",
         {"difference", "at least one solid"}},
        // An open box: the top face (two triangles) is missing.
        {"local m = glint.diffuse{}\n"
         "local open = glint.solid.mesh{ vertices = {{0,0,0},{1,0,0},{1,1,0},{0,1,0},\n"
         "                                           {0,0,1},{1,0,1},{1,1,1},{0,1,1}},\n"
         "  indices = {1,3,2, 1,4,3, 5,6,7, 5,7,8, 1,2,6, 1,6,5, 2,3,7, 2,7,6, 4,1,5, 4,5,8} }\n"
         "glint.add(glint.difference{ open, glint.solid.sphere{ radius = 0.2 }, material = m })",
         "scene.lua:2:",
         {"mesh", "not a closed"}},
        // A closed tetrahedron with one face wound the wrong way.
        {"local m = glint.diffuse{}\n"
         "glint.add(glint.solid.mesh{ vertices = {{0,0,0},{1,0,0},{0,1,0},{0,0,1}},\n"
         "  indices = {1,3,2, 1,2,4, 1,4,3, 2,4,3}, material = m })",
         "scene.lua:2:",
         {"consistently oriented"}},
        {"local m = glint.diffuse{}\n"
         "local h = glint.solid.hyperboloid_one_sheet{ a = 1, b = 2, c = 1, material = m }\n\n"
         "glint.add(h)",
         "scene.lua:2:",
         {"hyperboloid_one_sheet", "unbounded", "bounds =", "intersect it with a finite solid"}},
        {"local s = glint.solid.sphere{ radius = 1 }\n"
         "local b = glint.solid.box{}\n"
         "glint.add(glint.union{ s, b })",
         "scene.lua:1:",
         {"no material"}},
        {"local lamp = glint.emissive{ radiance = 1 }\n"
         "local s = glint.solid.sphere{ radius = 1 }\n"
         "glint.add(glint.difference{ glint.solid.box{}, s, material = lamp })",
         "scene.lua:3:",
         {"cannot emit light"}},
        {"glint.add(glint.union{ glint.solid.sphere{}, 5 })",
         "scene.lua:1:",
         {"entry 2 is not a solid"}},
        {"glint.add(glint.solid.elliptic_cylinder{ a = 1, c = 1, material = glint.diffuse{},\n"
         "                                        bounds = {{0, 0, 0}, {-1, 1, 1}} })",
         "scene.lua:1:",
         {"'bounds'"}},
        {"glint.add(glint.solid.torus{ material = glint.diffuse{} })", "scene.lua:1:", {"torus"}},
    };
    for (const Case& c : cases) {
        const std::string message = error_of([&] { build_scene(c.code); });
        EXPECT_NE(message.find(c.line), std::string::npos) << c.code << "\n  gave: " << message;
        for (const char* word : c.words) {
            EXPECT_NE(message.find(word), std::string::npos)
                << "'" << word << "' missing from: " << message;
        }
    }
}

// Every primitive keeps its material: from its own 'material', else from the nearest
// enclosing CSG node, else from glint.add. A cut face shows the material of the solid
// that was subtracted.
TEST(Solids, PrimitivesKeepTheirMaterials) {
    const auto scene = build_scene(std::string(kMaterials) + R"(
        local ball = glint.solid.sphere{ center = {-2, 0, 0}, radius = 1, material = red }
        local block = glint.solid.box{ min = {1, -1, -1}, max = {3, 1, 1} }
        glint.add(glint.union{ ball, block, material = blue })
        -- A slab with a hole cut by a green sphere; the slab takes glint.add's material.
        local slab = glint.solid.box{ min = {-1, 4, -1}, max = {1, 5, 1} }
        local hole = glint.solid.sphere{ center = {0, 5, 0}, radius = 0.5, material = green }
        glint.add(glint.difference{ slab, hole }, { material = red })
    )");
    const Vec3 down(0, 0, -1);
    EXPECT_TRUE(is_red(albedo_hit(*scene, Vec3(-2, 0, 5), down)));
    EXPECT_TRUE(is_blue(albedo_hit(*scene, Vec3(2, 0, 5), down)));
    EXPECT_EQ(to_rgb(albedo_hit(*scene, Vec3(-0.5f, 0, 5), down)).r, -1.0f);
    // From above: the slab's top at x = 0.8, the cavity's surface at x = 0.
    EXPECT_TRUE(is_red(albedo_hit(*scene, Vec3(0.8f, 10, 0), Vec3(0, -1, 0))));
    const auto cavity = scene->intersect(Ray{Vec3(0, 10, 0), Vec3(0, -1, 0)});
    ASSERT_TRUE(cavity.has_value());
    EXPECT_NEAR(cavity->p.y, 4.5f, 1e-4f);
    EXPECT_TRUE(is_green(cavity->material->albedo(*cavity)));
    // The cut face's normal points out of the slab, into the hole: up, towards the ray.
    EXPECT_NEAR(cavity->ng.y, 1.0f, 1e-4f);
}

// A ray through a union's two parts meets both materials: the first where it enters and,
// continued from there, the second.
TEST(Solids, ARayThroughTwoPartsSeesBothMaterials) {
    const auto scene = build_scene(std::string(kMaterials) + R"(
        local a = glint.solid.box{ min = {0, -1, -1}, max = {1, 1, 1}, material = red }
        local b = glint.solid.sphere{ center = {3, 0, 0}, radius = 1, material = blue }
        glint.add(glint.union{ a, b })
    )");
    const auto first = scene->intersect(Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)});
    ASSERT_TRUE(first.has_value());
    EXPECT_NEAR(first->p.x, 0.0f, 1e-4f);
    EXPECT_TRUE(is_red(first->material->albedo(*first)));
    const auto exit = scene->intersect(Ray{first->p, Vec3(1, 0, 0), 1e-3f});
    ASSERT_TRUE(exit.has_value());
    EXPECT_NEAR(exit->p.x, 1.0f, 1e-4f);
    EXPECT_TRUE(is_red(exit->material->albedo(*exit)));
    const auto second = scene->intersect(Ray{exit->p, Vec3(1, 0, 0), 1e-3f});
    ASSERT_TRUE(second.has_value());
    EXPECT_NEAR(second->p.x, 2.0f, 1e-4f);
    EXPECT_TRUE(is_blue(second->material->albedo(*second)));
}

// Integrators keep one SurfaceInteraction for a whole path and let each hit overwrite the
// last: a CSG part index or a texture footprint must not carry over to the next surface.
TEST(Solids, AReusedInteractionKeepsNothingFromThePreviousHit) {
    const auto scene = build_scene(std::string(kMaterials) + R"(
        local a = glint.solid.box{ min = {0, -1, -1}, max = {1, 1, 1}, material = red }
        local b = glint.solid.sphere{ center = {3, 0, 0}, radius = 1, material = blue }
        glint.add(glint.union{ a, b })
        glint.quad{ vertices = {{-4, 10, -1}, {-4, 10, 1}, {-2, 10, 1}, {-2, 10, -1}},
                    material = green }
    )");
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect(Ray{Vec3(3, 5, 0), Vec3(0, -1, 0)}, si));
    EXPECT_TRUE(is_blue(si.material->albedo(si)));
    EXPECT_NE(si.part, 0);
    si.set_footprint(Vec3(0.1f, 0, 0), Vec3(0, 0, 0.1f));
    ASSERT_TRUE(scene->intersect(Ray{Vec3(-3, 0, 0), Vec3(0, 1, 0)}, si));
    EXPECT_TRUE(is_green(si.material->albedo(si)));
    EXPECT_EQ(si.part, 0);
    EXPECT_EQ(si.dpdx, Vec3(0.0f));
    EXPECT_EQ(si.dpdy, Vec3(0.0f));
    EXPECT_EQ(si.dudx, 0.0f);
    EXPECT_EQ(si.dvdy, 0.0f);
    EXPECT_NEAR(si.p.y, 10.0f, 1e-4f);
    // The reference form gives the same hit as the value form.
    const auto value = scene->intersect(Ray{Vec3(-3, 0, 0), Vec3(0, 1, 0)});
    ASSERT_TRUE(value.has_value());
    EXPECT_EQ(value->p, si.p);
    EXPECT_EQ(value->ng, si.ng);
    EXPECT_FALSE(scene->intersect(Ray{Vec3(-3, 0, 0), Vec3(0, -1, 0)}, si));
}

// A CSG solid in a group placed twice is one prototype with two instances; both are hit,
// with the right material per part and normals carried to the world.
TEST(Solids, CsgInAGroupIsInstanced) {
    const auto scene = build_scene(std::string(kMaterials) + R"(
        local g = glint.group()
        local cup = glint.difference{
            glint.solid.cylinder{ radius = 1, height = 2, material = red },
            glint.solid.cylinder{ radius = 0.5, height = 2, transform = glint.translate(0, 0.5, 0),
                                  material = blue } }
        g:add(cup)
        glint.place(g, glint.translate(-5, 0, 0))
        glint.place(g, glint.translate(5, 0, 0) * glint.rotate(90, {0, 0, 1}))
    )");
    EXPECT_EQ(scene->stats().instances, 2u);
    EXPECT_EQ(scene->stats().groups, 1u);
    // The upright cup at x = -5: the rim (red) at y = 1, the inner floor (blue) at y = -0.5.
    const Vec3 down(0, -1, 0);
    const auto rim = scene->intersect(Ray{Vec3(-5.75f, 5, 0), down});
    ASSERT_TRUE(rim.has_value());
    EXPECT_NEAR(rim->p.y, 1.0f, 1e-4f);
    EXPECT_TRUE(is_red(rim->material->albedo(*rim)));
    const auto floor = scene->intersect(Ray{Vec3(-5, 5, 0), down});
    ASSERT_TRUE(floor.has_value());
    EXPECT_NEAR(floor->p.y, -0.5f, 1e-4f);
    EXPECT_NEAR(floor->ng.y, 1.0f, 1e-4f);
    EXPECT_TRUE(is_blue(floor->material->albedo(*floor)));
    // The cup at x = 5 lies on its side, opening towards -x: from -x the ray looks into it.
    const auto inside = scene->intersect(Ray{Vec3(0, 0, 0), Vec3(1, 0, 0)});
    ASSERT_TRUE(inside.has_value());
    EXPECT_NEAR(inside->p.x, 5.5f, 1e-4f);
    EXPECT_NEAR(inside->ng.x, -1.0f, 1e-4f);
    EXPECT_TRUE(is_blue(inside->material->albedo(*inside)));
    const auto side = scene->intersect(Ray{Vec3(5, 5, 0), down});
    ASSERT_TRUE(side.has_value());
    EXPECT_NEAR(side->p.y, 1.0f, 1e-4f);
    EXPECT_TRUE(is_red(side->material->albedo(*side)));
    // Between the two placements there is nothing.
    EXPECT_FALSE(scene->intersect(Ray{Vec3(0, 5, 0), down}).has_value());
}

// A node's transform moves the whole tree, normals included; 'bounds' clips an infinite
// quadric to a box whose faces become caps.
TEST(Solids, TransformedAndBoundedSolids) {
    const auto scene = build_scene(std::string(kMaterials) + R"(
        local lens = glint.intersection{
            glint.solid.sphere{ center = {-0.5, 0, 0}, radius = 1 },
            glint.solid.sphere{ center = {0.5, 0, 0}, radius = 1 },
            material = red,
            transform = glint.translate(0, 10, 0) * glint.rotate(90, {0, 0, 1}) }
        glint.add(lens)
        glint.add(glint.solid.elliptic_cylinder{ a = 1, c = 2, material = blue,
                                                 bounds = {{-5, -1, -5}, {5, 1, 5}},
                                                 transform = glint.translate(10, 0, 0) })
    )");
    // The lens, turned so its thin axis is y, at y = 10: its faces at y = 10 +- 0.5.
    const auto top = scene->intersect(Ray{Vec3(0, 20, 0), Vec3(0, -1, 0)});
    ASSERT_TRUE(top.has_value());
    EXPECT_NEAR(top->p.y, 10.5f, 1e-4f);
    EXPECT_NEAR(top->ng.y, 1.0f, 1e-4f);
    const auto bottom = scene->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 1, 0)});
    ASSERT_TRUE(bottom.has_value());
    EXPECT_NEAR(bottom->p.y, 9.5f, 1e-4f);
    EXPECT_NEAR(bottom->ng.y, -1.0f, 1e-4f);
    // Its rim, a circle of radius sqrt(3)/2 in the plane y = 10.
    const auto rim = scene->intersect(Ray{Vec3(0, 10, 5), Vec3(0, 0, -1)});
    ASSERT_TRUE(rim.has_value());
    EXPECT_NEAR(rim->p.z, std::sqrt(3.0f) / 2.0f, 1e-4f);

    // The bounded cylinder: the cap at y = 1 and the side at z = 2 (semi-axis c).
    const auto cap = scene->intersect(Ray{Vec3(10.5f, 5, 0), Vec3(0, -1, 0)});
    ASSERT_TRUE(cap.has_value());
    EXPECT_NEAR(cap->p.y, 1.0f, 1e-4f);
    EXPECT_NEAR(cap->ng.y, 1.0f, 1e-4f);
    EXPECT_TRUE(is_blue(cap->material->albedo(*cap)));
    const auto wall = scene->intersect(Ray{Vec3(10, 0.5f, 9), Vec3(0, 0, -1)});
    ASSERT_TRUE(wall.has_value());
    EXPECT_NEAR(wall->p.z, 2.0f, 1e-4f);
    EXPECT_NEAR(wall->ng.z, 1.0f, 1e-4f);
    // Above the bounds there is nothing, though the infinite cylinder goes on.
    EXPECT_FALSE(scene->intersect(Ray{Vec3(10, 3, 9), Vec3(0, 0, -1)}).has_value());
}

// The named primitives have the documented placement: a cylinder centred on the origin
// along y; a cone with its base on y = 0 and its apex at y = height.
TEST(Solids, CylinderAndConeDimensions) {
    const auto scene = build_scene(std::string(kMaterials) + R"(
        glint.add(glint.solid.cylinder{ radius = 1, height = 4, material = red })
        glint.add(glint.solid.cone{ radius = 1, height = 2, material = blue,
                                    transform = glint.translate(10, 0, 0) })
    )");
    const Vec3 down(0, -1, 0);
    EXPECT_NEAR(scene->intersect(Ray{Vec3(0.5f, 9, 0), down})->p.y, 2.0f, 1e-4f);
    EXPECT_NEAR(scene->intersect(Ray{Vec3(0, 0, 9), Vec3(0, 0, -1)})->p.z, 1.0f, 1e-4f);
    EXPECT_NEAR(scene->intersect(Ray{Vec3(0.5f, -9, 0), Vec3(0, 1, 0)})->p.y, -2.0f, 1e-4f);
    // The cone's radius at height y is 1 - y/2: at x = 0.5 from above, y = 1.
    EXPECT_NEAR(scene->intersect(Ray{Vec3(10.5f, 9, 0), down})->p.y, 1.0f, 1e-4f);
    EXPECT_NEAR(scene->intersect(Ray{Vec3(10, 9, 0), down})->p.y, 2.0f, 1e-3f);
    EXPECT_NEAR(scene->intersect(Ray{Vec3(10.5f, -9, 0), Vec3(0, 1, 0)})->p.y, 0.0f, 1e-4f);
}

// The render setting that turns the shortcuts off changes nothing that can be seen.
TEST(Solids, ShortcutsOffFindTheSameHits) {
    const std::string body = std::string(kMaterials) + R"(
        for i = 0, 3 do
            local capsule = glint.intersection{
                glint.solid.hyperboloid_one_sheet{ a = 0.4, b = 1, c = 0.4 },
                glint.solid.ellipsoid{ a = 1, b = 1.5, c = 1 },
                glint.solid.box{ min = {-2, -1, -2}, max = {2, 1, 2} },
                material = red, transform = glint.translate(3 * i, 0, 0) }
            glint.add(glint.difference{ capsule,
                glint.solid.elliptic_cylinder{ a = 0.2, c = 0.2, transform = glint.translate(3 * i, 0, 0) *
                                               glint.rotate(90, {1, 0, 0}) }, material = blue })
        end
    )";
    const auto on = build_scene(body);
    const auto off = build_scene("glint.render{ csg_shortcuts = false }\n" + body);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const float x = -2.0f + 13.0f * static_cast<float>(i % 40) / 40.0f;
        const float y = -1.5f + 3.0f * static_cast<float>(i / 40) / 25.0f;
        const Ray ray{Vec3(x, y, 5), glm::normalize(Vec3(0.1f, 0.05f, -1))};
        const auto a = on->intersect(ray), b = off->intersect(ray);
        ASSERT_EQ(a.has_value(), b.has_value()) << x << ", " << y;
        if (!a) continue;
        ++hits;
        EXPECT_EQ(a->p, b->p);
        EXPECT_EQ(a->ng, b->ng);
        EXPECT_EQ(to_rgb(a->material->albedo(*a)).r, to_rgb(b->material->albedo(*b)).r);
    }
    EXPECT_GT(hits, 150);
}

// A general quadric is the same surface for its matrix times any positive number: one with
// coefficients of 1e-30 (a unit sphere) renders as the same sphere with coefficients of 1,
// every sample finite (issue 28: its normals were 0/0 and its rays not finite).
TEST(Solids, QuadricScaledByAnyFactorRendersTheSame) {
    auto scene = [](const char* scale) {
        return fmt::format(R"(
            glint.camera{{ eye = {{0, 0, 4}}, look_at = {{0, 0, 0}}, fov = 40 }}
            glint.render{{ width = 24, height = 24, spp = 4 }}
            glint.point_light{{ position = {{0, 2, 3}}, intensity = 10 }}
            local s = {}
            glint.add(glint.solid.quadric{{ matrix = {{ s, 0, 0, 0,  0, s, 0, 0,  0, 0, s, 0,
                                                     0, 0, 0, -s }} }},
                      {{ material = glint.diffuse{{ reflectance = 0.5 }} }})
        )",
                           scale);
    };
    const Image unit = glint::test::render_lua(scene("1"));
    const Image tiny = glint::test::render_lua(scene("1e-30"));
    ASSERT_EQ(unit.pixels.size(), tiny.pixels.size());
    double sum = 0.0;
    for (size_t i = 0; i < unit.pixels.size(); ++i) {
        ASSERT_TRUE(std::isfinite(tiny.pixels[i])) << i;
        EXPECT_EQ(unit.pixels[i], tiny.pixels[i]) << i;
        sum += tiny.pixels[i];
    }
    EXPECT_GT(sum, 0.0);
}
