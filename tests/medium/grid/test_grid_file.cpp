// Grid files: a round trip through each format, and every kind of bad file a clear error that
// names the file, never a crash or a huge allocation.
#include <glint/core/error.h>
#include <glint/medium/grid/grid_file.h>
#ifdef GLINT_HAVE_NANOVDB
#include <glint/medium/grid/nanovdb_file.h>
#endif
#ifdef GLINT_HAVE_OPENVDB
#include <glint/medium/grid/openvdb_file.h>
#endif
#include <support/test_util.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace glint {
namespace {

using ::testing::HasSubstr;

// The message of the glint::Error that reading `path` throws ("" when it does not throw).
std::string read_error(const std::string& path) {
    try {
        read_density_grid(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// A 3 x 2 x 2 block at index (4, 5, 6) with distinct values.
std::vector<SparseVoxel> small_block() {
    std::vector<SparseVoxel> voxels;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                voxels.push_back({{4 + x, 5 + y, 6 + z}, 1.0f + x + 3 * y + 6 * z});
    return voxels;
}

// What every format must give for small_block() written with voxel size 0.5.
void expect_small_block(const VoxelGrid& grid) {
    EXPECT_EQ(grid.dims(), (GridIndex{3, 2, 2}));
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) EXPECT_EQ(grid.voxel(x, y, z), 1.0f + x + 3 * y + 6 * z);
    // Index box [3.5, 6.5] x [4.5, 6.5] x [5.5, 7.5] times the voxel size.
    EXPECT_FLOAT_EQ(grid.bounds().min.x, 1.75f);
    EXPECT_FLOAT_EQ(grid.bounds().max.x, 3.25f);
    EXPECT_FLOAT_EQ(grid.bounds().min.y, 2.25f);
    EXPECT_FLOAT_EQ(grid.bounds().max.z, 3.75f);
}

using Writer = void (*)(const std::string&, const std::string&, const std::vector<SparseVoxel>&,
                        double);

// The same checks for each format: round trip, truncation at several lengths, absurd size.
void check_format(const std::string& extension, Writer write) {
    test::TempDir dir("glint-grid");
    const std::string good = dir.file("good" + extension);
    write(good, "density", small_block(), 0.5);
    expect_small_block(read_density_grid(good));
    expect_small_block(read_density_grid(good, "density"));
    EXPECT_THAT(
        [&] {
            try {
                read_density_grid(good, "temperature");
            } catch (const Error& e) {
                return std::string(e.what());
            }
            return std::string();
        }(),
        HasSubstr("no float grid named 'temperature'"));

    const std::string bytes = file_bytes(good);
    const std::string cut = dir.file("cut" + extension);
    for (const size_t length :
         {size_t{0}, size_t{7}, size_t{40}, bytes.size() / 2, bytes.size() - 1}) {
        write_bytes(cut, bytes.substr(0, length));
        SCOPED_TRACE(::testing::Message() << "truncated to " << length << " bytes");
        // An error naming the file, or (where the format's reader does not need the lost
        // bytes: OpenVDB's last byte) the very same grid; never other data.
        try {
            expect_small_block(read_density_grid(cut));
            EXPECT_EQ(length, bytes.size() - 1);
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr(cut));
        }
    }

    // Two voxels 10^4 apart on each axis: a box of 10^12 voxels, refused before densifying.
    const std::string absurd = dir.file("absurd" + extension);
    write(absurd, "density", {{{0, 0, 0}, 1.0f}, {{9999, 9999, 9999}, 1.0f}}, 1.0);
    const std::string message = read_error(absurd);
    EXPECT_THAT(message, HasSubstr(absurd));
    EXPECT_THAT(message, HasSubstr("10000 x 10000 x 10000 voxels"));
}

#ifdef GLINT_HAVE_NANOVDB
TEST(GridFile, NanoVdbRoundTripAndBadFiles) {
    check_format(".nvdb", write_nanovdb_grid);
}

TEST(GridFile, NanoVdbWithFlippedBytesIsCorrupt) {
    test::TempDir dir("glint-grid");
    const std::string path = dir.file("flipped.nvdb");
    write_nanovdb_grid(path, "density", small_block(), 1.0);
    const std::string bytes = file_bytes(path);
    // Flipped bytes in the grid's header, its tree's node offsets, its root, its internal
    // nodes and its leaf values: the checksum (written in full by glint) or the layout
    // checks find each.
    for (const size_t at : {size_t{200}, size_t{260}, size_t{300}, size_t{700}, bytes.size() / 2,
                            bytes.size() - 40}) {
        std::string flipped = bytes;
        for (size_t i = at; i < at + 8; ++i) flipped[i] = char(~flipped[i]);
        write_bytes(path, flipped);
        EXPECT_THAT(read_error(path), HasSubstr(path)) << "bytes flipped at " << at;
    }
}
#endif

#ifdef GLINT_HAVE_OPENVDB
TEST(GridFile, OpenVdbRoundTripAndBadFiles) {
    check_format(".vdb", write_openvdb_grid);
}
#endif

TEST(GridFile, MissingUnknownOrNonRegularFilesAreNamed) {
    test::TempDir dir("glint-grid");
    const std::string missing = dir.file("missing.nvdb");
    EXPECT_THAT(read_error(missing), HasSubstr(missing));
    EXPECT_THAT(read_error(missing), HasSubstr("no such file"));
    const std::string text = dir.file("cloud.txt");
    write_bytes(text, "not a grid");
    EXPECT_THAT(read_error(text), HasSubstr("unknown extension '.txt'"));
    const std::string folder = dir.file("folder.vdb");
    std::filesystem::create_directory(folder);
    EXPECT_THAT(read_error(folder), HasSubstr("not a regular file"));
    const std::string garbage = dir.file("garbage.nvdb");
    write_bytes(garbage, std::string(4096, 'x'));
    EXPECT_THAT(read_error(garbage), HasSubstr(garbage));
    const std::string garbage_vdb = dir.file("garbage.vdb");
    write_bytes(garbage_vdb, std::string(4096, 'x'));
    EXPECT_THAT(read_error(garbage_vdb), HasSubstr(garbage_vdb));
}

}  // namespace
}  // namespace glint
