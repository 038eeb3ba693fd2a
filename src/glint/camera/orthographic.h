#pragma once
#include <glint/camera/camera.h>

namespace glint {

/// Orthographic camera: parallel rays along the viewing direction from a `scale` x
/// (scale * aspect) rectangle of the plane through `eye` perpendicular to it (scale is the
/// image's height in scene units). No lens, no perspective.
///
/// Importance is a delta in direction (every ray leaves along forward()), so a light path
/// reaches the camera only by a deterministic connection, as a directional light is
/// reached: sample_wi projects the reference point along -forward onto the film rectangle,
/// with pdf = 1 (the delta's weight) and We = 1 / A_film, A_film = scale^2 * aspect. A path
/// vertex then adds beta f |cos| / A_film, which, with the film's (pixel count / paths)
/// scale, is the mean of L cos dA / A_film over the pixel: the pixel's radiance. A ray found
/// by chance (we(), pdf_we().dir) never carries the camera's delta: both are 0.
class OrthographicCamera final : public Camera {
public:
    OrthographicCamera(const Vec3& eye, const Vec3& look_at, const Vec3& up, float scale,
                       Vec2i resolution);
    Ray generate_ray(const Vec2& film, const Vec2& lens) const override;
    bool needs_lens_sample() const override { return false; }
    void approximate_footprint(const Vec3& p, const Vec3& n, Vec3& dpdx, Vec3& dpdy) const override;
    std::optional<CameraWiSample> sample_wi(const Vec3& ref, const Vec2& u_lens) const override;
    Spectrum we(const Ray& ray, Vec2* film = nullptr) const override;
    CameraPdf pdf_we(const Ray& ray) const override;
    Vec3 forward() const override { return m_forward; }
    std::optional<FilmProjection> project(const Vec3& p) const override;
    std::unique_ptr<Camera> clone() const override {
        return std::make_unique<OrthographicCamera>(*this);
    }

    /// A_film: the area of the film rectangle, in scene units squared.
    float film_area() const { return m_half_width * m_half_height * 4.0f; }

private:
    // The point of the film rectangle for film position `film` (pixels, y down).
    Vec3 film_point(const Vec2& film) const;

    Vec3 m_eye, m_forward, m_right, m_up;
    float m_half_width, m_half_height;
    Vec2 m_resolution;
};

}  // namespace glint
