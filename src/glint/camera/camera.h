#pragma once
#include <glint/core/params.h>
#include <glint/core/ray.h>
#include <glint/core/sampler.h>
#include <glint/core/spectrum.h>
#include <glint/math/motion_transform.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace glint {

/// A point on the lens seen from a point in the scene (Camera::sample_wi).
struct CameraWiSample {
    Vec3 wi;           ///< unit, from the reference point towards p_lens
    Spectrum We;       ///< importance the camera emits from p_lens towards the reference point
    float pdf = 0.0f;  ///< density of choosing p_lens, per unit solid angle as seen from the
                       ///< reference point
    Vec3 p_lens;       ///< the point on the lens (the eye for a pinhole)
    Vec2 film;         ///< film position (pixels, origin top-left, y down, as generate_ray
                       ///< takes it) the ray from p_lens through the reference point lands on
};

/// Where a scene point lands on the film (Camera::project).
struct FilmProjection {
    Vec2 film;    ///< film position (pixels, origin top-left, y down, as generate_ray takes it)
    float depth;  ///< distance along the camera ray from its origin to the point: what the
                  ///< film's depth AOV (AovSample::depth) holds for a hit there
};

/// Densities with which generate_ray produces a ray (Camera::pdf_we).
struct CameraPdf {
    float pos = 0.0f;  ///< of the origin, per unit lens area
    float dir = 0.0f;  ///< of the direction, per unit solid angle
};

/// Importance, the camera's side of light transport (for light tracing and bidirectional
/// methods), normalised as in pbrt-v4's PerspectiveCamera:
///   We(ray) = 1 / (A_lens A_image cos^4 theta) for a ray leaving the lens through the frame,
///   0 otherwise, where theta is the angle to the viewing direction (forward()), A_image the
///   area of the frame on the image plane at distance 1 from the lens, and A_lens = pi r^2
///   the lens area (1 for a pinhole). Then the integral of We cos theta over the lens and
///   the solid angle of the frame is 1, and a camera ray's pdf_we is {1 / A_lens,
///   1 / (A_image cos^3 theta)}: generate_ray with a film point uniform over the image and
///   a lens point uniform on the disc.
/// A light path vertex that connects to the lens (sample_wi) adds
///   beta f |cos| We / pdf
/// to the pixel at CameraWiSample::film, where beta is the path's throughput and f |cos|
/// its scattering towards wi; splatting every path's sum and scaling the film's splats by
/// (pixel count / number of light paths) gives the image in the units of add_sample's
/// radiance.

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
    // so every integrator consumes the same sample dimensions for its camera rays. Then,
    // when the scene moves (set_time_sampled), a time drawn from the sampler's next
    // dimension, uniform over the shutter (stratified as the sampler stratifies), and the
    // ray carried by the camera's own motion at that time.
    Ray sample_ray(const Vec2& film, Sampler& sampler) const {
        Ray ray = generate_ray(film, needs_lens_sample() ? sampler.get_2d() : Vec2(0.5f));
        if (m_time_sampled) [[unlikely]]
            move_to_time(ray, time_of_sample(sampler.get_1d()));
        else
            ray.time = m_shutter_open;
        return ray;
    }
    /// sample_ray at scene time `time`, drawing no time: for a walk whose time another walk
    /// chose (vcm's camera subpath takes the time of the light subpath it joins).
    Ray sample_ray_at(const Vec2& film, Sampler& sampler, float time) const {
        Ray ray = generate_ray(film, needs_lens_sample() ? sampler.get_2d() : Vec2(0.5f));
        move_to_time(ray, time);
        return ray;
    }
    /// The time of a walk that starts at a light and meets the camera there (light tracing,
    /// a light subpath of its own): drawn uniform over the shutter with `sampler`'s next
    /// dimension when the scene moves, the shutter's opening otherwise (no draw).
    float sample_time(Sampler& sampler) const {
        return m_time_sampled ? time_of_sample(sampler.get_1d()) : m_shutter_open;
    }

    /// The scene times [open, close] the shutter is open for, within the motion keys' span
    /// [0, 1]; open == close is an instant (no blur). Throws glint::Error otherwise.
    void set_shutter(float open, float close);
    float shutter_open() const { return m_shutter_open; }
    float shutter_close() const { return m_shutter_close; }
    /// The camera's own motion over [0, 1], applied to its rays in world space (the eye and
    /// view it was made with are those of the identity).
    void set_motion(MotionTransform motion) { m_motion = std::move(motion); }
    bool is_moving() const { return m_motion.is_moving(); }
    /// Whether sample_ray draws a time: set by the scene when something moves and the
    /// shutter stays open for a while; otherwise every ray has the shutter's opening time
    /// and no sample dimension goes to time, so still scenes keep their images bit for bit.
    void set_time_sampled(bool sampled) {
        m_time_sampled = sampled && m_shutter_close > m_shutter_open;
    }
    bool time_sampled() const { return m_time_sampled; }
    /// The scene time of time sample `u` in [0, 1): uniform over the shutter.
    float time_of_sample(float u) const {
        return std::min(m_shutter_close, m_shutter_open + u * (m_shutter_close - m_shutter_open));
    }

    /// Samples a point on the lens (from `u_lens` as generate_ray maps its lens sample) and
    /// the importance it sends towards `ref`; nullopt when `ref` is behind the camera,
    /// outside the frame, or on the lens.
    virtual std::optional<CameraWiSample> sample_wi(const Vec3& ref, const Vec2& u_lens) const = 0;
    /// sample_wi for the camera where its motion puts it at scene time `time`.
    std::optional<CameraWiSample> sample_wi_at(const Vec3& ref, const Vec2& u_lens,
                                               float time) const;
    /// Importance of a ray leaving the lens (unit direction; zero outside the frame or
    /// backwards); when `film` is non-null and the importance is not zero, sets the film
    /// position the ray comes from.
    virtual Spectrum we(const Ray& ray, Vec2* film = nullptr) const = 0;
    /// Densities with which generate_ray (a film point uniform over the whole image, the
    /// lens point uniform on its disc) produces `ray` (unit direction); zero outside the
    /// frame.
    virtual CameraPdf pdf_we(const Ray& ray) const = 0;
    /// pdf_we of a ray that leaves the lens at scene time ray.time.
    CameraPdf pdf_we_at(const Ray& ray) const;
    /// Whether every motion key only turns and moves the camera (no scale or shear): then
    /// densities on and through the lens are the same at every time, as the methods that
    /// join light paths to the lens (sample_wi_at, pdf_we_at) need.
    bool motion_is_rigid() const;
    /// The lens normal (the viewing direction), unit, for cosines at the lens.
    virtual Vec3 forward() const = 0;

    /// generate_ray backwards for the centre of the lens: the film position whose ray from
    /// the lens centre (the pinhole; for an orthographic camera its film rectangle) passes
    /// through `p`, and the distance along that ray. nullopt when `p` is behind the camera;
    /// the position may lie outside the frame [0, width] x [0, height] (a caller that warps
    /// whole triangles needs their corners off the frame too). For reprojecting earlier frames
    /// (view/reprojection.h) and warping images by their depth (view/image_warp.h).
    virtual std::optional<FilmProjection> project(const Vec3& p) const = 0;

    /// A copy of this camera, motion and all: what outlives the scene's camera when the viewer
    /// replaces it (ReSTIR's temporal reuse projects onto the previous pass's camera).
    virtual std::unique_ptr<Camera> clone() const = 0;

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

private:
    // Gives `ray` scene time `time` and moves it (with its differentials) as the camera
    // stands at that time.
    void move_to_time(Ray& ray, float time) const;

    float m_shutter_open = 0.0f, m_shutter_close = 0.0f;
    bool m_time_sampled = false;
    MotionTransform m_motion;
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
    std::optional<CameraWiSample> sample_wi(const Vec3& ref, const Vec2& u_lens) const override;
    Spectrum we(const Ray& ray, Vec2* film = nullptr) const override;
    CameraPdf pdf_we(const Ray& ray) const override;
    Vec3 forward() const override { return m_forward; }
    std::optional<FilmProjection> project(const Vec3& p) const override;
    std::unique_ptr<Camera> clone() const override {
        return std::make_unique<PerspectiveCamera>(*this);
    }

private:
    // Where a ray leaving the lens comes from on the film, with cos theta to the forward
    // axis; nullopt when it leaves backwards or outside the frame.
    struct FilmHit {
        Vec2 film;
        float cos_theta;
    };
    std::optional<FilmHit> film_hit(const Ray& ray) const;
    // The lens point for lens sample `u` (the eye for a pinhole), as generate_ray uses it.
    Vec3 lens_point(const Vec2& u) const;
    // A_lens: pi r^2, or 1 for a pinhole.
    float lens_area() const;

    // Direction through film position `film` from the pinhole, with forward component 1.
    Vec3 pinhole_direction(const Vec2& film) const;

    Vec3 m_eye, m_forward, m_right, m_up;
    float m_tan_half_fov;
    float m_aspect;
    Vec2 m_resolution;
    // Per camera ray, products rather than divisions: 2 / resolution (film to screen
    // coordinates), and a pixel's height on the plane at distance 1, 2 tan(fov / 2) / height.
    Vec2 m_screen_per_pixel;
    float m_pixel_height;
    float m_aperture_radius;
    float m_focus_distance;
    float m_image_area;  // A_image: the frame's area on the plane at distance 1
};

/// Reads glint.camera{...}: type ("perspective", the default, or "orthographic"), eye,
/// look_at, up; for a perspective camera fov (vertical, degrees), aperture (lens radius) and
/// either focus_distance (defaults to the look_at distance) or focus_on (a point whose
/// distance along the view direction becomes the focus distance); for an orthographic one
/// scale (the image's height in scene units). Errors name the key and the script line.
std::unique_ptr<Camera> make_camera(const Params& params, Vec2i resolution);

}  // namespace glint
