#pragma once
// What the grid file readers share: checking a file's index box before densifying it.
#include <glint/medium/grid/voxel_grid.h>

#include <array>
#include <string>

namespace glint {

/// The dimensions of the inclusive index box [lo, hi]; throws glint::Error naming `path` when
/// it is empty or holds more than VoxelGrid::kMaxVoxels voxels. Computed in 64 bits, so an
/// absurd box (2^31 voxels per axis) cannot overflow.
GridIndex checked_grid_dims(const std::string& path, const std::array<int64_t, 3>& lo,
                            const std::array<int64_t, 3>& hi);

}  // namespace glint
