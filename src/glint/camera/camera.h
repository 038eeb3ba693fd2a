#pragma once
#include <glint/core/params.h>
#include <glint/core/ray.h>
#include <glint/core/sampler.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace glint {

class Camera {
public:
    virtual ~Camera() = default;
    // A primary ray through continuous film position `film` (pixels, origin at the top-left
    // corner, y down) using `lens` in [0,1)^2 for the aperture. Directions are unit length.
    // The ray carries differentials towards the neighbouring pixels, scaled by the
    // footprint scale, for texture filtering.
    virtual Ray generate_ray(const Vec2& film, const Vec2& lens) const = 0;
    // False for a pinhole: its rays ignore `lens`, so integrators need not draw the sample.
    virtual bool needs_lens_sample() const { return true; }
    // generate_ray with the lens sample drawn from `sampler`, only when the camera uses one,
    // so every integrator consumes the same sample dimensions for its camera rays.
    Ray sample_ray(const Vec2& film, Sampler& sampler) const {
        return generate_ray(film, needs_lens_sample() ? sampler.get_2d() : Vec2(0.5f));
    }

    // How far a point p on a surface with normal n moves per pixel step, for hits that
    // carry no ray differentials (after a bounce): pbrt-v4's approximation, which sees the
    // point from the camera as a camera ray would.
    virtual void approximate_footprint(const Vec3& p, const Vec3& n, Vec3& dpdx,
                                       Vec3& dpdy) const = 0;

    // With many samples per pixel each one need only filter a fraction of the pixel; pbrt-v4
    // scales differentials by max(1/8, 1/sqrt(spp)).
    void set_samples_per_pixel(int spp) {
        m_footprint_scale =
            std::max(0.125f, 1.0f / std::sqrt(static_cast<float>(std::max(1, spp))));
    }

protected:
    float m_footprint_scale = 1.0f;
};

// Perspective pinhole or thin-lens camera looking from `eye` at `look_at`.
// Right-handed: with y up and the camera looking along +z, +x appears on the image left.
class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const Vec3& eye, const Vec3& look_at, const Vec3& up, float fov_y_degrees,
                      Vec2i resolution, float aperture_radius, float focus_distance);
    Ray generate_ray(const Vec2& film, const Vec2& lens) const override;
    bool needs_lens_sample() const override { return m_aperture_radius > 0.0f; }
    void approximate_footprint(const Vec3& p, const Vec3& n, Vec3& dpdx, Vec3& dpdy) const override;

private:
    // Direction through film position `film` from the pinhole, with forward component 1.
    Vec3 pinhole_direction(const Vec2& film) const;

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
