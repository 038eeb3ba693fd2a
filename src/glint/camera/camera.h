#pragma once
#include <glint/core/params.h>
#include <glint/core/ray.h>

#include <memory>

namespace glint {

class Camera {
public:
    virtual ~Camera() = default;
    // A primary ray through continuous film position `film` (pixels, origin at the top-left
    // corner, y down) using `lens` in [0,1)^2 for the aperture. Directions are unit length.
    virtual Ray generate_ray(const Vec2& film, const Vec2& lens) const = 0;
};

// Perspective pinhole or thin-lens camera looking from `eye` at `look_at`.
// Right-handed: with y up and the camera looking along +z, +x appears on the image left.
class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const Vec3& eye, const Vec3& look_at, const Vec3& up, float fov_y_degrees,
                      Vec2i resolution, float aperture_radius, float focus_distance);
    Ray generate_ray(const Vec2& film, const Vec2& lens) const override;

private:
    Vec3 m_eye, m_forward, m_right, m_up;
    float m_tan_half_fov;
    float m_aspect;
    Vec2 m_resolution;
    float m_aperture_radius;
    float m_focus_distance;
};

// Reads eye, look_at, up, fov (vertical, degrees), aperture (lens radius) and
// focus_distance (defaults to the look_at distance).
std::unique_ptr<Camera> make_camera(const Params& params, Vec2i resolution);

}  // namespace glint
