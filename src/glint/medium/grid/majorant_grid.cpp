#include <glint/core/error.h>
#include <glint/medium/grid/majorant_grid.h>

#include <algorithm>

namespace glint {

MajorantGrid::MajorantGrid(const VoxelGrid& grid, int resolution) {
    if (resolution < 1) throw Error("majorant grid: the resolution must be at least 1");
    const GridIndex& dims = grid.dims();
    m_resolution = {std::min(resolution, dims.x), std::min(resolution, dims.y),
                    std::min(resolution, dims.z)};
    m_values.resize(voxel_count(m_resolution));
    const Vec3 cell_size = 1.0f / Vec3(m_resolution.x, m_resolution.y, m_resolution.z);
    size_t i = 0;
    for (int z = 0; z < m_resolution.z; ++z) {
        for (int y = 0; y < m_resolution.y; ++y) {
            for (int x = 0; x < m_resolution.x; ++x) {
                const Vec3 lo = Vec3(x, y, z) * cell_size;
                m_values[i++] = grid.max_density(lo, lo + cell_size);
            }
        }
    }
}

GridIndex MajorantGrid::cell_of(const Vec3& u) const {
    const auto index = [](float v, int n) {
        return std::clamp(static_cast<int>(v * static_cast<float>(n)), 0, n - 1);
    };
    return {index(u.x, m_resolution.x), index(u.y, m_resolution.y), index(u.z, m_resolution.z)};
}

}  // namespace glint
