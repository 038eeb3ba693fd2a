#pragma once
// Glowing media as the start of light paths: a light tracer sees what a medium emits only
// if some of its paths start there. Each medium that emits is sampled in the box round the
// shapes it fills (their interior); a point of the box outside the medium (the box's
// corners round a sphere, another medium inside) starts no path, so the box's volume, not
// the region's, is the density's: no region's volume is needed, and the estimate stays
// unbiased for any shape. A medium that fills no shape (the camera's atmosphere, which has
// no bounds) cannot be sampled and is left out (MediumEmitters::unbounded).
#include <glint/core/medium.h>
#include <glint/math/bounds.h>
#include <glint/scene/scene.h>

#include <optional>
#include <vector>

namespace glint {

class MediumEmitters {
public:
    /// The scene's glowing homogeneous media and the boxes they fill.
    explicit MediumEmitters(const Scene& scene);

    bool empty() const { return m_regions.empty(); }
    /// The power the boxes would emit were they filled (luminance, W): an upper bound,
    /// for choosing between them and the lights.
    float power() const { return m_total_power; }
    /// Media that emit but fill no shape, which no light path can start in.
    const std::vector<const Medium*>& unbounded() const { return m_unbounded; }

    /// A point to start a light path from.
    struct Start {
        Vec3 p{0.0f};
        const Medium* medium = nullptr;
        /// The source sigma_a Le there (radiance per unit length) over the point's density
        /// (per unit volume, the box's choice included).
        Spectrum source_over_pdf{0.0f};
    };
    /// A box chosen by power with `u_region`, a point uniform in it with `u_point`: nullopt
    /// where the point lies outside the box's medium.
    std::optional<Start> sample(const Scene& scene, float u_region, const Vec3& u_point) const;

private:
    struct Region {
        const Medium* medium;
        Bounds3 box;
        float volume;  // the box's
        float power;
    };
    std::vector<Region> m_regions;
    std::vector<float> m_cdf;  // m_cdf[i]: the power of regions before i over the total
    float m_total_power = 0.0f;
    std::vector<const Medium*> m_unbounded;
};

}  // namespace glint
