#pragma once
// What a light tree knows of a light or a cluster of lights: where it is (a box), how much
// it emits (power), and which way (a cone of normals, plus the spread of emission about each
// normal). Conty Estevez and Kulla 2018, "Importance sampling of many lights with adaptive
// tree splitting"; the form pbrt-v4 uses.
#include <glint/math/bounds.h>
#include <glint/math/direction_cone.h>

namespace glint {

struct LightBounds {
    Bounds3 bounds;            ///< where the emitters are
    float phi = 0.0f;          ///< emitted power (luminance, W)
    DirectionCone normals;     ///< the emitters' normals (their main emission directions)
    float cos_theta_e = 0.0f;  ///< emission reaches acos(cos_theta_e) beyond each normal
                               ///< (pi / 2 for a surface: 0)
    bool two_sided = false;    ///< emits on both sides of each normal too

    /// An estimate of the light reaching `p` (unit surface normal `n`, or zero for none)
    /// from these emitters: power over squared distance, times the cosine of the smallest
    /// angle between the direction to `p` and any direction the cone allows, times the
    /// largest |cos| at the receiver over the box (Conty Estevez and Kulla's bounds; |cos|
    /// because a surface that transmits takes light from both sides). Zero only where no
    /// emitter in the box can send light to `p`: the angle exceeds the emission spread by a
    /// margin that covers float rounding. The receiver's cosine never makes it zero.
    float importance(const Vec3& p, const Vec3& n) const;

    static LightBounds merged(const LightBounds& a, const LightBounds& b);
};

}  // namespace glint
