#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/medium/grid/grid_box.h>
#include <glint/medium/grid/openvdb_file.h>

#include <fmt/format.h>
#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <sstream>

namespace glint {

namespace {

// A library's message made fit to print: OpenVDB quotes bytes from a corrupt file verbatim,
// so control characters become spaces, runs of spaces one, and the length is capped.
std::string printable(const char* message) {
    std::string result;
    // A corrupt file can put a string of any length read from it into OpenVDB's message:
    // look at its start only, never copying or measuring the whole of it.
    constexpr size_t kMaxScanned = 4096;
    for (size_t i = 0; i < kMaxScanned && message[i] != '\0'; ++i) {
        const char c = message[i];
        const char shown = (c >= 32 && c < 127) ? c : ' ';
        if (shown == ' ' && (result.empty() || result.back() == ' ')) continue;
        result += shown;
        if (result.size() >= 200) return result + "...";
    }
    return result;
}

// The name of the grid to read, from the file's metadata alone (no voxels are loaded).
openvdb::GridBase::ConstPtr choose_grid(const std::string& path, openvdb::io::File& file,
                                        const std::string& grid_name) {
    const openvdb::GridPtrVecPtr metas = file.readAllGridMetadata();
    std::string names;
    for (const openvdb::GridBase::Ptr& meta : *metas) {
        const bool is_float = meta->isType<openvdb::FloatGrid>();
        if (is_float && (grid_name.empty() || meta->getName() == grid_name)) return meta;
        names += fmt::format("{}'{}' ({})", names.empty() ? "" : ", ", meta->getName(),
                             meta->valueType());
    }
    throw Error(fmt::format("grid file '{}': no float grid{} (the file holds: {})", path,
                            grid_name.empty() ? "" : fmt::format(" named '{}'", grid_name),
                            names.empty() ? "no grids" : names));
}

std::array<int64_t, 3> as_array(const openvdb::Coord& c) {
    return {c.x(), c.y(), c.z()};
}

// OpenVDB records each grid's active box in its metadata when it writes the file: checking
// it first refuses an absurd grid before its voxels are read.
void check_recorded_box(const std::string& path, const openvdb::GridBase& meta) {
    const auto lo = meta.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    const auto hi = meta.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    if (lo && hi) {
        const openvdb::Vec3i a = lo->value(), b = hi->value();
        checked_grid_dims(path, {a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()});
    }
}

}  // namespace

VoxelGrid read_openvdb_grid(const std::string& path, const std::string& grid_name) {
    try {
        openvdb::initialize();
        openvdb::io::File file(path);
        file.open(false);
        const openvdb::GridBase::ConstPtr meta = choose_grid(path, file, grid_name);
        check_recorded_box(path, *meta);
        const std::string name = meta->getName();
        file.close();
        // The voxels are read through a stream over the file's bytes rather than by
        // io::File, which reads a grid's last block leniently: a file cut short by a byte or
        // two would give garbage voxels there. The stream fails instead.
        std::istringstream stream(read_regular_file(path, "grid file"));
        // A read past the end throws at once: OpenVDB would otherwise go on with the length
        // it failed to read (whatever was in memory) and allocate that much.
        stream.exceptions(std::ios::failbit | std::ios::badbit);
        openvdb::io::Stream reader(stream, /*delayLoad=*/false);
        const openvdb::GridPtrVecPtr grids = reader.getGrids();
        if (!stream) throw Error(fmt::format("grid file '{}': truncated", path));
        openvdb::FloatGrid::Ptr grid;
        for (const openvdb::GridBase::Ptr& candidate : *grids) {
            if (candidate->getName() == name)
                grid = openvdb::gridPtrCast<openvdb::FloatGrid>(candidate);
        }
        if (!grid)
            throw Error(fmt::format("grid file '{}': cannot read its float grid '{}'", path, name));
        const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
        const GridIndex dims = checked_grid_dims(path, as_array(box.min()), as_array(box.max()));
        std::vector<float> values(voxel_count(dims));
        const auto accessor = grid->getConstAccessor();
        size_t i = 0;
        for (int z = 0; z < dims.z; ++z) {
            for (int y = 0; y < dims.y; ++y) {
                for (int x = 0; x < dims.x; ++x) {
                    values[i++] = std::max(0.0f, accessor.getValue(box.min().offsetBy(x, y, z)));
                }
            }
        }
        // Voxel centres sit at integer index coordinates: the dense box reaches half a voxel
        // beyond the first and last centres.
        Bounds3 bounds;
        for (const openvdb::Vec3d& corner :
             {box.min().asVec3d() - 0.5, box.max().asVec3d() + 0.5}) {
            const openvdb::Vec3d world = grid->indexToWorld(corner);
            bounds.expand(Vec3(world.x(), world.y(), world.z()));
        }
        return VoxelGrid(dims, std::move(values), bounds);
    } catch (const Error& e) {
        const std::string message = e.what();
        if (message.find(path) != std::string::npos) throw;
        throw Error(fmt::format("grid file '{}': {}", path, message));
    } catch (const std::ios_base::failure&) {
        throw Error(fmt::format("grid file '{}': truncated (it ends inside its grid)", path));
    } catch (const std::exception& e) {
        throw Error(fmt::format("grid file '{}': not a readable OpenVDB file: {}", path,
                                printable(e.what())));
    }
}

void write_openvdb_grid(const std::string& path, const std::string& grid_name,
                        const std::vector<SparseVoxel>& voxels, double voxel_size) {
    try {
        openvdb::initialize();
        const openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
        grid->setName(grid_name);
        grid->setGridClass(openvdb::GRID_FOG_VOLUME);
        grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel_size));
        auto accessor = grid->getAccessor();
        for (const SparseVoxel& v : voxels) {
            accessor.setValue(openvdb::Coord(v.index.x, v.index.y, v.index.z), v.value);
        }
        openvdb::io::File(path).write({grid});
    } catch (const std::exception& e) {
        throw Error(fmt::format("grid file '{}': cannot write: {}", path, e.what()));
    }
}

}  // namespace glint
