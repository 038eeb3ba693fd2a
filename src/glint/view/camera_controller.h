#pragma once
// The viewer's camera: a look-at pose moved by the mouse and keys (orbit, pan, zoom, fly),
// turned back into a glint.camera{...} table for make_camera() and into a line of Lua to
// paste into a scene. Plain math, no window: the tests drive it directly.
#include <glint/core/params.h>
#include <glint/math/vector.h>

#include <string>

namespace glint {

/// Where a look-at camera is (scene units), what it looks at, and which way is up (unit).
struct CameraPose {
    Vec3 eye{0.0f, 0.0f, 0.0f};
    Vec3 target{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
};

class CameraController {
public:
    /// Starts from the scene's glint.camera{...} table, or the default camera when it is
    /// null; every other key of the table (type, fov, aperture, focus, scale) is kept.
    explicit CameraController(const Params* camera);

    const CameraPose& pose() const { return m_pose; }
    /// Throws glint::Error unless the target differs from the eye and up is not parallel
    /// to the view (make_camera's own conditions).
    void set_pose(const CameraPose& pose);
    /// The distance from the eye to the target.
    float distance() const;

    /// Turns the eye around the target, `yaw` degrees about the up axis and `pitch` degrees
    /// about the camera's right axis (positive: the eye rises). The distance to the target
    /// stays; the eye stops 1 degree short of straight above or below the target, so that
    /// up never becomes the viewing direction.
    void orbit(float yaw_degrees, float pitch_degrees);
    /// Moves eye and target together across the view: `right` and `up` are fractions of
    /// the distance to the target.
    void pan(float right, float up);
    /// Moves the eye along the view: the distance to the target becomes distance * factor
    /// (factor > 0; < 1 comes closer).
    void zoom(float factor);
    /// Moves eye and target together by `step` in scene units: x to the right of the view,
    /// y along up, z forward (WASD/QE).
    void fly(const Vec3& step);
    /// Back to the pose the scene gave.
    void reset() { m_pose = m_initial; }

    /// The camera table with the current pose, ready for make_camera().
    Params params() const;
    /// The current camera as one line of a scene script, e.g.
    /// `glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3
    /// }`; numbers are printed so that they read back as the same floats.
    std::string lua() const;

private:
    Params m_table;  // the scene's camera table, eye, look_at and up replaced in params()
    CameraPose m_initial;
    CameraPose m_pose;
};

}  // namespace glint
