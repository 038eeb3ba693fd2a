// The DDA must visit, in order, exactly the majorant cells a ray segment passes through.
#include <glint/core/rng.h>
#include <glint/medium/grid/dda_majorant_iterator.h>

#include <gtest/gtest.h>

namespace glint {
namespace {

struct CellVisit {
    GridIndex cell;
    float t_min, t_max;
};

// By brute force: the ray's overlap with every cell's box (slab test), kept when longer than
// `min_length`, in order along the ray.
std::vector<CellVisit> cells_crossed(const GridIndex& res, const Vec3& o, const Vec3& d,
                                     float t_max, float min_length) {
    std::vector<CellVisit> visits;
    for (int z = 0; z < res.z; ++z) {
        for (int y = 0; y < res.y; ++y) {
            for (int x = 0; x < res.x; ++x) {
                const Vec3 lo = Vec3(x, y, z) / Vec3(res.x, res.y, res.z);
                const Vec3 hi = Vec3(x + 1, y + 1, z + 1) / Vec3(res.x, res.y, res.z);
                double t0 = 0.0, t1 = t_max;
                for (int a = 0; a < 3; ++a) {
                    if (d[a] == 0.0f) {
                        if (o[a] < lo[a] || o[a] > hi[a]) t0 = kInfinity;
                        continue;
                    }
                    double n = (double(lo[a]) - o[a]) / d[a], f = (double(hi[a]) - o[a]) / d[a];
                    if (n > f) std::swap(n, f);
                    t0 = std::max(t0, n);
                    t1 = std::min(t1, f);
                }
                if (t1 - t0 > min_length) {
                    visits.push_back({{x, y, z}, float(t0), float(t1)});
                }
            }
        }
    }
    std::sort(visits.begin(), visits.end(),
              [](const CellVisit& a, const CellVisit& b) { return a.t_min < b.t_min; });
    return visits;
}

TEST(DdaMajorantIterator, VisitsExactlyTheCellsARayCrosses) {
    Rng rng(1234);
    for (int trial = 0; trial < 2000; ++trial) {
        const GridIndex dims{1 + int(rng.next_u32() % 9), 1 + int(rng.next_u32() % 9),
                             1 + int(rng.next_u32() % 9)};
        const VoxelGrid grid(dims, std::vector<float>(voxel_count(dims), 1.0f),
                             Bounds3{Vec3(0.0f), Vec3(1.0f)});
        const MajorantGrid majorants(grid, 9);
        const Vec3 o(2.0f * rng.next_float() - 0.5f, 2.0f * rng.next_float() - 0.5f,
                     2.0f * rng.next_float() - 0.5f);
        Vec3 d(2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f,
               2.0f * rng.next_float() - 1.0f);
        // Some rays parallel to one or two axes; a scale that is not 1.
        if (trial % 5 == 0) d[trial % 3] = 0.0f;
        if (trial % 15 == 0) d[(trial + 1) % 3] = 0.0f;
        if (d == Vec3(0.0f)) d.x = 1.0f;
        d *= 0.25f + 3.0f * rng.next_float();
        const float t_max = trial % 2 ? kInfinity : 2.0f * rng.next_float();

        const float eps = 1e-4f / glm::length(d);
        const std::vector<CellVisit> expected =
            cells_crossed(majorants.resolution(), o, d, t_max, eps);
        std::vector<CellVisit> visited;
        DdaMajorantIterator dda(majorants, o, d, 0.0f, t_max);
        float previous_end = -1.0f;
        while (const auto crossing = dda.next()) {
            // Segments are contiguous and never empty-backwards.
            ASSERT_LE(crossing->t_min, crossing->t_max);
            if (previous_end >= 0.0f) {
                ASSERT_EQ(crossing->t_min, previous_end);
            }
            previous_end = crossing->t_max;
            if (crossing->t_max - crossing->t_min > eps) {
                visited.push_back({crossing->cell, crossing->t_min, crossing->t_max});
            }
        }
        ASSERT_EQ(visited.size(), expected.size()) << "trial " << trial;
        for (size_t i = 0; i < expected.size(); ++i) {
            ASSERT_EQ(visited[i].cell, expected[i].cell) << "trial " << trial << " visit " << i;
            EXPECT_NEAR(visited[i].t_min, expected[i].t_min, 1e-4f * (1.0f + expected[i].t_min));
            EXPECT_NEAR(visited[i].t_max, expected[i].t_max, 1e-4f * (1.0f + expected[i].t_max));
        }
    }
}

TEST(DdaMajorantIterator, GivesNothingForARayThatMissesTheGrid) {
    const VoxelGrid grid({4, 4, 4}, std::vector<float>(64, 1.0f), Bounds3{Vec3(0.0f), Vec3(1.0f)});
    const MajorantGrid majorants(grid, 4);
    DdaMajorantIterator beside(majorants, Vec3(2.0f, 0.5f, 0.5f), Vec3(0.0f, 1.0f, 0.0f), 0.0f,
                               kInfinity);
    EXPECT_FALSE(beside.next());
    DdaMajorantIterator behind(majorants, Vec3(2.0f, 0.5f, 0.5f), Vec3(1.0f, 0.0f, 0.0f), 0.0f,
                               kInfinity);
    EXPECT_FALSE(behind.next());
    DdaMajorantIterator too_short(majorants, Vec3(-1.0f, 0.5f, 0.5f), Vec3(1.0f, 0.0f, 0.0f), 0.0f,
                                  0.5f);
    EXPECT_FALSE(too_short.next());
}

}  // namespace
}  // namespace glint
