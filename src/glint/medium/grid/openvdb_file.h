#pragma once
// OpenVDB files (.vdb): the only file that uses the OpenVDB API.
#include <glint/medium/grid/voxel_grid.h>

#include <glint/medium/grid/nanovdb_file.h>

#include <string>
#include <vector>

namespace glint {

/// See read_density_grid (grid_file.h).
VoxelGrid read_openvdb_grid(const std::string& path, const std::string& grid_name);

/// Writes an OpenVDB fog volume named `grid_name` with the given active voxels, `voxel_size`
/// world units apart (the tests' way to make .vdb files). Throws glint::Error on failure.
void write_openvdb_grid(const std::string& path, const std::string& grid_name,
                        const std::vector<SparseVoxel>& voxels, double voxel_size);

}  // namespace glint
