#pragma once
// Density grids from files: NanoVDB (.nvdb) and OpenVDB (.vdb), each an optional part of the
// build (libnanovdb-dev, libopenvdb-dev). The grid's active bounding box is densified into a
// VoxelGrid whose box is the grid's index box mapped to its world space.
#include <glint/medium/grid/voxel_grid.h>

#include <string>

namespace glint {

/// Reads the float grid named `grid_name` (empty: the file's first float grid) from `path`,
/// chosen by its extension (.nvdb or .vdb). Throws glint::Error naming the file when it is
/// missing, not a regular file, truncated or corrupt, has no such grid, was written with a
/// compression this build lacks, or would need more than VoxelGrid::kMaxVoxels voxels (checked
/// before anything that size is allocated); or when glint was built without that format.
VoxelGrid read_density_grid(const std::string& path, const std::string& grid_name = "");

/// Whether this build reads .nvdb and .vdb files.
bool can_read_nanovdb();
bool can_read_openvdb();

}  // namespace glint
