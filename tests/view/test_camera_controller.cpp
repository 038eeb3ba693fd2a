// The viewer's camera controller: orbit keeps the distance to the target, pan and fly move
// eye and target together, and the printed line reads back as the same camera.
#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/view/camera_controller.h>

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

Params camera_table(const std::string& line) {
    const SceneDesc desc = load_scene_string(line, "camera.lua");
    EXPECT_TRUE(desc.camera.has_value());
    return *desc.camera;
}

CameraController cornell_controller() {
    const Params table = camera_table(
        "glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, "
        "fov = 39.3077 }");
    return CameraController(&table);
}

float angle_to_up(const CameraController& c) {
    const Vec3 offset = glm::normalize(c.pose().eye - c.pose().target);
    return std::acos(glm::dot(offset, c.pose().up)) * 180.0f / 3.14159265f;
}

TEST(CameraController, OrbitKeepsTheDistanceToTheTarget) {
    CameraController c = cornell_controller();
    const float distance = c.distance();
    const Vec3 target = c.pose().target;
    const float moves[][2] = {{30, 0}, {0, 20}, {-75, -40}, {190, 10}, {5, 85}, {-360, -5}};
    for (const auto& move : moves) {
        const Vec3 before = c.pose().eye;
        c.orbit(move[0], move[1]);
        EXPECT_NEAR(c.distance(), distance, 1e-4f * distance);
        EXPECT_EQ(c.pose().target, target);
        EXPECT_GT(glm::length(c.pose().eye - before), 1.0f) << "the eye must move";
    }
}

TEST(CameraController, OrbitYawAndPitchAngles) {
    CameraController c = cornell_controller();
    EXPECT_NEAR(angle_to_up(c), 90.0f, 1e-3f);
    c.orbit(90.0f, 0.0f);  // a quarter turn about y: the eye moves from -z to a side
    EXPECT_NEAR(std::abs(c.pose().eye.x - 278.0f), 800.0f, 0.05f);
    EXPECT_NEAR(c.pose().eye.z, 0.0f, 0.05f);
    c.orbit(0.0f, 30.0f);  // the eye rises by 30 degrees
    EXPECT_NEAR(angle_to_up(c), 60.0f, 1e-2f);
    c.orbit(0.0f, 500.0f);  // stops a degree short of the pole
    EXPECT_NEAR(angle_to_up(c), 1.0f, 1e-2f);
    c.orbit(0.0f, -500.0f);
    EXPECT_NEAR(angle_to_up(c), 179.0f, 1e-2f);
}

TEST(CameraController, PanFlyZoomAndReset) {
    CameraController c = cornell_controller();
    const CameraPose start = c.pose();
    c.pan(0.1f, -0.05f);
    EXPECT_NEAR(c.distance(), 800.0f, 1e-3f);
    EXPECT_NEAR(glm::length(c.pose().eye - start.eye), 800.0f * std::hypot(0.1f, 0.05f), 1e-2f);
    EXPECT_NEAR(c.pose().eye.y - start.eye.y, -40.0f, 1e-3f);
    const Vec3 moved = c.pose().eye - start.eye;
    EXPECT_NEAR(glm::length((c.pose().target - start.target) - moved), 0.0f, 1e-3f);

    c.reset();
    c.fly(Vec3(0.0f, 0.0f, 100.0f));  // forward is +z here
    EXPECT_NEAR(c.pose().eye.z, -700.0f, 1e-3f);
    EXPECT_NEAR(c.pose().target.z, 100.0f, 1e-3f);
    c.fly(Vec3(10.0f, 20.0f, 0.0f));  // right and up
    EXPECT_NEAR(c.pose().eye.y, 293.0f, 1e-3f);
    EXPECT_NEAR(std::abs(c.pose().eye.x - 278.0f), 10.0f, 1e-3f);

    c.reset();
    c.zoom(0.5f);
    EXPECT_NEAR(c.distance(), 400.0f, 1e-3f);
    EXPECT_EQ(c.pose().target, start.target);
    c.reset();
    EXPECT_EQ(c.pose().eye, start.eye);
    EXPECT_EQ(c.pose().target, start.target);
}

TEST(CameraController, RejectsDegeneratePoses) {
    CameraController c = cornell_controller();
    EXPECT_THROW(c.set_pose({Vec3(1.0f), Vec3(1.0f), Vec3(0, 1, 0)}), Error);
    EXPECT_THROW(c.set_pose({Vec3(0.0f), Vec3(0, 5, 0), Vec3(0, 1, 0)}), Error);
}

// Rays of two cameras through the same film points, bit for bit.
void expect_same_camera(const Params& a, const Params& b) {
    const Vec2i resolution(64, 48);
    const auto ca = make_camera(a, resolution), cb = make_camera(b, resolution);
    for (const Vec2 film : {Vec2(0.5f, 0.5f), Vec2(31.25f, 17.5f), Vec2(63.9f, 47.1f)}) {
        for (const Vec2 lens : {Vec2(0.5f), Vec2(0.1f, 0.8f)}) {
            const Ray ra = ca->generate_ray(film, lens), rb = cb->generate_ray(film, lens);
            EXPECT_EQ(ra.origin, rb.origin);
            EXPECT_EQ(ra.direction, rb.direction);
        }
    }
}

class PrintedCamera : public testing::TestWithParam<std::string> {};

// The line the viewer prints, pasted into a scene, gives the camera the viewer shows.
TEST_P(PrintedCamera, ReadsBackAsTheSameCamera) {
    const Params table = camera_table(GetParam());
    CameraController c(&table);
    c.orbit(37.0f, -12.5f);
    c.pan(0.013f, 0.021f);
    c.zoom(0.77f);
    const std::string line = c.lua();
    SCOPED_TRACE(line);
    EXPECT_EQ(line.rfind("glint.camera{", 0), 0u);
    expect_same_camera(camera_table(line), c.params());
}

INSTANTIATE_TEST_SUITE_P(
    View, PrintedCamera,
    testing::Values(
        "glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, fov = 39.3077 }",
        "glint.camera{ eye = {0.1, 3.3, 5.7}, look_at = {0, 0.5, 0}, up = {0, 1, 0.2}, "
        "fov = 40, aperture = 0.05, focus_distance = 4.5 }",
        "glint.camera{ eye = {1, 2, 3}, look_at = {0, 0, 0}, focus_on = {0.5, 0, 0}, "
        "aperture = 0.1 }",
        "glint.camera{ type = 'orthographic', eye = {0, 5, 5}, look_at = {0, 0, 0}, "
        "scale = 3.5 }"));

TEST(CameraController, DefaultCamera) {
    CameraController c(nullptr);
    EXPECT_EQ(c.pose().eye, Vec3(0.0f));
    EXPECT_EQ(c.pose().target, Vec3(0.0f, 0.0f, -1.0f));
    expect_same_camera(camera_table(c.lua()), Params("camera", "default camera"));
}

}  // namespace
}  // namespace glint
