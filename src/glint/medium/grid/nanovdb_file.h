#pragma once
// NanoVDB files (.nvdb): the only file that uses the NanoVDB API.
#include <glint/medium/grid/voxel_grid.h>

#include <string>
#include <vector>

namespace glint {

/// See read_density_grid (grid_file.h).
VoxelGrid read_nanovdb_grid(const std::string& path, const std::string& grid_name);

/// One active voxel of a sparse grid to write.
struct SparseVoxel {
    GridIndex index;
    float value = 0.0f;
};

/// Writes a NanoVDB fog volume named `grid_name` with the given active voxels, `voxel_size`
/// world units apart, index (0, 0, 0) at the world origin: how the repository makes its
/// example grid and how tests make valid and absurd files. Throws glint::Error on failure.
void write_nanovdb_grid(const std::string& path, const std::string& grid_name,
                        const std::vector<SparseVoxel>& voxels, double voxel_size);

}  // namespace glint
