#include <glint/camera/camera.h>
#include <glint/camera/orthographic.h>
#include <glint/core/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

void Camera::set_shutter(float open, float close) {
    if (!(open >= 0.0f && close <= 1.0f && open <= close)) {
        throw Error(
            fmt::format("the shutter [{:g}, {:g}] must lie within the motion's span "
                        "[0, 1], opening before it closes",
                        open, close));
    }
    m_shutter_open = open;
    m_shutter_close = close;
}

void Camera::move_to_time(Ray& ray, float time) const {
    ray.time = time;
    if (!m_motion.is_moving()) return;
    const Transform xf = m_motion.at(ray.time);
    ray.origin = xf.point(ray.origin);
    ray.direction = glm::normalize(xf.vector(ray.direction));
    RayDifferentials& d = ray.differentials;
    d.rx_origin = xf.point(d.rx_origin);
    d.ry_origin = xf.point(d.ry_origin);
    d.rx_direction = xf.vector(d.rx_direction);
    d.ry_direction = xf.vector(d.ry_direction);
}

std::optional<CameraWiSample> Camera::sample_wi_at(const Vec3& ref, const Vec2& u_lens,
                                                   float time) const {
    if (!m_motion.is_moving()) return sample_wi(ref, u_lens);
    // In the camera's own frame at that time, then back: the frame only turns and moves
    // (motion_is_rigid), so the solid-angle density at ref is the same in both.
    const Transform xf = m_motion.at(time);
    std::optional<CameraWiSample> s = sample_wi(xf.inverse().point(ref), u_lens);
    if (s) {
        s->wi = glm::normalize(xf.vector(s->wi));
        s->p_lens = xf.point(s->p_lens);
    }
    return s;
}

CameraPdf Camera::pdf_we_at(const Ray& ray) const {
    if (!m_motion.is_moving()) return pdf_we(ray);
    const Transform to_camera = m_motion.at(ray.time).inverse();
    Ray local = ray;
    local.origin = to_camera.point(ray.origin);
    local.direction = glm::normalize(to_camera.vector(ray.direction));
    return pdf_we(local);
}

bool Camera::motion_is_rigid() const {
    constexpr float kTolerance = 1e-4f;
    for (size_t i = 0; i < m_motion.key_count(); ++i) {
        const TransformParts& parts = m_motion.parts(i);
        if (glm::length(parts.scale - Vec3(1.0f)) > kTolerance ||
            glm::length(parts.shear) > kTolerance)
            return false;
    }
    return true;
}

namespace {

// glint.camera{ shutter = {open, close} }: two scene times within [0, 1].
void read_shutter(const Params& params, Camera& camera) {
    if (!params.has("shutter")) return;
    const std::vector<double> shutter = params.get_numbers("shutter");
    if (shutter.size() != 2) params.fail_at("shutter", "'shutter' must be two times {open, close}");
    try {
        camera.set_shutter(static_cast<float>(shutter[0]), static_cast<float>(shutter[1]));
    } catch (const Error& e) {
        params.fail_at("shutter", e.what());
    }
}

std::unique_ptr<Camera> make_camera_of_type(const Params& params, Vec2i resolution);

}  // namespace

std::unique_ptr<Camera> make_camera(const Params& params, Vec2i resolution) {
    std::unique_ptr<Camera> camera = make_camera_of_type(params, resolution);
    read_shutter(params, *camera);
    params.check_all_used();
    return camera;
}

namespace {

std::unique_ptr<Camera> make_camera_of_type(const Params& params, Vec2i resolution) {
    const std::string type = params.get_string("type", "perspective");
    const Vec3 eye = params.get_vec3("eye", Vec3(0, 0, 0));
    const Vec3 look_at = params.get_vec3("look_at", Vec3(0, 0, -1));
    const Vec3 up = params.get_vec3("up", Vec3(0, 1, 0));
    if (glm::length(look_at - eye) <= 0.0f) params.fail("'look_at' must differ from 'eye'");
    if (glm::length(glm::cross(look_at - eye, up)) <= 0.0f) {
        params.fail("'up' must not be parallel to the viewing direction");
    }
    // Rays are floats: coordinates and lengths beyond this overflow when squared (a ray's
    // direction is normalised), and the rays Embree gets would not be finite.
    constexpr float kLargest = 1e12f;
    for (const char* name : {"eye", "look_at", "up"}) {
        const Vec3 v = params.get_vec3(name, Vec3(0.0f));
        if (std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}) > kLargest)
            params.fail(fmt::format("'{}' must lie within {:g} of the origin", name, kLargest));
    }
    if (type == "orthographic") {
        const float scale = params.get_float("scale", 2.0f);
        if (!(scale > 0.0f) || !std::isfinite(scale))
            params.fail_at("scale", "'scale' (the image's height in scene units) must be positive");
        if (scale > kLargest) params.fail(fmt::format("'scale' must be at most {:g}", kLargest));
        return std::make_unique<OrthographicCamera>(eye, look_at, up, scale, resolution);
    }
    if (type != "perspective") {
        params.fail_at(
            "type",
            fmt::format("unknown camera type '{}' (expected: perspective, orthographic)", type));
    }
    const float fov = params.get_float("fov", 45.0f);
    const float aperture = params.get_float("aperture", 0.0f);
    const Vec3 forward = glm::normalize(look_at - eye);
    float focus = glm::length(look_at - eye);
    if (params.has("focus_on")) {
        if (params.has("focus_distance"))
            params.fail_at("focus_on", "give 'focus_on' or 'focus_distance', not both");
        // The plane of focus passes through the point: its distance along the view direction.
        focus = glm::dot(params.get_vec3("focus_on") - eye, forward);
        if (!(focus > 0.0f))
            params.fail_at("focus_on", "'focus_on' must be in front of the camera");
    } else {
        focus = params.get_float("focus_distance", focus);
    }
    if (!(fov > 0.0f && fov < 180.0f)) params.fail("'fov' must be in (0, 180) degrees");
    if (aperture < 0.0f) params.fail("'aperture' must not be negative");
    if (!(focus > 0.0f)) params.fail("'focus_distance' must be positive");
    if (aperture > kLargest) params.fail(fmt::format("'aperture' must be at most {:g}", kLargest));
    if (focus > kLargest)
        params.fail(fmt::format("'focus_distance' must be at most {:g}", kLargest));
    return std::make_unique<PerspectiveCamera>(eye, look_at, up, fov, resolution, aperture, focus);
}

}  // namespace

}  // namespace glint
