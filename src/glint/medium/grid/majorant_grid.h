#pragma once
// A coarse grid over a density grid's box whose cells hold the largest density inside them:
// the majorant a tracking walk uses between two cell faces. Where the cloud is thin the
// majorant is small and the walk takes long steps; one global majorant (a 1x1x1 majorant
// grid) would make it take the densest voxel's small steps everywhere. (The idea is
// pbrt-v4's MajorantGrid; see Novák et al. 2018, "Monte Carlo methods for volumetric light
// transport simulation", section 5.)
#include <glint/medium/grid/voxel_grid.h>

#include <vector>

namespace glint {

class MajorantGrid {
public:
    /// The default number of cells along each axis.
    static constexpr int kDefaultResolution = 16;

    /// Bounds `grid` with `resolution` cells along each axis (fewer along an axis that has
    /// fewer voxels). Each cell's value is >= the density at every position inside it,
    /// faces included. Throws glint::Error for a resolution < 1.
    explicit MajorantGrid(const VoxelGrid& grid, int resolution = kDefaultResolution);

    const GridIndex& resolution() const { return m_resolution; }
    float cell(int x, int y, int z) const {
        return m_values[(static_cast<size_t>(z) * m_resolution.y + y) * m_resolution.x + x];
    }
    /// The cell holding normalised position u (clamped into the grid).
    GridIndex cell_of(const Vec3& u) const;

private:
    GridIndex m_resolution;
    std::vector<float> m_values;
};

}  // namespace glint
