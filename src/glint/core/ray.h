#pragma once
#include <glint/math/vector.h>

namespace glint {

// Two neighbouring rays, one pixel (scaled by the sample density) to the right and one
// below, that tell how large a texture footprint a hit covers (Igehy 1999).
struct RayDifferentials {
    Vec3 rx_origin, rx_direction;
    Vec3 ry_origin, ry_direction;
};

struct Ray {
    Vec3 origin;
    Vec3 direction;
    float t_min = 0.0f;
    float t_max = kInfinity;
    // Scene time the ray sees moving geometry at (0 at the first motion key, 1 at the last;
    // see Camera::sample_ray): every ray of a path carries its camera ray's time.
    float time = 0.0f;
    // Camera rays carry differentials; rays after a bounce do not, and the camera
    // approximates their footprint instead (see SurfaceInteraction::set_footprint).
    bool has_differentials = false;
    RayDifferentials differentials{};

    Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace glint
