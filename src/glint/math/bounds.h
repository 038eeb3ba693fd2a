#pragma once
#include <glint/math/transform.h>
#include <glint/math/vector.h>

namespace glint {

struct Bounds3 {
    Vec3 min{kInfinity};
    Vec3 max{-kInfinity};

    bool is_empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void expand(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Bounds3& b) {
        if (b.is_empty()) return;
        expand(b.min);
        expand(b.max);
    }
    Vec3 center() const { return 0.5f * (min + max); }
    Vec3 extent() const { return max - min; }

    // Bounds of the eight transformed corners.
    Bounds3 transformed(const Transform& xf) const {
        Bounds3 result;
        if (is_empty()) return result;
        for (int corner = 0; corner < 8; ++corner) {
            result.expand(xf.point(Vec3(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y,
                                        corner & 4 ? max.z : min.z)));
        }
        return result;
    }
};

}  // namespace glint
