#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/medium/grid/grid_box.h>
#include <glint/medium/grid/nanovdb_file.h>

#include <fmt/format.h>
#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/GridValidator.h>
#include <nanovdb/util/IO.h>

#include <sstream>

namespace glint {

namespace {

// The index of the grid to read among the file's grids, from the metadata alone.
uint64_t choose_grid(const std::string& path, const std::vector<nanovdb::io::GridMetaData>& metas,
                     const std::string& grid_name) {
    std::string names;
    for (uint64_t i = 0; i < metas.size(); ++i) {
        const bool is_float = metas[i].gridType == nanovdb::GridType::Float;
        if (is_float && (grid_name.empty() || metas[i].gridName == grid_name)) return i;
        names += fmt::format("{}'{}' ({})", names.empty() ? "" : ", ", metas[i].gridName,
                             nanovdb::toStr(metas[i].gridType));
    }
    throw Error(fmt::format("grid file '{}': no float grid{} (the file holds: {})", path,
                            grid_name.empty() ? "" : fmt::format(" named '{}'", grid_name),
                            names.empty() ? "no grids" : names));
}

std::array<int64_t, 3> as_array(const nanovdb::Coord& c) {
    return {c[0], c[1], c[2]};
}

// Whether the grid's root and node arrays lie inside its buffer, checked before NanoVDB's own
// validation, whose checksum walks them: a corrupt offset or count must be an error, not a
// read beyond the buffer. Nodes of one level are stored one after another (breadth-first).
bool has_sound_layout(const nanovdb::NanoGrid<float>& grid, uint64_t buffer_size) {
    using Tree = nanovdb::NanoTree<float>;
    using Root = nanovdb::NanoRoot<float>;
    if (grid.gridSize() > buffer_size || !grid.isBreadthFirst()) return false;
    const auto* end = reinterpret_cast<const uint8_t*>(&grid) + grid.gridSize();
    const Tree& tree = grid.tree();
    const auto* tree_begin = reinterpret_cast<const uint8_t*>(&tree);
    const uint64_t available = static_cast<uint64_t>(end - tree_begin);
    const auto* offsets = tree.data()->mNodeOffset;
    const auto fits = [&](uint64_t offset, uint64_t bytes) {
        return offset <= available && bytes <= available - offset;
    };
    if (!fits(offsets[3], sizeof(Root::DataType))) return false;
    const uint64_t tiles = tree.root().data()->mTableSize;
    if (!fits(offsets[3], sizeof(Root::DataType) + tiles * sizeof(Root::DataType::Tile))) {
        return false;
    }
    return fits(offsets[0], tree.nodeCount(0) * sizeof(nanovdb::NanoLeaf<float>)) &&
           fits(offsets[1], tree.nodeCount(1) * sizeof(nanovdb::NanoLower<float>)) &&
           fits(offsets[2], tree.nodeCount(2) * sizeof(nanovdb::NanoUpper<float>));
}

}  // namespace

VoxelGrid read_nanovdb_grid(const std::string& path, const std::string& grid_name) {
    // The whole file in memory first: a size stated in the file can then be checked against
    // the bytes that are really there before NanoVDB allocates a buffer of that size.
    const std::string bytes = read_regular_file(path, "grid file");
    std::istringstream stream(bytes);
    try {
        const auto metas = nanovdb::io::readGridMetaData(stream);
        const uint64_t index = choose_grid(path, metas, grid_name);
        const nanovdb::io::GridMetaData& meta = metas[index];
        if (meta.gridSize > bytes.size() && meta.codec == nanovdb::io::Codec::NONE) {
            throw Error(
                fmt::format("grid file '{}': truncated (grid '{}' needs {} bytes, the "
                            "file has {})",
                            path, meta.gridName, meta.gridSize, bytes.size()));
        }
        // Smaller than the grid's and tree's headers, the buffer could not even be inspected.
        constexpr uint64_t kHeaders =
            sizeof(nanovdb::GridData) + sizeof(nanovdb::NanoTree<float>::DataType);
        if (meta.gridSize < kHeaders) {
            throw Error(
                fmt::format("grid file '{}': grid '{}' is corrupt (its size, {} bytes, "
                            "is less than its headers')",
                            path, meta.gridName, meta.gridSize));
        }
        checked_grid_dims(path, as_array(meta.indexBBox.min()), as_array(meta.indexBBox.max()));
        stream.clear();
        stream.seekg(0);
        const auto handle = nanovdb::io::readGrid(stream, index);
        const nanovdb::NanoGrid<float>* grid = handle.grid<float>();
        if (grid == nullptr || !has_sound_layout(*grid, handle.size()) ||
            !nanovdb::isValid(*grid, true)) {
            throw Error(
                fmt::format("grid file '{}': grid '{}' is corrupt (its checksum or "
                            "structure does not hold)",
                            path, meta.gridName));
        }
        // The tree's own box, which the checksum covers (the metadata's might differ).
        const nanovdb::CoordBBox box = grid->indexBBox();
        const GridIndex dims = checked_grid_dims(path, as_array(box.min()), as_array(box.max()));
        std::vector<float> values(voxel_count(dims));
        auto accessor = grid->getAccessor();
        size_t i = 0;
        for (int z = 0; z < dims.z; ++z) {
            for (int y = 0; y < dims.y; ++y) {
                for (int x = 0; x < dims.x; ++x) {
                    values[i++] = std::max(0.0f, accessor.getValue(box.min().offsetBy(x, y, z)));
                }
            }
        }
        // Voxel centres sit at integer index coordinates, so the dense grid's box reaches
        // half a voxel beyond the first and last centres.
        Bounds3 bounds;
        const nanovdb::Vec3d lo =
            nanovdb::Vec3d(box.min()[0], box.min()[1], box.min()[2]) - nanovdb::Vec3d(0.5);
        const nanovdb::Vec3d hi =
            nanovdb::Vec3d(box.max()[0], box.max()[1], box.max()[2]) + nanovdb::Vec3d(0.5);
        for (const nanovdb::Vec3d& corner : {lo, hi}) {
            const nanovdb::Vec3d world = grid->indexToWorld(corner);
            bounds.expand(Vec3(world[0], world[1], world[2]));
        }
        return VoxelGrid(dims, std::move(values), bounds);
    } catch (const Error& e) {
        const std::string message = e.what();
        if (message.find(path) != std::string::npos) throw;
        throw Error(fmt::format("grid file '{}': {}", path, message));
    } catch (const std::exception& e) {
        throw Error(fmt::format("grid file '{}': not a readable NanoVDB file: {}", path, e.what()));
    }
}

void write_nanovdb_grid(const std::string& path, const std::string& grid_name,
                        const std::vector<SparseVoxel>& voxels, double voxel_size) {
    try {
        nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
        // A checksum over every node, leaves included, so that readers find any corruption.
        builder.setChecksum(nanovdb::ChecksumMode::Full);
        auto accessor = builder.getAccessor();
        for (const SparseVoxel& v : voxels) {
            accessor.setValue(nanovdb::Coord(v.index.x, v.index.y, v.index.z), v.value);
        }
        const auto handle = builder.getHandle<>(voxel_size, nanovdb::Vec3d(0.0), grid_name);
        // NanoVDB writes the grid first, past room for the header, then seeks back: the
        // stream must already be as long as the file, since a string stream cannot seek
        // beyond its end.
        nanovdb::io::Segment segment(nanovdb::io::Codec::NONE);
        segment.add(handle);
        std::ostringstream stream(std::string(segment.memUsage() + handle.size(), '\0'));
        nanovdb::io::writeGrid(stream, handle, nanovdb::io::Codec::NONE);
        write_file_atomically(path, stream.str(), "grid file");
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(fmt::format("grid file '{}': cannot write: {}", path, e.what()));
    }
}

}  // namespace glint
