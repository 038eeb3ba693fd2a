// 3D image warping: the Cornell box rendered from camera A and warped to a nearby camera B
// matches a direct render from B where A saw the surface (within the renders' noise and the
// edges' blend), and marks as disoccluded the pixels A could not see; the camera an image
// was rendered with travels in its EXR header.
#include <glint/camera/camera.h>
#include <glint/camera/camera_attributes.h>
#include <glint/core/error.h>
#include <glint/film/image_io.h>
#include <glint/render/render_job.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/view/image_warp.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

namespace glint {
namespace {

constexpr int kWarpWidth = 96, kWarpHeight = 72;

struct Rendered {
    Image image;
    std::unique_ptr<Camera> camera;
};

Rendered render_from(const std::string& camera_lua, uint64_t seed) {
    std::string code = test::example_with_settings(
        "cornell-box.lua", fmt::format("width = {}, height = {}, spp = 32, seed = {}, "
                                       "integrator = 'path', aovs = true",
                                       kWarpWidth, kWarpHeight, seed));
    // The example's camera line, replaced.
    const std::size_t start = code.find("glint.camera{");
    code.replace(start, code.find('\n', start) - start, camera_lua);
    SceneDesc desc = load_scene_string(code, "cornell.lua");
    RenderControl control;
    control.quiet = true;
    Rendered r;
    r.image = render_image(desc, parse_render_settings(&*desc.render), control).image;
    auto stored = camera_from_attributes(r.image.attributes, "render");
    EXPECT_TRUE(stored.has_value()) << "an image with depth records its camera";
    r.camera = make_camera(stored->params, stored->resolution);
    return r;
}

const std::string kCameraA =
    "glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3077 "
    "}";
const std::string kCameraB =
    "glint.camera{ eye = {330, 300, -780}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3077 "
    "}";

// Whether the surface B shows at pixel (x, y) was visible to A: its point lands in A's frame
// where A's depth agrees.
bool seen_by_a(const Rendered& a, const Rendered& b, int x, int y) {
    // An escaped ray (depth 0, or infinite) sees the background in its direction, far away.
    auto escaped_at = [](float depth) { return depth == 0.0f || std::isinf(depth); };
    const float depth = b.image.at(x, y, b.image.channel_index("depth.Z"));
    const bool escaped = escaped_at(depth);
    const Ray ray = b.camera->generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
    const auto p = a.camera->project(ray.origin + (escaped ? 1e6f : depth) * ray.direction);
    if (!p || p->film.x < 0 || p->film.y < 0 || p->film.x >= kWarpWidth || p->film.y >= kWarpHeight)
        return false;
    const float a_depth = a.image.at(static_cast<int>(p->film.x), static_cast<int>(p->film.y),
                                     a.image.channel_index("depth.Z"));
    if (escaped) return escaped_at(a_depth);
    return std::abs(a_depth - p->depth) < 0.05f * p->depth;
}

// Whether B's pixel (x, y) lies on an edge: a 4-neighbour more than 10 % nearer or further
// (or escaped), or more than twice as bright or dark (the light's rim). Such a pixel blends
// two surfaces, and resampling moves the blend by a fraction of a pixel: no warp can match it
// pixel for pixel.
bool on_edge(const Rendered& b, int x, int y) {
    const int z = b.image.channel_index("depth.Z");
    const float d = b.image.at(x, y, z);
    auto luminance = [&](int px, int py) {
        return Rgb(b.image.at(px, py, 0), b.image.at(px, py, 1), b.image.at(px, py, 2)).luminance();
    };
    const float l = luminance(x, y);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, kWarpWidth - 1);
            const int ny = std::clamp(y + dy, 0, kWarpHeight - 1);
            const float n = b.image.at(nx, ny, z), ln = luminance(nx, ny);
            if (!(std::abs(n - d) <= 0.1f * d)) return true;
            if (ln > 2.0f * l + 0.05f || l > 2.0f * ln + 0.05f) return true;
        }
    }
    return false;
}

TEST(ImageWarp, WarpedRenderMatchesADirectRenderAndMarksDisocclusions) {
    const Rendered a = render_from(kCameraA, 1);
    const Rendered b = render_from(kCameraB, 2);
    const Rendered b_again = render_from(kCameraB, 3);
    const WarpResult warped = warp_image(a.image, *a.camera, *b.camera, kWarpWidth, kWarpHeight);
    ASSERT_EQ(warped.image.width, kWarpWidth);

    // Relative squared error over the pixels both show, against the noise of two renders
    // from B with different seeds (the warped image carries A's noise instead of B's).
    double warp_error = 0.0, noise = 0.0;
    int shared = 0, holes_seen = 0, covered_unseen = 0, unseen = 0;
    for (int y = 0; y < kWarpHeight; ++y) {
        for (int x = 0; x < kWarpWidth; ++x) {
            if (on_edge(b, x, y)) continue;
            const bool seen = seen_by_a(a, b, x, y);
            const bool hole = warped.hole[y * kWarpWidth + x] != 0;
            unseen += !seen;
            if (hole) {
                holes_seen += seen;
                for (int c = 0; c < 3; ++c)
                    EXPECT_EQ(warped.image.at(x, y, c), WarpSettings{}.hole_colour[c]);
                continue;
            }
            covered_unseen += !seen;
            if (!seen) continue;
            ++shared;
            for (int c = 0; c < 3; ++c) {
                const double ref = b.image.at(x, y, c);
                const double scale = ref * ref + 1e-2;
                warp_error += std::pow(warped.image.at(x, y, c) - ref, 2.0) / scale;
                noise += std::pow(b_again.image.at(x, y, c) - ref, 2.0) / scale;
            }
        }
    }
    warp_error /= 3.0 * shared;
    noise /= 3.0 * shared;
    EXPECT_GT(shared, kWarpWidth * kWarpHeight / 2);
    EXPECT_LT(warp_error, 2.0 * noise) << "noise between two renders " << noise;
    // Holes are where A saw nothing (a pixel's blend of edges aside), and where A saw
    // nothing there are holes.
    EXPECT_GT(warped.holes, 50);
    EXPECT_EQ(warped.holes, std::count(warped.hole.begin(), warped.hole.end(), 1));
    EXPECT_LT(holes_seen, warped.holes / 5) << "holes where A saw the surface";
    EXPECT_LT(covered_unseen, unseen / 5) << "of " << unseen << " pixels A did not see";
}

TEST(ImageWarp, SameCameraGivesTheImageBackWithoutHoles) {
    const Rendered a = render_from(kCameraA, 1);
    const WarpResult same = warp_image(a.image, *a.camera, *a.camera, kWarpWidth, kWarpHeight);
    EXPECT_EQ(same.holes, 0);
    for (int y = 0; y < kWarpHeight; ++y)
        for (int x = 0; x < kWarpWidth; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(same.image.at(x, y, c), a.image.at(x, y, c),
                            1e-4f * (1.0f + a.image.at(x, y, c)));
}

TEST(ImageWarp, NeedsDepth) {
    const Rendered a = render_from(kCameraA, 1);
    const Image no_depth = without_channels(a.image, {"depth."});
    EXPECT_THROW(warp_image(no_depth, *a.camera, *a.camera, kWarpWidth, kWarpHeight), Error);
}

TEST(CameraAttributes, RoundTripThroughAnExrHeader) {
    Params camera("camera", "test");
    camera.set("type", std::string("orthographic"));
    camera.set("eye", std::vector<double>{1.25, -2, 3.1});
    camera.set("look_at", std::vector<double>{0, 0, 0});
    camera.set("scale", 3.3);
    Image image = make_image(4, 3, {"R", "G", "B"});
    image.attributes = camera_attributes(&camera, Vec2i(4, 3));
    const std::string path =
        (std::filesystem::path(testing::TempDir()) / "camera_attributes.exr").string();
    write_image(path, image);
    const auto stored = camera_from_attributes(read_image(path).attributes, path);
    ASSERT_TRUE(stored.has_value());
    EXPECT_EQ(stored->resolution, Vec2i(4, 3));
    EXPECT_EQ(stored->params.get_string("type"), "orthographic");
    EXPECT_EQ(stored->params.get_vec3("eye"), Vec3(1.25f, -2.0f, 3.1f));
    EXPECT_EQ(stored->params.get_float("scale"), 3.3f);
    EXPECT_FALSE(camera_from_attributes({}, path).has_value());
    EXPECT_THROW(camera_from_attributes({{"camera.type", "perspective"}}, path), Error);
}

}  // namespace
}  // namespace glint
