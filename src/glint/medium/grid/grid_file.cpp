#include <glint/core/error.h>
#include <glint/medium/grid/grid_box.h>
#include <glint/medium/grid/grid_file.h>

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#ifdef GLINT_HAVE_NANOVDB
#include <glint/medium/grid/nanovdb_file.h>
#endif
#ifdef GLINT_HAVE_OPENVDB
#include <glint/medium/grid/openvdb_file.h>
#endif

namespace glint {

GridIndex checked_grid_dims(const std::string& path, const std::array<int64_t, 3>& lo,
                            const std::array<int64_t, 3>& hi) {
    uint64_t count = 1;
    std::array<int64_t, 3> size{};
    for (int axis = 0; axis < 3; ++axis) {
        size[axis] = hi[axis] - lo[axis] + 1;
        if (size[axis] < 1) {
            throw Error(fmt::format("grid file '{}': the grid has no active voxels", path));
        }
        // Saturate instead of overflowing: any axis beyond the limit is already too many.
        count = size[axis] > static_cast<int64_t>(VoxelGrid::kMaxVoxels)
                    ? VoxelGrid::kMaxVoxels + 1
                    : std::min<uint64_t>(count * static_cast<uint64_t>(size[axis]),
                                         VoxelGrid::kMaxVoxels + 1);
    }
    if (count > VoxelGrid::kMaxVoxels) {
        throw Error(fmt::format(
            "grid file '{}': its bounding box of {} x {} x {} voxels is more than the {} glint "
            "can hold densely",
            path, size[0], size[1], size[2], VoxelGrid::kMaxVoxels));
    }
    return {static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2])};
}

bool can_read_nanovdb() {
#ifdef GLINT_HAVE_NANOVDB
    return true;
#else
    return false;
#endif
}

bool can_read_openvdb() {
#ifdef GLINT_HAVE_OPENVDB
    return true;
#else
    return false;
#endif
}

VoxelGrid read_density_grid(const std::string& path, const std::string& grid_name) {
    // Checked here, before a third-party reader sees the path: a FIFO or a device would block
    // or never end.
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status)) {
        throw Error(fmt::format("grid file '{}': no such file", path));
    }
    if (!std::filesystem::is_regular_file(status)) {
        throw Error(fmt::format("grid file '{}': not a regular file", path));
    }
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension == ".nvdb") {
#ifdef GLINT_HAVE_NANOVDB
        return read_nanovdb_grid(path, grid_name);
#else
        throw Error(
            fmt::format("grid file '{}': this glint was built without NanoVDB "
                        "(install libnanovdb-dev and rebuild)",
                        path));
#endif
    }
    if (extension == ".vdb") {
#ifdef GLINT_HAVE_OPENVDB
        return read_openvdb_grid(path, grid_name);
#else
        throw Error(
            fmt::format("grid file '{}': this glint was built without OpenVDB "
                        "(install libopenvdb-dev and rebuild)",
                        path));
#endif
    }
    throw Error(fmt::format("grid file '{}': unknown extension '{}' (expected .nvdb or .vdb)", path,
                            extension));
}

}  // namespace glint
