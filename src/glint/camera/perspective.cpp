#include <glint/camera/camera.h>
#include <glint/math/warp.h>

namespace glint {

PerspectiveCamera::PerspectiveCamera(const Vec3& eye, const Vec3& look_at, const Vec3& up,
                                     float fov_y_degrees, Vec2i resolution, float aperture_radius,
                                     float focus_distance)
    : m_eye(eye),
      m_forward(glm::normalize(look_at - eye)),
      m_tan_half_fov(std::tan(glm::radians(fov_y_degrees) * 0.5f)),
      m_aspect(static_cast<float>(resolution.x) / static_cast<float>(resolution.y)),
      m_resolution(resolution),
      m_aperture_radius(aperture_radius),
      m_focus_distance(focus_distance) {
    m_right = glm::normalize(glm::cross(m_forward, up));
    m_up = glm::cross(m_right, m_forward);
}

Ray PerspectiveCamera::generate_ray(const Vec2& film, const Vec2& lens) const {
    // Screen coordinates in [-1, 1], y up.
    const float sx = 2.0f * film.x / m_resolution.x - 1.0f;
    const float sy = 1.0f - 2.0f * film.y / m_resolution.y;
    const Vec3 direction = glm::normalize(m_forward + (sx * m_tan_half_fov * m_aspect) * m_right +
                                          (sy * m_tan_half_fov) * m_up);
    if (m_aperture_radius <= 0.0f) return Ray{m_eye, direction, 0.0f, kInfinity};
    // Thin lens: all rays through the lens meet at the plane of focus.
    const float t_focus = m_focus_distance / glm::dot(direction, m_forward);
    const Vec3 focus_point = m_eye + t_focus * direction;
    const Vec2 disk = m_aperture_radius * warp::square_to_uniform_disk_concentric(lens);
    const Vec3 origin = m_eye + disk.x * m_right + disk.y * m_up;
    return Ray{origin, glm::normalize(focus_point - origin), 0.0f, kInfinity};
}

std::unique_ptr<Camera> make_camera(const Params& params, Vec2i resolution) {
    const Vec3 eye = params.get_vec3("eye", Vec3(0, 0, 0));
    const Vec3 look_at = params.get_vec3("look_at", Vec3(0, 0, -1));
    const Vec3 up = params.get_vec3("up", Vec3(0, 1, 0));
    const float fov = params.get_float("fov", 45.0f);
    const float aperture = params.get_float("aperture", 0.0f);
    const float focus = params.get_float("focus_distance", glm::length(look_at - eye));
    if (glm::length(look_at - eye) <= 0.0f) params.fail("'look_at' must differ from 'eye'");
    if (glm::length(glm::cross(look_at - eye, up)) <= 0.0f) {
        params.fail("'up' must not be parallel to the viewing direction");
    }
    if (!(fov > 0.0f && fov < 180.0f)) params.fail("'fov' must be in (0, 180) degrees");
    if (aperture < 0.0f) params.fail("'aperture' must not be negative");
    if (!(focus > 0.0f)) params.fail("'focus_distance' must be positive");
    params.check_all_used();
    return std::make_unique<PerspectiveCamera>(eye, look_at, up, fov, resolution, aperture, focus);
}

}  // namespace glint
