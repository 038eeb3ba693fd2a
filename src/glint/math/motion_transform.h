#pragma once
// A transform that moves over the shutter: keys spread evenly over the scene times [0, 1],
// interpolated by parts as Embree's quaternion motion interpolates them (translation and
// scale/shear linearly, rotation by slerp), so that glint and Embree agree on where a
// moving object is at any time.
#include <glint/math/bounds.h>
#include <glint/math/transform.h>

#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace glint {

/// An affine transform split as M = T R S: S upper triangular (scale on the diagonal,
/// shear above it), R a rotation, T a translation. Embree's RTCQuaternionDecomposition
/// holds the same parts.
struct TransformParts {
    Vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  ///< unit (w, x, y, z)
    Vec3 scale{1.0f};                            ///< S's diagonal
    Vec3 shear{0.0f};                            ///< S's (x,y), (x,z), (y,z) entries
};

/// The parts of `xf` (its linear part by Gram-Schmidt, a mirror kept in S's z scale).
TransformParts decompose(const Transform& xf);
/// T R S as a Transform.
Transform compose(const TransformParts& parts);

class MotionTransform {
public:
    /// Standing still at the identity.
    MotionTransform() = default;
    /// Standing still at `xf`.
    explicit MotionTransform(const Transform& xf) : MotionTransform(std::vector<Transform>{xf}) {}
    /// Keys at times i / (n - 1), i = 0 .. n - 1; one key stands still. Consecutive
    /// rotations are taken the short way round (under 180 degrees apart).
    explicit MotionTransform(std::vector<Transform> keys);

    bool is_moving() const { return m_keys.size() > 1; }
    size_t key_count() const { return m_keys.size(); }
    const Transform& key(size_t i) const { return m_keys[i]; }
    const TransformParts& parts(size_t i) const { return m_parts[i]; }

    /// The transform at scene time `time`, clamped to [0, 1]: at a key exactly the key.
    Transform at(float time) const;
    /// A box holding `local` at every key (the bounds of the path between keys are not
    /// bounded by it; used for statistics, not for culling).
    Bounds3 bounds_of_keys(const Bounds3& local) const;

    /// Keywise product: both standing still or moving with the same number of keys, or one
    /// of them still. Throws glint::Error when both move with different key counts.
    MotionTransform operator*(const MotionTransform& rhs) const;

private:
    std::vector<Transform> m_keys{Transform()};
    std::vector<TransformParts> m_parts{TransformParts{}};
};

}  // namespace glint
