// The majorant grid must bound the density everywhere in each cell, or tracking is biased.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/medium/grid/fbm_cloud.h>
#include <glint/medium/grid/majorant_grid.h>

#include <gtest/gtest.h>

namespace glint {
namespace {

// A random grid: a few dims per axis, most voxels empty, a few spikes.
VoxelGrid random_grid(Rng& rng) {
    const GridIndex dims{1 + static_cast<int>(rng.next_u32() % 20),
                         1 + static_cast<int>(rng.next_u32() % 20),
                         1 + static_cast<int>(rng.next_u32() % 20)};
    std::vector<float> values(voxel_count(dims));
    for (float& v : values) {
        const float r = rng.next_float();
        v = r < 0.7f ? 0.0f : r < 0.95f ? rng.next_float() : 10.0f * rng.next_float();
    }
    return VoxelGrid(dims, std::move(values),
                     Bounds3{Vec3(-1.0f, 0.0f, 2.0f), Vec3(3.0f, 1.0f, 2.5f)});
}

TEST(MajorantGrid, NeverUnderBoundsTheInterpolatedDensity) {
    Rng rng(29);
    for (int trial = 0; trial < 200; ++trial) {
        const VoxelGrid grid = random_grid(rng);
        const MajorantGrid majorants(grid, 1 + static_cast<int>(rng.next_u32() % 9));
        const GridIndex& res = majorants.resolution();
        const Vec3 cell_size = 1.0f / Vec3(res.x, res.y, res.z);
        for (int z = 0; z < res.z; ++z) {
            for (int y = 0; y < res.y; ++y) {
                for (int x = 0; x < res.x; ++x) {
                    const Vec3 lo = Vec3(x, y, z) * cell_size;
                    const float bound = majorants.cell(x, y, z);
                    // Random points inside, and on the faces and corners, which the cells
                    // on both sides must bound.
                    for (int i = 0; i < 64; ++i) {
                        Vec3 t(rng.next_float(), rng.next_float(), rng.next_float());
                        if (i % 4 == 0) t[i / 4 % 3] = static_cast<float>(i / 12 % 2);
                        if (i < 8) t = Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
                        const Vec3 u = glm::min(lo + t * cell_size, Vec3(1.0f));
                        ASSERT_LE(grid.density(u), bound)
                            << "trial " << trial << " cell " << x << "," << y << "," << z;
                    }
                }
            }
        }
    }
}

TEST(MajorantGrid, BoundsEveryVoxelCentreAndEqualsTheMaximumAtOneCell) {
    Rng rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        const VoxelGrid grid = random_grid(rng);
        const MajorantGrid single(grid, 1);
        EXPECT_EQ(single.cell(0, 0, 0), grid.max_value());
        const MajorantGrid majorants(grid, 4);
        const GridIndex& d = grid.dims();
        for (int z = 0; z < d.z; ++z) {
            for (int y = 0; y < d.y; ++y) {
                for (int x = 0; x < d.x; ++x) {
                    const Vec3 u = (Vec3(x, y, z) + 0.5f) / Vec3(d.x, d.y, d.z);
                    const GridIndex c = majorants.cell_of(u);
                    ASSERT_LE(grid.voxel(x, y, z), majorants.cell(c.x, c.y, c.z));
                }
            }
        }
    }
}

TEST(MajorantGrid, IsTighterThanOneGlobalBoundOnASparseCloud) {
    const VoxelGrid cloud = make_fbm_cloud({.resolution = 32}, Bounds3{Vec3(0.0f), Vec3(1.0f)});
    const MajorantGrid majorants(cloud, 16);
    double sum = 0.0;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) sum += majorants.cell(x, y, z);
    // The mean cell bound is what a walk pays per unit length on average.
    EXPECT_LT(sum / (16 * 16 * 16), 0.5 * cloud.max_value());
}

TEST(VoxelGrid, RejectsNegativeOrNonFiniteDensities) {
    const Bounds3 box{Vec3(0.0f), Vec3(1.0f)};
    EXPECT_THROW(VoxelGrid({1, 1, 1}, {-1.0f}, box), Error);
    EXPECT_THROW(VoxelGrid({1, 1, 1}, {std::nanf("")}, box), Error);
    EXPECT_THROW(VoxelGrid({2, 1, 1}, {1.0f}, box), Error);
}

}  // namespace
}  // namespace glint
