#pragma once
#include <glint/math/vector.h>

namespace glint {

struct Ray {
    Vec3 origin;
    Vec3 direction;
    float t_min = 0.0f;
    float t_max = kInfinity;

    Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace glint
