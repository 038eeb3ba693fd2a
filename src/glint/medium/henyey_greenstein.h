#pragma once
// The Henyey-Greenstein phase function (Henyey and Greenstein 1941): the angular density of
// the direction light scatters into at a point in a medium, with one asymmetry parameter g,
// the mean cosine of the scattering angle. Directions follow the BSDF convention: `wo` points
// away from the scattering point towards where the light goes, `wi` towards where it came
// from, so forward scattering is wi = -wo.
#include <glint/math/vector.h>

namespace glint {

/// A direction sampled from the phase function; `p` is both its value and its density
/// (the function is normalised over the sphere, and sampled exactly).
struct PhaseSample {
    Vec3 wi;
    float p = 0.0f;
};

class HenyeyGreenstein {
public:
    /// g in (-1, 1); values at or beyond +-0.999 are clamped to it (a delta lobe is no
    /// phase function this sampling can follow).
    explicit HenyeyGreenstein(float g);

    /// The density over the sphere of scattering from `wi` into `wo` (both unit).
    float eval(const Vec3& wo, const Vec3& wi) const;
    /// Samples wi for unit `wo` from u in [0, 1)^2, in proportion to eval.
    PhaseSample sample(const Vec3& wo, const Vec2& u) const;
    float g() const { return m_g; }

private:
    float m_g;
};

}  // namespace glint
