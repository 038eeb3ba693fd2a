#include <glint/camera/camera.h>
#include <glint/math/warp.h>

#include <fmt/format.h>

#include <algorithm>

namespace glint {

PerspectiveCamera::PerspectiveCamera(const Vec3& eye, const Vec3& look_at, const Vec3& up,
                                     float fov_y_degrees, Vec2i resolution, float aperture_radius,
                                     float focus_distance)
    : m_eye(eye),
      m_forward(glm::normalize(look_at - eye)),
      m_tan_half_fov(std::tan(glm::radians(fov_y_degrees) * 0.5f)),
      m_aspect(static_cast<float>(resolution.x) / static_cast<float>(resolution.y)),
      m_resolution(resolution),
      m_screen_per_pixel(2.0f / m_resolution.x, 2.0f / m_resolution.y),
      m_pixel_height(2.0f * m_tan_half_fov / m_resolution.y),
      m_aperture_radius(aperture_radius),
      m_focus_distance(focus_distance),
      m_image_area(4.0f * m_tan_half_fov * m_tan_half_fov * m_aspect) {
    m_right = glm::normalize(glm::cross(m_forward, up));
    m_up = glm::cross(m_right, m_forward);
}

Vec3 PerspectiveCamera::pinhole_direction(const Vec2& film) const {
    // Screen coordinates in [-1, 1], y up. Not normalised: its component along the
    // forward axis is exactly 1, which the thin lens below relies on.
    const float sx = film.x * m_screen_per_pixel.x - 1.0f;
    const float sy = 1.0f - film.y * m_screen_per_pixel.y;
    return m_forward + (sx * m_tan_half_fov * m_aspect) * m_right + (sy * m_tan_half_fov) * m_up;
}

Ray PerspectiveCamera::generate_ray(const Vec2& film, const Vec2& lens) const {
    const Vec3 direction = pinhole_direction(film);
    // One pixel to the right and one down, scaled by the footprint scale.
    const float pixel = m_pixel_height * m_footprint_scale;
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

Vec3 PerspectiveCamera::lens_point(const Vec2& u) const {
    if (m_aperture_radius <= 0.0f) return m_eye;
    const Vec2 disk = m_aperture_radius * warp::square_to_uniform_disk_concentric(u);
    return m_eye + disk.x * m_right + disk.y * m_up;
}

float PerspectiveCamera::lens_area() const {
    return m_aperture_radius > 0.0f ? kPi * m_aperture_radius * m_aperture_radius : 1.0f;
}

// generate_ray backwards. A thin-lens ray from film point f meets the plane of focus at
// eye + focus_distance * pinhole_direction(f), whatever its lens point; so a ray leaving
// the lens is traced to that plane and its point there, seen from the eye, gives f.
std::optional<PerspectiveCamera::FilmHit> PerspectiveCamera::film_hit(const Ray& ray) const {
    const float cos_theta = glm::dot(ray.direction, m_forward);
    if (!(cos_theta > 0.0f)) return std::nullopt;
    Vec3 through;  // from the eye through the film point, with forward component 1
    if (m_aperture_radius <= 0.0f) {
        through = ray.direction / cos_theta;
    } else {
        const Vec3 focus_point = ray.origin + (m_focus_distance / cos_theta) * ray.direction;
        through = (focus_point - m_eye) / m_focus_distance;
    }
    const float sx = glm::dot(through, m_right) / (m_tan_half_fov * m_aspect);
    const float sy = glm::dot(through, m_up) / m_tan_half_fov;
    // The frame is [-1, 1)^2 in (sx, -sy), as film positions [0, width) x [0, height).
    if (!(sx >= -1.0f && sx < 1.0f && sy > -1.0f && sy <= 1.0f)) return std::nullopt;
    const Vec2 film(0.5f * (sx + 1.0f) * m_resolution.x, 0.5f * (1.0f - sy) * m_resolution.y);
    return FilmHit{film, cos_theta};
}

std::optional<FilmProjection> PerspectiveCamera::project(const Vec3& p) const {
    const Vec3 to_p = p - m_eye;
    const float z = glm::dot(to_p, m_forward);
    if (!(z > 0.0f)) return std::nullopt;
    // pinhole_direction inverted: the screen coordinates of to_p / z (forward part 1).
    const float sx = glm::dot(to_p, m_right) / (z * m_tan_half_fov * m_aspect);
    const float sy = glm::dot(to_p, m_up) / (z * m_tan_half_fov);
    const Vec2 film(0.5f * (sx + 1.0f) * m_resolution.x, 0.5f * (1.0f - sy) * m_resolution.y);
    return FilmProjection{film, glm::length(to_p)};
}

Spectrum PerspectiveCamera::we(const Ray& ray, Vec2* film) const {
    const std::optional<FilmHit> hit = film_hit(ray);
    if (!hit) return Spectrum(0.0f);
    if (film) *film = hit->film;
    const float cos2 = hit->cos_theta * hit->cos_theta;
    return Spectrum(1.0f / (lens_area() * m_image_area * cos2 * cos2));
}

// A film point uniform over the image is a point uniform on the frame at distance 1, which
// seen from the lens has solid-angle density dist^2 / (A_image cos theta) with
// dist = 1 / cos theta. A thin lens keeps that density: the ray's direction is the one
// from the eye towards the same focus point, translated, and the lens point is independent.
CameraPdf PerspectiveCamera::pdf_we(const Ray& ray) const {
    const std::optional<FilmHit> hit = film_hit(ray);
    if (!hit) return {};
    const float c = hit->cos_theta;
    return {1.0f / lens_area(), 1.0f / (m_image_area * c * c * c)};
}

// A lens point uniform on the disc (the eye for a pinhole, whose "area" is 1), converted
// from area to solid angle as seen from ref: dist^2 / |cos theta at the lens|.
std::optional<CameraWiSample> PerspectiveCamera::sample_wi(const Vec3& ref,
                                                           const Vec2& u_lens) const {
    const Vec3 p_lens = lens_point(u_lens);
    const Vec3 to_lens = p_lens - ref;
    const float dist2 = glm::dot(to_lens, to_lens);
    if (!(dist2 > 0.0f)) return std::nullopt;
    const Vec3 wi = to_lens / std::sqrt(dist2);
    const std::optional<FilmHit> hit = film_hit(Ray{p_lens, -wi});
    if (!hit) return std::nullopt;
    CameraWiSample s;
    s.wi = wi;
    s.p_lens = p_lens;
    s.film = hit->film;
    const float cos2 = hit->cos_theta * hit->cos_theta;
    s.We = Spectrum(1.0f / (lens_area() * m_image_area * cos2 * cos2));
    s.pdf = dist2 / (hit->cos_theta * lens_area());
    return s;
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
    const float pixel_angle = m_pixel_height * m_footprint_scale;
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

}  // namespace glint
