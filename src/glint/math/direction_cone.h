#pragma once
// A cone of directions, the bound on the normals of a set of emitters (a light tree's
// orientation bound) that Conty Estevez and Kulla 2018 use.
#include <glint/math/vector.h>

namespace glint {

/// A cone of directions: every direction within angle acos(cos_theta) of `axis`.
struct DirectionCone {
    Vec3 axis{0.0f, 0.0f, 1.0f};
    float cos_theta = -1.0f;  ///< -1: the whole sphere
    bool empty = false;       ///< no direction at all (the identity of `merged`)

    static DirectionCone whole_sphere() { return {}; }
    static DirectionCone none() { return {Vec3(0.0f, 0.0f, 1.0f), 1.0f, true}; }
    /// The smallest cone (of this form) holding both.
    static DirectionCone merged(const DirectionCone& a, const DirectionCone& b);
};

}  // namespace glint
