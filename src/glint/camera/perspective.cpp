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

Vec3 PerspectiveCamera::pinhole_direction(const Vec2& film) const {
    // Screen coordinates in [-1, 1], y up. Not normalised: its component along the
    // forward axis is exactly 1, which the thin lens below relies on.
    const float sx = 2.0f * film.x / m_resolution.x - 1.0f;
    const float sy = 1.0f - 2.0f * film.y / m_resolution.y;
    return m_forward + (sx * m_tan_half_fov * m_aspect) * m_right + (sy * m_tan_half_fov) * m_up;
}

Ray PerspectiveCamera::generate_ray(const Vec2& film, const Vec2& lens) const {
    const Vec3 direction = pinhole_direction(film);
    // One pixel to the right and one down, scaled by the footprint scale.
    const float pixel = 2.0f * m_tan_half_fov / m_resolution.y * m_footprint_scale;
    const Vec3 step_x = pixel * m_right, step_y = -pixel * m_up;
    Ray ray;
    ray.has_differentials = true;
    RayDifferentials& d = ray.differentials;
    if (m_aperture_radius <= 0.0f) {
        ray.origin = d.rx_origin = d.ry_origin = m_eye;
        ray.direction = glm::normalize(direction);
        // Differential directions need not be unit length: only where they meet a surface
        // matters.
        d.rx_direction = direction + step_x;
        d.ry_direction = direction + step_y;
        return ray;
    }
    // Thin lens: every ray through the lens from one film point meets the plane of focus
    // at the same point, eye + focus_distance * direction (direction has forward part 1).
    const Vec2 disk = m_aperture_radius * warp::square_to_uniform_disk_concentric(lens);
    const Vec3 origin = m_eye + disk.x * m_right + disk.y * m_up;
    const Vec3 focus_point = m_eye + m_focus_distance * direction;
    ray.origin = d.rx_origin = d.ry_origin = origin;
    ray.direction = glm::normalize(focus_point - origin);
    d.rx_direction = focus_point + m_focus_distance * step_x - origin;
    d.ry_direction = focus_point + m_focus_distance * step_y - origin;
    return ray;
}

void PerspectiveCamera::approximate_footprint(const Vec3& p, const Vec3& n, Vec3& dpdx,
                                              Vec3& dpdy) const {
    // A pinhole ray towards p, and its neighbours one (scaled) pixel step away in angle as
    // at the image centre; each neighbour is intersected with p's tangent plane.
    const Vec3 to_p = p - m_eye;
    const float distance = glm::length(to_p);
    dpdx = dpdy = Vec3(0.0f);
    if (!(distance > 0.0f)) return;
    const Vec3 d = to_p / distance;
    const float pixel_angle = 2.0f * m_tan_half_fov / m_resolution.y * m_footprint_scale;
    const float d_dot_n = glm::dot(d, n);
    auto on_plane = [&](const Vec3& step) {
        const Vec3 dir = d + pixel_angle * step;
        const float denom = glm::dot(dir, n);
        if (std::abs(denom) < 1e-6f * std::abs(d_dot_n) || std::abs(denom) < 1e-12f)
            return Vec3(0.0f);
        const float t = distance * d_dot_n / denom;
        return m_eye + t * dir - p;
    };
    dpdx = on_plane(m_right);
    dpdy = on_plane(-m_up);
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
