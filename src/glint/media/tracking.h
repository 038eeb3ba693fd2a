#pragma once
// Null-collision tracking through a density grid bounded by a majorant grid: delta tracking
// samples the distance to the first real collision, ratio tracking estimates transmittance.
// Both walk tentative collisions of a Poisson process whose rate is the majorant, constant
// inside each majorant cell (Woodcock et al. 1965; Novák et al. 2014, "Residual ratio
// tracking"; the walk over majorant segments follows pbrt-v4's SampleT_maj).
//
// Rays are given in the grid's normalised space (o + t d, [0, 1]^3 is the grid) with the
// caller's parametrisation kept: `sigma_t` is the extinction per unit of t at density 1, so a
// medium whose world ray maps to this one passes its extinction times |world direction|.
// Every random number comes from `uniform()`, a callable returning floats in [0, 1).
#include <glint/core/spectrum.h>
#include <glint/media/dda_majorant_iterator.h>

#include <cmath>
#include <optional>

namespace glint {

namespace tracking_detail {
inline float largest(float v) {
    return v;
}
inline float largest(const Spectrum& s) {
    return s.max_value();
}
}  // namespace tracking_detail

/// Calls `on_collision(t, density_bound)` at each tentative collision along o + t d for t in
/// [0, t_max], in order, where the majorant rate is sigma_max * density_bound; stops when it
/// returns false. Returns whether the walk reached t_max (or left the grid) without being
/// stopped. Cells whose bound is 0 are crossed without a random number.
template <class Uniform, class OnCollision>
bool walk_majorant_collisions(const MajorantGrid& majorants, const Vec3& o, const Vec3& d,
                              float t_max, float sigma_max, Uniform&& uniform,
                              OnCollision&& on_collision) {
    DdaMajorantIterator cells(majorants, o, d, 0.0f, t_max);
    while (const std::optional<MajorantSegment> segment = cells.next()) {
        const float rate = sigma_max * segment->max_density;
        if (!(rate > 0.0f)) continue;
        // The process is memoryless, so each cell starts afresh from its entry point.
        float t = segment->t_min;
        while (true) {
            t -= std::log1p(-uniform()) / rate;
            if (t >= segment->t_max) break;
            if (!on_collision(t, segment->max_density)) return false;
        }
    }
    return true;
}

/// Delta tracking: the parameter t of the first real collision along o + t d, distributed
/// with density sigma_t(t) exp(-integral of sigma_t), or nothing when the ray reaches t_max
/// first (with probability equal to the transmittance).
template <class Uniform>
std::optional<float> delta_tracking(const VoxelGrid& grid, const MajorantGrid& majorants,
                                    const Vec3& o, const Vec3& d, float t_max, float sigma_t,
                                    Uniform&& uniform) {
    std::optional<float> collision;
    walk_majorant_collisions(majorants, o, d, t_max, sigma_t, uniform,
                             [&](float t, float density_bound) {
                                 // Real with probability sigma_t / sigma_majorant.
                                 if (uniform() * density_bound < grid.density(o + t * d)) {
                                     collision = t;
                                     return false;
                                 }
                                 return true;
                             });
    return collision;
}

/// Ratio tracking: an unbiased estimate of the transmittance over [0, t_max] of a medium with
/// extinction sigma_t * density (a float, or a Spectrum per channel; the majorant uses the
/// largest channel). Each tentative collision weighs the estimate by the null fraction
/// 1 - sigma_t / sigma_majorant.
template <class Coefficient, class Uniform>
Coefficient ratio_tracking(const VoxelGrid& grid, const MajorantGrid& majorants, const Vec3& o,
                           const Vec3& d, float t_max, const Coefficient& sigma_t,
                           Uniform&& uniform) {
    const float sigma_max = tracking_detail::largest(sigma_t);
    Coefficient transmittance(1.0f);
    walk_majorant_collisions(
        majorants, o, d, t_max, sigma_max, uniform, [&](float t, float density_bound) {
            const float density = grid.density(o + t * d);
            transmittance *= Coefficient(1.0f) - sigma_t * (density / (sigma_max * density_bound));
            return true;
        });
    return transmittance;
}

}  // namespace glint
