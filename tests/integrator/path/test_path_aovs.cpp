// The path integrator's features (aovs = true) follow perfect specular bounces to the first
// diffuse or glossy hit, as Open Image Denoise recommends for mirrors and glass: a mirror's
// pixel gets the albedo of what it reflects, tinted by the mirror, and that surface's normal.
#include <glint/film/image.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <string>

namespace glint {
namespace {

// The camera looks down -z at a mirror (normal +z) that fills the view; behind the camera, a
// diffuse wall (normal -z) is what the mirror shows. `mirror` is the material in front.
std::string scene(const std::string& mirror) {
    return R"(
local wall = glint.diffuse{ reflectance = {0.8, 0.6, 0.4} }
glint.camera{ eye = {0, 0, 0}, look_at = {0, 0, -1}, fov = 30 }
glint.render{ width = 8, height = 8, spp = 4, integrator = "path", aovs = true }
glint.quad{ vertices = {{-10, -10, -2}, {10, -10, -2}, {10, 10, -2}, {-10, 10, -2}},
            material = )" +
           mirror + R"( }
glint.quad{ vertices = {{-10, -10, 2}, {-10, 10, 2}, {10, 10, 2}, {10, -10, 2}},
            material = wall }
glint.point_light{ position = {0, 0, 1}, intensity = 1 }
)";
}

void expect_features(const Image& image, float r, float g, float b, float normal_z) {
    const int albedo = image.channel_index("albedo.R"), normal = image.channel_index("normal.X");
    ASSERT_GE(albedo, 0);
    ASSERT_GE(normal, 0);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            EXPECT_NEAR(image.at(x, y, albedo), r, 1e-5f) << x << ", " << y;
            EXPECT_NEAR(image.at(x, y, albedo + 1), g, 1e-5f) << x << ", " << y;
            EXPECT_NEAR(image.at(x, y, albedo + 2), b, 1e-5f) << x << ", " << y;
            EXPECT_NEAR(image.at(x, y, normal + 2), normal_z, 1e-5f) << x << ", " << y;
        }
    }
}

TEST(PathFeatures, MirrorShowsTheTintedAlbedoAndNormalOfWhatItReflects) {
    const Image image = test::render_lua(scene("glint.mirror{ tint = 0.5 }"), 1);
    expect_features(image, 0.4f, 0.3f, 0.2f, -1.0f);
}

TEST(PathFeatures, DiffuseSurfaceKeepsItsOwnFeatures) {
    const Image image =
        test::render_lua(scene("glint.diffuse{ reflectance = {0.1, 0.2, 0.3} }"), 1);
    expect_features(image, 0.1f, 0.2f, 0.3f, 1.0f);
}

}  // namespace
}  // namespace glint
