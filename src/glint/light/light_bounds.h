#pragma once
// What a light tree knows of a light or a cluster of lights: where it is (a box), how much
// it emits (power), and which way (a cone of normals, plus the spread of emission about each
// normal). Conty Estevez and Kulla 2018, "Importance sampling of many lights with adaptive
// tree splitting"; the form pbrt-v4 uses.
#include <glint/math/bounds.h>
#include <glint/math/direction_cone.h>

#include <array>

namespace glint {

struct LightBounds {
    Bounds3 bounds;            ///< where the emitters are
    float phi = 0.0f;          ///< emitted power (luminance, W)
    DirectionCone normals;     ///< the emitters' normals (their main emission directions)
    float cos_theta_e = 0.0f;  ///< emission reaches acos(cos_theta_e) beyond each normal
                               ///< (pi / 2 for a surface: 0)
    bool two_sided = false;    ///< emits on both sides of each normal too

    /// The estimate of the light reaching `p` that LightBoundsX4::importances gives (one
    /// lane's worth; for tests and single clusters).
    float importance(const Vec3& p, const Vec3& n) const;

    static LightBounds merged(const LightBounds& a, const LightBounds& b);
};

/// Four LightBounds lane by lane (the children of a node of a 4-wide light tree), in the
/// form the importance needs: the box as the sphere round it, the cone's sine beside its
/// cosine. Lanes that hold no bounds have no power and get importance 0.
struct alignas(16) LightBoundsX4 {
    std::array<std::array<float, 4>, 3> center{};  ///< x, y, z of the boxes' centres
    std::array<float, 4> radius2{};                ///< squared radius of the sphere round each box
    std::array<float, 4> phi{};
    std::array<std::array<float, 4>, 3> axis{};  ///< the normal cones' axes
    std::array<float, 4> cos_theta_o{}, sin_theta_o{};
    std::array<float, 4> cos_theta_e{};
    std::array<float, 4> two_sided{};  ///< 1 where a lane emits on both sides, else 0

    void set(int lane, const LightBounds& b);

    /// For each lane, an estimate of the light reaching `p` (unit surface normal `n`, or
    /// zero for none) from its emitters: power over squared distance, times the cosine of
    /// the smallest angle between the direction to `p` and any direction the cone allows,
    /// times the largest |cos| at the receiver over the box (Conty Estevez and Kulla's
    /// bounds; |cos| because a surface that transmits takes light from both sides). Zero
    /// only where no emitter in the box can send light to `p`: the angle exceeds the
    /// emission spread by a margin that covers float rounding. The receiver's cosine never
    /// makes it zero. The four lanes are computed at once (SIMD, in light_bounds.cpp).
    std::array<float, 4> importances(const Vec3& p, const Vec3& n) const;
};

}  // namespace glint
