#include <glint/core/error.h>
#include <glint/view/camera_controller.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

constexpr float kDegrees = kPi / 180.0f;

// `v` turned by `radians` about the unit `axis` (Rodrigues' formula).
Vec3 rotate(const Vec3& v, const Vec3& axis, float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

// Shortest text that reads back as the same float.
std::string number(float x) {
    return fmt::format("{}", x);
}
std::string vector_text(const Vec3& v) {
    return fmt::format("{{{}, {}, {}}}", number(v.x), number(v.y), number(v.z));
}

}  // namespace

CameraController::CameraController(const Params* camera)
    : m_table(camera ? *camera : Params("camera", "default camera")) {
    // make_camera's defaults.
    CameraPose pose;
    pose.eye = m_table.get_vec3("eye", Vec3(0.0f, 0.0f, 0.0f));
    pose.target = m_table.get_vec3("look_at", Vec3(0.0f, 0.0f, -1.0f));
    pose.up = m_table.get_vec3("up", Vec3(0.0f, 1.0f, 0.0f));
    set_pose(pose);
    m_initial = m_pose;
}

void CameraController::set_pose(const CameraPose& pose) {
    const Vec3 view = pose.target - pose.eye;
    if (!(glm::length(view) > 0.0f)) throw Error("the camera's target must differ from its eye");
    if (!(glm::length(glm::cross(view, pose.up)) > 0.0f))
        throw Error("the camera's up must not be parallel to its viewing direction");
    m_pose = pose;
    m_pose.up = glm::normalize(pose.up);
}

float CameraController::distance() const {
    return glm::length(m_pose.target - m_pose.eye);
}

void CameraController::orbit(float yaw_degrees, float pitch_degrees) {
    const Vec3 up = m_pose.up;
    Vec3 offset = rotate(m_pose.eye - m_pose.target, up, yaw_degrees * kDegrees);
    // Pitch as a change of the angle between the offset and up, clamped away from the poles.
    const float length = glm::length(offset);
    const float theta = std::acos(std::clamp(glm::dot(offset / length, up), -1.0f, 1.0f));
    const float wanted = std::clamp(theta - pitch_degrees * kDegrees, kDegrees, kPi - kDegrees);
    const Vec3 right = glm::normalize(glm::cross(up, offset));
    offset = rotate(offset, right, wanted - theta);  // about up x offset: away from up
    m_pose.eye = m_pose.target + offset;
}

void CameraController::pan(float right, float up) {
    const Vec3 forward = glm::normalize(m_pose.target - m_pose.eye);
    const Vec3 side = glm::normalize(glm::cross(forward, m_pose.up));
    const Vec3 lift = glm::cross(side, forward);
    const Vec3 step = (side * right + lift * up) * distance();
    m_pose.eye += step;
    m_pose.target += step;
}

void CameraController::zoom(float factor) {
    if (!(factor > 0.0f) || !std::isfinite(factor)) return;
    m_pose.eye = m_pose.target + (m_pose.eye - m_pose.target) * factor;
}

void CameraController::fly(const Vec3& step) {
    const Vec3 forward = glm::normalize(m_pose.target - m_pose.eye);
    const Vec3 side = glm::normalize(glm::cross(forward, m_pose.up));
    const Vec3 lift = glm::cross(side, forward);
    const Vec3 move = side * step.x + lift * step.y + forward * step.z;
    m_pose.eye += move;
    m_pose.target += move;
}

Params CameraController::params() const {
    Params table = m_table;
    table.set("eye", numbers_of(m_pose.eye));
    table.set("look_at", numbers_of(m_pose.target));
    table.set("up", numbers_of(m_pose.up));
    return table;
}

std::string CameraController::lua() const {
    std::string line =
        fmt::format("glint.camera{{ eye = {}, look_at = {}, up = {}", vector_text(m_pose.eye),
                    vector_text(m_pose.target), vector_text(m_pose.up));
    // The scene's other camera keys, as it gave them (a copy: reading marks keys as used).
    const Params table = m_table;
    if (table.has("type")) line += fmt::format(", type = \"{}\"", table.get_string("type"));
    for (const char* key : {"fov", "aperture", "focus_distance", "scale"}) {
        if (table.has(key)) line += fmt::format(", {} = {}", key, number(table.get_float(key)));
    }
    if (table.has("focus_on"))
        line += fmt::format(", focus_on = {}", vector_text(table.get_vec3("focus_on")));
    return line + " }";
}

}  // namespace glint
