#pragma once
// A medium whose density varies in space: smoke, clouds. A density grid (a file or the
// procedural cloud) scales the medium's coefficients, a coarse majorant grid bounds it cell
// by cell, and a 3D DDA gives the walks one majorant segment per cell crossed, so that
// delta and ratio tracking (delta_tracking.h) take long steps where the medium is thin.
#include <glint/core/medium.h>
#include <glint/math/transform.h>
#include <glint/medium/grid/majorant_grid.h>

namespace glint {

class HeterogeneousMedium final : public Medium {
public:
    /// `sigma_a` and `sigma_s` are the coefficients at density 1 (per unit length in scene
    /// units); the grid's densities scale both. `grid_to_world` places the grid's box
    /// (grid.bounds(), in the grid's own space) in the scene; g is the Henyey-Greenstein
    /// asymmetry; `majorant_resolution` the majorant grid's cells per axis (1: one global
    /// majorant).
    HeterogeneousMedium(VoxelGrid grid, const Transform& grid_to_world, const Rgb& sigma_a,
                        const Rgb& sigma_s, float g,
                        int majorant_resolution = MajorantGrid::kDefaultResolution);

    MediumPoint at(const Vec3& p) const override;
    /// One segment per majorant cell the ray crosses, skipping empty cells (the gaps the
    /// interface allows).
    void majorants(const Ray& ray, float t_max, MajorantVisitor visit) const override;
    /// Ratio tracking against the majorant segments (an unbiased estimate).
    Spectrum transmittance(const Ray& ray, float t, Rng& rng) const override;
    float phase_asymmetry() const override { return m_g; }
    bool scatters() const override {
        return m_sigma_s.max_value() > 0.0f && m_grid.max_value() > 0.0f;
    }

    const VoxelGrid& grid() const { return m_grid; }
    const MajorantGrid& majorant_grid() const { return m_majorants; }

private:
    VoxelGrid m_grid;
    MajorantGrid m_majorants;
    // Scene space to the grid's normalised space, [0, 1]^3 over its box.
    Transform m_world_to_unit;
    // At density 1; colours, uplifted when asked (see AbsorbingMedium).
    Rgb m_sigma_a;
    Rgb m_sigma_s;
    float m_g;
};

}  // namespace glint
