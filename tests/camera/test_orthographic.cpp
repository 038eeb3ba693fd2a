// The orthographic camera (parallel rays, importance a delta in direction) and focus_on:
// sample_wi round-trips through generate_ray; a light-traced image agrees with the path
// tracer's, which checks We = 1 / A_film; camera parameters and their errors.
#include <glint/camera/orthographic.h>
#include <glint/core/error.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <random>

using namespace glint;

namespace {

const Vec3 kOrthoEye(1.0f, 2.0f, 3.0f);
const Vec3 kOrthoLookAt(0.0f, 1.5f, -2.0f);
const Vec3 kOrthoUp(0.0f, 1.0f, 0.0f);
const Vec2i kOrthoResolution(64, 48);
constexpr float kScale = 3.0f;

std::unique_ptr<Camera> camera_from(const std::string& code) {
    const SceneDesc desc = load_scene_string(code, "camera-test.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    return make_camera(*desc.camera, kOrthoResolution);
}

}  // namespace

TEST(OrthographicCamera, SampleWiRoundTripsThroughGenerateRay) {
    const OrthographicCamera camera(kOrthoEye, kOrthoLookAt, kOrthoUp, kScale, kOrthoResolution);
    const Vec3 forward = glm::normalize(kOrthoLookAt - kOrthoEye);
    EXPECT_NEAR(camera.film_area(), kScale * kScale * 64.0f / 48.0f, 1e-5f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int inside = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec2 film(u(rng) * kOrthoResolution.x, u(rng) * kOrthoResolution.y);
        const Ray ray = camera.generate_ray(film, Vec2(0.5f));
        EXPECT_GT(glm::dot(ray.direction, forward), 1.0f - 1e-6f);
        const Vec3 ref = ray.origin + (0.1f + 10.0f * u(rng)) * ray.direction;
        const std::optional<CameraWiSample> s = camera.sample_wi(ref, Vec2(u(rng), u(rng)));
        ASSERT_TRUE(s);
        ++inside;
        EXPECT_NEAR(s->film.x, film.x, 2e-3f);
        EXPECT_NEAR(s->film.y, film.y, 2e-3f);
        EXPECT_LT(glm::length(s->p_lens - ray.origin), 1e-4f);
        EXPECT_GT(glm::dot(s->wi, -forward), 1.0f - 1e-6f);
        EXPECT_FLOAT_EQ(s->pdf, 1.0f);
        EXPECT_FLOAT_EQ(to_rgb(s->We)[0], 1.0f / camera.film_area());
        // The footprint of a parallel ray on a plane facing the camera is one pixel.
        Vec3 dpdx, dpdy;
        camera.approximate_footprint(ref, -forward, dpdx, dpdy);
        EXPECT_NEAR(glm::length(dpdx), kScale / kOrthoResolution.y, 1e-4f);
    }
    EXPECT_EQ(inside, 500);
    // Behind the film plane, or beside the frame: no connection.
    EXPECT_FALSE(camera.sample_wi(kOrthoEye - forward, Vec2(0.5f)));
    const Ray corner = camera.generate_ray(Vec2(0.0f), Vec2(0.5f));
    const Vec3 right = glm::normalize(glm::cross(forward, kOrthoUp));
    EXPECT_FALSE(camera.sample_wi(corner.origin + 2.0f * forward - 0.01f * right, Vec2(0.5f)));
    // A delta in direction: no ray found by chance carries importance.
    EXPECT_EQ(to_rgb(camera.we(corner))[0], 0.0f);
    EXPECT_EQ(camera.pdf_we(corner).dir, 0.0f);
}

// A diffuse floor under a point light, seen from above at a slant by an orthographic
// camera: the light tracer (through sample_wi and We) and the path tracer (through
// generate_ray) must give the same image mean. Both are unbiased; the bound is 4 standard
// errors of the difference, estimated from the pixels.
TEST(OrthographicCamera, LightTracingAgreesWithPathTracing) {
    auto render = [](const std::string& integrator, int spp) {
        return glint::test::render_lua(R"(
            glint.camera{ type = "orthographic", eye = {0, 3, 2}, look_at = {0, 0, 0}, scale = 2 }
            glint.render{ width = 32, height = 24, spp = )" +
                                       std::to_string(spp) + R"(, integrator = ")" + integrator +
                                       R"(", seed = 5 }
            glint.quad{ vertices = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}},
                        material = glint.diffuse{ reflectance = 0.5 } }
            glint.point_light{ position = {0.5, 1.5, 0.3}, intensity = 4 }
        )");
    };
    const Image path = render("path", 16);
    const Image light = render("light", 64);
    double sum_path = 0, sum_light = 0, var = 0;
    const int n = path.width * path.height;
    for (int y = 0; y < path.height; ++y) {
        for (int x = 0; x < path.width; ++x) {
            sum_path += path.at(x, y, 1);
            sum_light += light.at(x, y, 1);
        }
    }
    const double mean_path = sum_path / n, mean_light = sum_light / n;
    // The per-pixel differences vary with the lighting; their spread bounds the noise.
    for (int y = 0; y < path.height; ++y) {
        for (int x = 0; x < path.width; ++x) {
            const double d = (light.at(x, y, 1) - path.at(x, y, 1)) - (mean_light - mean_path);
            var += d * d;
        }
    }
    const double se = std::sqrt(var / n / n);
    ASSERT_GT(mean_path, 0.01);
    EXPECT_NEAR(mean_light, mean_path, 4.0 * se + 0.01 * mean_path)
        << "ratio " << mean_light / mean_path;
}

TEST(CameraParameters, FocusOnSetsTheFocusDistanceAlongTheViewDirection) {
    // Looking along -z from z = 5: a point at z = 1, off the axis, is 4 away along it.
    auto focus_ray = [](const std::string& focus) {
        const std::unique_ptr<Camera> camera = camera_from(
            "glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0}, aperture = 0.5, " + focus + " }");
        return camera->generate_ray(Vec2(10.0f, 30.0f), Vec2(0.9f, 0.2f));
    };
    const Ray a = focus_ray("focus_on = {2, 1, 1}");
    const Ray b = focus_ray("focus_distance = 4");
    EXPECT_EQ(a.origin, b.origin);
    EXPECT_EQ(a.direction, b.direction);
    const Ray c = focus_ray("focus_distance = 4.5");
    EXPECT_NE(a.direction, c.direction);
}

TEST(CameraParameters, BadCamerasNameTheKey) {
    auto message = [](const std::string& code) {
        try {
            camera_from(code);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("glint.camera{ eye = {0, 0, 5}, focus_on = {0, 0, 7} }")
                  .find("'focus_on' must be in front of the camera"),
              std::string::npos);
    EXPECT_NE(message("glint.camera{ focus_on = {0, 0, -7}, focus_distance = 2 }").find("not both"),
              std::string::npos);
    EXPECT_NE(message("glint.camera{ type = 'fisheye' }").find("unknown camera type 'fisheye'"),
              std::string::npos);
    EXPECT_NE(message("glint.camera{ type = 'orthographic', scale = 0 }").find("'scale'"),
              std::string::npos);
    EXPECT_NE(message("glint.camera{ type = 'orthographic', fov = 30 }").find("fov"),
              std::string::npos);
    EXPECT_NE(message("glint.camera{ type = 'orthographic', scale = -1 }").find("camera-test.lua"),
              std::string::npos);
}
