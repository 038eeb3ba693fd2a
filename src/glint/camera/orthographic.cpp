#include <glint/camera/orthographic.h>

namespace glint {

OrthographicCamera::OrthographicCamera(const Vec3& eye, const Vec3& look_at, const Vec3& up,
                                       float scale, Vec2i resolution)
    : m_eye(eye),
      m_forward(glm::normalize(look_at - eye)),
      m_half_width(0.5f * scale * static_cast<float>(resolution.x) /
                   static_cast<float>(resolution.y)),
      m_half_height(0.5f * scale),
      m_resolution(resolution) {
    m_right = glm::normalize(glm::cross(m_forward, up));
    m_up = glm::cross(m_right, m_forward);
}

Vec3 OrthographicCamera::film_point(const Vec2& film) const {
    const float sx = 2.0f * film.x / m_resolution.x - 1.0f;
    const float sy = 1.0f - 2.0f * film.y / m_resolution.y;
    return m_eye + (sx * m_half_width) * m_right + (sy * m_half_height) * m_up;
}

Ray OrthographicCamera::generate_ray(const Vec2& film, const Vec2&) const {
    // Neighbouring pixels' rays are parallel, one (scaled) pixel apart.
    const float pixel = 2.0f * m_half_height / m_resolution.y * m_footprint_scale;
    Ray ray;
    ray.origin = film_point(film);
    ray.direction = m_forward;
    ray.has_differentials = true;
    ray.differentials.rx_origin = ray.origin + pixel * m_right;
    ray.differentials.ry_origin = ray.origin - pixel * m_up;
    ray.differentials.rx_direction = ray.differentials.ry_direction = m_forward;
    return ray;
}

std::optional<CameraWiSample> OrthographicCamera::sample_wi(const Vec3& ref, const Vec2&) const {
    const float depth = glm::dot(ref - m_eye, m_forward);
    if (!(depth > 0.0f)) return std::nullopt;
    const Vec3 p_film = ref - depth * m_forward;
    const float sx = glm::dot(p_film - m_eye, m_right) / m_half_width;
    const float sy = glm::dot(p_film - m_eye, m_up) / m_half_height;
    // The frame is [-1, 1)^2 in (sx, -sy), as film positions [0, width) x [0, height).
    if (!(sx >= -1.0f && sx < 1.0f && sy > -1.0f && sy <= 1.0f)) return std::nullopt;
    CameraWiSample s;
    s.wi = -m_forward;
    s.p_lens = p_film;
    s.film = Vec2(0.5f * (sx + 1.0f) * m_resolution.x, 0.5f * (1.0f - sy) * m_resolution.y);
    s.We = Spectrum(1.0f / film_area());
    s.pdf = 1.0f;  // the delta direction, chosen with certainty
    return s;
}

std::optional<FilmProjection> OrthographicCamera::project(const Vec3& p) const {
    const float depth = glm::dot(p - m_eye, m_forward);
    if (!(depth > 0.0f)) return std::nullopt;
    const float sx = glm::dot(p - m_eye, m_right) / m_half_width;
    const float sy = glm::dot(p - m_eye, m_up) / m_half_height;
    const Vec2 film(0.5f * (sx + 1.0f) * m_resolution.x, 0.5f * (1.0f - sy) * m_resolution.y);
    return FilmProjection{film, depth};
}

Spectrum OrthographicCamera::we(const Ray&, Vec2*) const {
    return Spectrum(0.0f);
}

CameraPdf OrthographicCamera::pdf_we(const Ray&) const {
    return {};
}

void OrthographicCamera::approximate_footprint(const Vec3& p, const Vec3& n, Vec3& dpdx,
                                               Vec3& dpdy) const {
    // A parallel ray one pixel step to the side, met on p's tangent plane.
    const float pixel = 2.0f * m_half_height / m_resolution.y * m_footprint_scale;
    const float cos_n = glm::dot(m_forward, n);
    auto on_plane = [&](const Vec3& step) {
        if (std::abs(cos_n) < 1e-6f) return Vec3(0.0f);
        return step - (glm::dot(step, n) / cos_n) * m_forward;
    };
    (void)p;
    dpdx = on_plane(pixel * m_right);
    dpdy = on_plane(-pixel * m_up);
}

}  // namespace glint
