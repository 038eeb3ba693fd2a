#pragma once
// The Henyey-Greenstein phase function (Henyey and Greenstein 1941): the angular density of
// the direction light scatters into at a point in a medium, with one asymmetry parameter g,
// the mean cosine of the scattering angle. Directions follow the BSDF convention: `wo` points
// away from the scattering point towards where the light goes, `wi` towards where it came
// from, so forward scattering is wi = -wo.
#include <glint/math/vector.h>

#include <algorithm>
#include <cmath>

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
    explicit HenyeyGreenstein(float g) : m_g(std::clamp(g, -0.999f, 0.999f)) {}

    /// The density over the sphere of scattering from `wi` into `wo` (both unit). Inline:
    /// the preview in fog asks it for every volume photon a pixel's ray passes.
    float eval(const Vec3& wo, const Vec3& wi) const { return density(glm::dot(wo, wi)); }
    /// Samples wi for unit `wo` from u in [0, 1)^2, in proportion to eval.
    PhaseSample sample(const Vec3& wo, const Vec2& u) const;
    float g() const { return m_g; }

private:
    // The density as a function of cos_theta = dot(wo, wi): with wo pointing away, forward
    // scattering is cos_theta = -1, where the denominator 1 + g^2 + 2 g cos_theta is
    // smallest for g > 0.
    float density(float cos_theta) const {
        const float denominator = 1.0f + m_g * m_g + 2.0f * m_g * cos_theta;
        return kInv4Pi * (1.0f - m_g * m_g) /
               (denominator * std::sqrt(std::max(denominator, 1e-12f)));
    }

    float m_g;
};

}  // namespace glint
