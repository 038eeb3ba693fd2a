// The transport layer's hash grid (the photon gathers of preview, sppm and vcm) against a
// loop over all the points: random points and queries at several radii, points on a
// plane that is a cells' boundary (a floor's caustic at y = 0), a lattice whose points lie
// on cell borders at exactly the radius from each other, and the two numberings.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/integrator/transport/hash_grid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

using namespace glint;

namespace {

// The indices of the points within `radius` of `x` (closed ball), ascending.
std::vector<uint32_t> brute_force(const std::vector<Vec3>& points, const Vec3& x, float radius) {
    std::vector<uint32_t> within;
    for (size_t i = 0; i < points.size(); ++i)
        if (length_squared(points[i] - x) <= radius * radius)
            within.push_back(static_cast<uint32_t>(i));
    return within;
}

// What one query visits, in visit order; the distances must be the ones brute force sees.
std::vector<uint32_t> visits(const HashGrid& grid, const std::vector<Vec3>& points, const Vec3& x,
                             HashGrid::Cache& cache) {
    std::vector<uint32_t> visited;
    grid.for_each_near(x, cache, [&](uint32_t index, float distance2) {
        EXPECT_EQ(distance2, length_squared(points[index] - x));
        visited.push_back(index);
    });
    return visited;
}

// Points on the plane y = 0, in a dense spot on it and scattered in a box.
std::vector<Vec3> mixed_points(Rng& rng, int count) {
    auto u = [&] { return rng.next_float(); };
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) {
        if (i % 3 == 0)
            points.emplace_back(4.0f * u() - 2.0f, 0.0f, 4.0f * u() - 2.0f);
        else if (i % 3 == 1)
            points.emplace_back(0.5f + 0.05f * u(), 0.0f, -0.3f + 0.05f * u());
        else
            points.emplace_back(4.0f * u() - 2.0f, 2.0f * u() - 1.0f, 4.0f * u() - 2.0f);
    }
    return points;
}

}  // namespace

// Each point within the radius is visited exactly once, no other, in an order that
// depends only on the points and the query (a rebuild and a cache shared by all queries,
// as a thread keeps it, change nothing).
TEST(HashGrid, FindsThePointsWithinTheRadius) {
    Rng rng(12345);
    auto u = [&] { return rng.next_float(); };
    const std::vector<Vec3> points = mixed_points(rng, 3000);
    for (float radius : {0.01f, 0.07f, 0.3f, 1.5f}) {
        HashGrid grid, rebuilt;
        grid.build(points, radius);
        rebuilt.build(points, radius);
        ASSERT_EQ(grid.size(), points.size());
        HashGrid::Cache cache, fresh;
        size_t found = 0;
        for (int q = 0; q < 1000; ++q) {
            Vec3 x;
            switch (q % 4) {
                case 0:
                    x = Vec3(4.0f * u() - 2.0f, 0.0f, 4.0f * u() - 2.0f);
                    break;
                case 1:
                    x = Vec3(4.0f * u() - 2.0f, 0.03f * u() - 0.015f, 4.0f * u() - 2.0f);
                    break;
                case 2:
                    x = Vec3(0.45f + 0.15f * u(), 0.0f, -0.35f + 0.15f * u());
                    break;
                default:
                    x = Vec3(4.0f * u() - 2.0f, 2.0f * u() - 1.0f, 4.0f * u() - 2.0f);
                    break;
            }
            std::vector<uint32_t> visited = visits(grid, points, x, cache);
            HashGrid::Cache own;
            EXPECT_EQ(visits(rebuilt, points, x, own), visited) << "query " << q;
            EXPECT_EQ(visits(grid, points, x, fresh), visited) << "query " << q;
            std::sort(visited.begin(), visited.end());
            const std::vector<uint32_t> expected = brute_force(points, x, radius);
            EXPECT_EQ(visited, expected) << "radius " << radius << ", query " << q;
            found += expected.size();
        }
        EXPECT_GT(found, 1000u) << "radius " << radius;  // the queries met points
    }
}

// Points and queries on a lattice of the cell size: every point on cell borders, its
// neighbours at exactly the radius (found by the closed ball, not by the open one), the
// diagonal ones beyond.
TEST(HashGrid, FindsPointsOnCellBordersAtExactlyTheRadius) {
    const float radius = 0.25f;
    std::vector<Vec3> points;
    for (int z = -4; z <= 4; ++z)
        for (int y = -4; y <= 4; ++y)
            for (int x = -4; x <= 4; ++x) points.emplace_back(Vec3(x, y, z) * radius);
    HashGrid grid;
    grid.build(points, radius);
    HashGrid::Cache cache;
    for (const Vec3& offset : {Vec3(0.0f), Vec3(0.5f, 0.0f, 0.0f), Vec3(0.5f, 0.5f, 0.0f),
                               Vec3(0.5f, 0.5f, 0.5f), Vec3(0.25f, 0.0f, 0.75f)}) {
        for (int z = -3; z <= 3; ++z) {
            for (int y = -3; y <= 3; ++y) {
                for (int x = -3; x <= 3; ++x) {
                    const Vec3 q = (Vec3(x, y, z) + offset) * radius;
                    std::vector<uint32_t> visited = visits(grid, points, q, cache);
                    std::sort(visited.begin(), visited.end());
                    EXPECT_EQ(visited, brute_force(points, q, radius));
                    if (offset == Vec3(0.0f)) {
                        EXPECT_EQ(visited.size(), 7u);  // itself and its 6 neighbours
                    }
                    // The open ball leaves out the points at exactly the radius.
                    std::vector<uint32_t> open;
                    grid.for_each_near<HashGrid::Ball::kOpen>(
                        q, cache, [&](uint32_t index, float) { open.push_back(index); });
                    std::sort(open.begin(), open.end());
                    std::vector<uint32_t> strictly;
                    for (uint32_t i : visited)
                        if (length_squared(points[i] - q) < radius * radius) strictly.push_back(i);
                    EXPECT_EQ(open, strictly);
                    if (offset == Vec3(0.0f)) {
                        EXPECT_EQ(open.size(), 1u);  // itself
                    }
                }
            }
        }
    }
}

// Storage numbering: a visit names a position in order(), which lists every given point
// once; the visits name the same points as with the given numbering, in the same order.
TEST(HashGrid, StorageNumberingFollowsTheOrder) {
    Rng rng(777);
    const std::vector<Vec3> points = mixed_points(rng, 2000);
    const float radius = 0.07f;
    HashGrid given, stored;
    given.build(points, radius);
    stored.build(points, radius, HashGrid::Numbering::kStorage);
    std::vector<uint32_t> order = stored.order();
    ASSERT_EQ(order.size(), points.size());
    std::sort(order.begin(), order.end());
    for (uint32_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], i);
    HashGrid::Cache cache;
    for (int q = 0; q < 500; ++q) {
        const Vec3 x = points[static_cast<size_t>(q) * 4];
        std::vector<uint32_t> translated;
        stored.for_each_near(x, cache,
                             [&](uint32_t k, float) { translated.push_back(stored.order()[k]); });
        EXPECT_EQ(translated, visits(given, points, x, cache)) << "query " << q;
    }
}

// Queries that walk in small steps, as a row of pixels does, so that the cache meets each
// cell again and again, beside the ones it holds (along every axis, both ways, and turning
// back): each query gets the visits, in the order, that a query with a fresh cache gets.
TEST(HashGrid, WalkingQueriesGetTheVisitsOfAFreshCache) {
    Rng rng(777);
    std::vector<Vec3> points = mixed_points(rng, 6000);
    // A dense cloud round the walks, so that most cells they pass hold points.
    for (int i = 0; i < 6000; ++i)
        points.emplace_back(0.4f * rng.next_float() - 0.2f, 0.4f * rng.next_float() - 0.2f,
                            0.4f * rng.next_float() - 0.2f);
    const float radius = 0.03f;
    HashGrid grid;
    grid.build(points, radius);
    HashGrid::Cache walking;
    int slid = 0, queries = 0;
    const Vec3 steps[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const Vec3& step : steps) {
        Vec3 x(-0.15f, -0.12f, -0.1f);
        for (int k = 0; k < 40; ++k, ++queries) {
            // Forward, then a few back: the cache meets centres on either side of it.
            x += (k % 10 < 7 ? 0.41f : -0.41f) * radius * step;
            HashGrid::Cache fresh;
            const std::vector<uint32_t> expected = visits(grid, points, x, fresh);
            EXPECT_EQ(visits(grid, points, x, walking), expected) << "step " << k;
            slid += expected.empty() ? 0 : 1;
        }
    }
    EXPECT_GT(slid, queries / 2);  // the walks pass through points
}

// A rebuild with other points: a cache filled before it notices and forgets what it knew.
TEST(HashGrid, CacheNoticesARebuild) {
    Rng rng(4242);
    const std::vector<Vec3> points = mixed_points(rng, 3000);
    const float radius = 0.07f;
    HashGrid grid;
    grid.build(points, radius);
    HashGrid::Cache cache;
    const Vec3 spot(0.52f, 0.0f, -0.28f);
    EXPECT_EQ(visits(grid, points, spot, cache).size(), brute_force(points, spot, radius).size());
    const std::vector<Vec3> half(points.begin(), points.begin() + 1500);
    grid.build(half, radius);
    std::vector<uint32_t> after = visits(grid, half, spot, cache);
    std::sort(after.begin(), after.end());
    EXPECT_EQ(after, brute_force(half, spot, radius));
    EXPECT_FALSE(after.empty());
}

TEST(HashGrid, EmptyGridAndBadRadius) {
    HashGrid grid;
    int visited = 0;
    grid.for_each_near(Vec3(0.0f), [&](uint32_t, float) { ++visited; });
    grid.build(std::vector<Vec3>{}, 1.0f);
    grid.for_each_near(Vec3(0.0f), [&](uint32_t, float) { ++visited; });
    EXPECT_EQ(visited, 0);
    const std::vector<Vec3> one{Vec3(0.0f)};
    EXPECT_THROW(grid.build(one, 0.0f), Error);
    EXPECT_THROW(grid.build(one, -1.0f), Error);
    EXPECT_THROW(grid.build(one, std::numeric_limits<float>::infinity()), Error);
}
