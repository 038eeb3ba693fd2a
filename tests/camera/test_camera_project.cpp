// Camera::project is generate_ray backwards: a point on a camera ray projects to the film
// position the ray came from, at the distance along the ray the film's depth AOV records.
#include <glint/camera/camera.h>
#include <glint/camera/orthographic.h>

#include <gtest/gtest.h>

#include <memory>
#include <random>

namespace glint {
namespace {

constexpr Vec2i kResolution(64, 48);

void expect_round_trip(const Camera& camera) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 200; ++i) {
        const Vec2 film(u(rng) * kResolution.x, u(rng) * kResolution.y);
        const float depth = 0.5f + 20.0f * u(rng);
        const Ray ray = camera.generate_ray(film, Vec2(0.5f));
        const auto projected = camera.project(ray.origin + depth * ray.direction);
        ASSERT_TRUE(projected.has_value()) << "film " << film.x << ", " << film.y;
        EXPECT_NEAR(projected->film.x, film.x, 2e-3f);
        EXPECT_NEAR(projected->film.y, film.y, 2e-3f);
        EXPECT_NEAR(projected->depth, depth, 1e-4f * depth);
    }
}

TEST(CameraProject, PerspectiveInvertsGenerateRay) {
    const PerspectiveCamera camera(Vec3(1, 2, 3), Vec3(0, 0.5f, -1), Vec3(0, 1, 0), 50.0f,
                                   kResolution, 0.0f, 1.0f);
    expect_round_trip(camera);
    // A copy outlives the camera (ReSTIR projects onto the previous pass's) and projects alike.
    expect_round_trip(*camera.clone());
}

TEST(CameraProject, OrthographicInvertsGenerateRay) {
    const OrthographicCamera camera(Vec3(1, 2, 3), Vec3(0, 0.5f, -1), Vec3(0, 1, 0), 3.0f,
                                    kResolution);
    expect_round_trip(camera);
    expect_round_trip(*camera.clone());
}

TEST(CameraProject, PointsBehindHaveNoFilmPositionAndOutsideTheFrameLieOffIt) {
    const PerspectiveCamera perspective(Vec3(0), Vec3(0, 0, -1), Vec3(0, 1, 0), 90.0f, kResolution,
                                        0.0f, 1.0f);
    EXPECT_FALSE(perspective.project(Vec3(0, 0, 1)).has_value());  // behind
    EXPECT_FALSE(perspective.project(Vec3(0, 0, 0)).has_value());  // at the eye
    const auto above = perspective.project(Vec3(0, 1.5f, -1));
    ASSERT_TRUE(above.has_value());
    EXPECT_FLOAT_EQ(above->film.y, 24.0f - 1.5f * 24.0f);  // above the frame: y < 0
    const auto centre = perspective.project(Vec3(0, 0, -2));
    ASSERT_TRUE(centre.has_value());
    EXPECT_FLOAT_EQ(centre->film.x, 32.0f);
    EXPECT_FLOAT_EQ(centre->film.y, 24.0f);
    EXPECT_FLOAT_EQ(centre->depth, 2.0f);

    const OrthographicCamera orthographic(Vec3(0), Vec3(0, 0, -1), Vec3(0, 1, 0), 2.0f,
                                          kResolution);
    EXPECT_FALSE(orthographic.project(Vec3(0, 0, 1)).has_value());
    const auto off = orthographic.project(Vec3(0, 1.5f, -1));
    ASSERT_TRUE(off.has_value());
    EXPECT_FLOAT_EQ(off->film.y, -12.0f);
    const auto corner = orthographic.project(Vec3(-4.0f / 3.0f, 1.0f, -5.0f));
    ASSERT_TRUE(corner.has_value());
    EXPECT_NEAR(corner->film.x, 0.0f, 1e-4f);
    EXPECT_NEAR(corner->film.y, 0.0f, 1e-4f);
    EXPECT_FLOAT_EQ(corner->depth, 5.0f);  // along the view, not from the eye
}

}  // namespace
}  // namespace glint
