// The geometry buffer, traced in packets of neighbouring pixel centres, holds what one ray per
// pixel centre finds (depth, camera-facing normal, albedo, object id), at sizes that leave
// partial packets, on scenes with meshes, spheres, glass and instances.
#include <glint/camera/camera.h>
#include <glint/core/interaction.h>
#include <glint/material/material.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/scene/scene.h>
#include <glint/view/geometry_buffer.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>

namespace glint {
namespace {

// `emitters` receives how many pixels see a lamp.
void expect_one_ray_per_pixel(const std::string& example, int width, int height, int& emitters) {
    const std::string code = test::example_with_settings(
        example, "width = " + std::to_string(width) + ", height = " + std::to_string(height));
    const SceneDesc desc = load_scene_string(code, example);
    const std::unique_ptr<Scene> scene = build_scene(desc, parse_render_settings(&*desc.render));
    const Camera& camera = scene->camera();
    const GeometryBuffer buffer = trace_geometry_buffer(*scene, camera, width, height);
    ASSERT_EQ(buffer.size(), static_cast<std::size_t>(width) * height);
    int hits = 0;
    emitters = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            const Ray ray = camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            SurfaceInteraction si;
            HitRecord hit{};
            const std::string where =
                example + " pixel " + std::to_string(x) + ", " + std::to_string(y);
            if (!scene->intersect(ray, si, hit)) {
                EXPECT_FALSE(buffer.hit(i)) << where;
                EXPECT_EQ(buffer.depth[i], 0.0f) << where;
                EXPECT_EQ(buffer.albedo[i], Rgb(1.0f)) << where;
                continue;
            }
            ++hits;
            ASSERT_TRUE(buffer.hit(i)) << where;
            // Embree's packet and one-ray kernels may round the distance differently.
            EXPECT_NEAR(buffer.depth[i], si.t, 1e-5f * si.t) << where;
            Vec3 n = si.shading.n();
            if (glm::dot(n, ray.direction) > 0.0f) n = -n;
            EXPECT_GT(glm::dot(buffer.normal[i], n), 0.9999f) << where;
            const Rgb albedo = si.material ? to_rgb(si.material->albedo(si)) : Rgb(1.0f);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(buffer.albedo[i][c], albedo[c], 1e-4f) << where;
            const uint32_t local = hit.instanced() ? hit.local_geometry + 1 : 0;
            EXPECT_EQ(buffer.object_id[i], hit.top_geometry ^ (local << 16)) << where;
            const bool emits = si.material && si.material->is_emissive();
            EXPECT_EQ(buffer.emitter[i], emits ? 1 : 0) << where;
            emitters += emits;
        }
    }
    EXPECT_GT(hits, width * height / 4) << example;
}

TEST(GeometryBuffer, PacketsFindWhatOneRayPerPixelFinds) {
    int emitters = 0;
    expect_one_ray_per_pixel("cornell-box.lua", 37, 23, emitters);
    EXPECT_GT(emitters, 0) << "the ceiling's lamp";
    expect_one_ray_per_pixel("cornell-spheres.lua", 30, 17, emitters);
    expect_one_ray_per_pixel("instancing.lua", 41, 29, emitters);
}

}  // namespace
}  // namespace glint
