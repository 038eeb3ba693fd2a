#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/core/sampler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace glint;

TEST(Sampler, SameKeyGivesSameNumbers) {
    for (const char* name : {"independent", "stratified", "sobol"}) {
        auto a = make_sampler(name, 16, 7);
        auto b = a->clone();
        a->start_pixel_sample(Vec2i(3, 5), 9);
        b->start_pixel_sample(Vec2i(3, 5), 9);
        for (int i = 0; i < 10; ++i) EXPECT_EQ(a->get_1d(), b->get_1d()) << name;
        b->start_pixel_sample(Vec2i(3, 6), 9);
        a->start_pixel_sample(Vec2i(3, 5), 9);
        EXPECT_NE(a->get_1d(), b->get_1d()) << name;
    }
}

// Lanes cloned for one thread may share per-pixel work (the Sobol group keys), but each
// gives what a sampler of its own gives, however their draws interleave, across pixels
// and for paths deeper than the shared key cache.
TEST(Sampler, LaneClonesGiveWhatLoneSamplersGive) {
    for (const char* name : {"independent", "stratified", "sobol"}) {
        auto first = make_sampler(name, 16, 7);
        auto second = first->clone_for_lane();
        for (const Vec2i pixel : {Vec2i(3, 5), Vec2i(4, 5), Vec2i(3, 5)}) {
            first->start_pixel_sample(pixel, 2);
            second->start_pixel_sample(pixel, 11);
            std::vector<float> first_values, second_values;
            for (int d = 0; d < 200; ++d) {  // 50 groups of four: past the 32 cached keys
                second_values.push_back(d % 3 == 0 ? second->get_2d().y : second->get_1d());
                first_values.push_back(d % 3 == 0 ? first->get_2d().y : first->get_1d());
            }
            for (const auto& [index, values] :
                 {std::pair{2, &first_values}, std::pair{11, &second_values}}) {
                auto lone = make_sampler(name, 16, 7);
                lone->start_pixel_sample(pixel, index);
                for (int d = 0; d < 200; ++d) {
                    const float expected = d % 3 == 0 ? lone->get_2d().y : lone->get_1d();
                    ASSERT_EQ((*values)[d], expected)
                        << name << ", sample " << index << ", draw " << d;
                }
            }
        }
    }
}

TEST(Sampler, ValuesInUnitInterval) {
    for (const char* name : {"independent", "stratified", "sobol"}) {
        auto s = make_sampler(name, 7, 1);
        for (int i = 0; i < 7; ++i) {
            s->start_pixel_sample(Vec2i(1, 2), i);
            for (int d = 0; d < 20; ++d) {
                const float v = s->get_1d();
                EXPECT_GE(v, 0.0f);
                EXPECT_LT(v, 1.0f);
            }
        }
    }
}

// Each stratum of every dimension receives exactly one of the pixel's samples.
TEST(Sampler, StratifiedCoversEveryStratumOnce) {
    for (int spp : {16, 7}) {
        auto s = make_sampler("stratified", spp, 3);
        const int dims = 6;
        std::vector<std::vector<int>> strata(dims);
        for (int i = 0; i < spp; ++i) {
            s->start_pixel_sample(Vec2i(4, 4), i);
            for (int d = 0; d < dims; ++d) strata[d].push_back(static_cast<int>(s->get_1d() * spp));
        }
        for (auto& values : strata) {
            std::sort(values.begin(), values.end());
            for (int i = 0; i < spp; ++i) EXPECT_EQ(values[i], i) << "spp " << spp;
        }
    }
    auto grid = make_sampler("stratified", 16, 3);
    std::vector<int> cells;
    for (int i = 0; i < 16; ++i) {
        grid->start_pixel_sample(Vec2i(0, 0), i);
        const Vec2 u = grid->get_2d();
        cells.push_back(static_cast<int>(u.y * 4) * 4 + static_cast<int>(u.x * 4));
    }
    std::sort(cells.begin(), cells.end());
    for (int i = 0; i < 16; ++i) EXPECT_EQ(cells[i], i);
}

TEST(Sampler, UnknownNameThrows) {
    EXPECT_THROW(make_sampler("sobolx", 4, 0), Error);
}

namespace {

// The (0,2)-net property of a power-of-two number of points: elementary intervals of shape
// 2^-a x 2^-(k-a) each hold exactly one point.
void expect_one_point_per_elementary_interval(const std::vector<Vec2>& points) {
    const int count = static_cast<int>(points.size());
    const int k = static_cast<int>(std::log2(count));
    for (int a = 0; a <= k; ++a) {
        const int nx = 1 << a, ny = 1 << (k - a);
        std::vector<int> hits(count, 0);
        for (const Vec2& p : points)
            ++hits[static_cast<int>(p.y * ny) * nx + static_cast<int>(p.x * nx)];
        for (int h : hits) EXPECT_EQ(h, 1) << count << " samples, intervals " << nx << "x" << ny;
    }
}

}  // namespace

// Owen-scrambled Sobol: every power-of-two prefix of a pixel's samples is stratified in
// each dimension and in each pair's elementary intervals (the (0,2)-sequence property),
// so adaptive sampling can stop a pixel after any such prefix.
TEST(Sampler, SobolPrefixesAreStratified) {
    auto s = make_sampler("sobol", 1024, 11);
    for (int count : {4, 16, 64}) {
        const int dims = 4;  // two 2D pairs
        std::vector<Vec2> points[dims / 2];
        for (int i = 0; i < count; ++i) {
            s->start_pixel_sample(Vec2i(7, 3), i);
            for (int d = 0; d < dims / 2; ++d) points[d].push_back(s->get_2d());
        }
        for (const auto& pair : points) expect_one_point_per_elementary_interval(pair);
    }
}

TEST(Sampler, SobolDiffersBetweenPixelsAndDimensions) {
    auto s = make_sampler("sobol", 16, 2);
    s->start_pixel_sample(Vec2i(0, 0), 5);
    const Vec2 a = s->get_2d(), b = s->get_2d();
    s->start_pixel_sample(Vec2i(1, 0), 5);
    const Vec2 c = s->get_2d();
    EXPECT_NE(a, b);
    EXPECT_NE(a, c);
}

// The Sobol sampler hands out dimensions in groups of four: a 2D request takes a group's
// first two, 1D requests the next free ones. The path tracer's pattern per bounce (a 2D
// value, then two 1D values) must keep every power-of-two prefix stratified in each 1D
// dimension (Sobol dimensions 2 and 3 included) and in the 2D pairs' elementary intervals,
// also when a 2D request follows 1D requests that left the group half used.
TEST(Sampler, SobolGroupsKeepEveryDimensionStratified) {
    auto s = make_sampler("sobol", 1024, 3);
    for (int count : {4, 16, 64, 256}) {
        std::vector<float> ones[5];
        std::vector<Vec2> twos[2];
        for (int i = 0; i < count; ++i) {
            s->start_pixel_sample(Vec2i(2, 9), i);
            ones[0].push_back(s->get_1d());  // opens group 0: dimension 0
            twos[0].push_back(s->get_2d());  // group 1, dimensions 0 and 1
            ones[1].push_back(s->get_1d());  // group 1, dimension 2
            ones[2].push_back(s->get_1d());  // group 1, dimension 3
            ones[3].push_back(s->get_1d());  // group 2, dimension 0
            twos[1].push_back(s->get_2d());  // group 3
            ones[4].push_back(s->get_1d());
        }
        for (const auto& values : ones) {
            std::vector<int> hits(count, 0);
            for (float v : values) ++hits[static_cast<int>(v * count)];
            for (int h : hits) EXPECT_EQ(h, 1) << count << " samples";
        }
        for (const auto& pair : twos) expect_one_point_per_elementary_interval(pair);
    }
}

// Dimensions of different groups are scrambled independently: over a pixel's samples, the
// first dimensions of two groups are uncorrelated (an unshuffled index would make them
// move together).
TEST(Sampler, SobolGroupsAreDecorrelated) {
    auto s = make_sampler("sobol", 256, 8);
    double sum_a = 0, sum_b = 0, sum_ab = 0, sum_aa = 0, sum_bb = 0;
    const int n = 256;
    for (int i = 0; i < n; ++i) {
        s->start_pixel_sample(Vec2i(5, 5), i);
        const double a = s->get_2d().x;
        const double b = s->get_2d().x;
        sum_a += a, sum_b += b, sum_ab += a * b, sum_aa += a * a, sum_bb += b * b;
    }
    const double cov = sum_ab / n - (sum_a / n) * (sum_b / n);
    const double var_a = sum_aa / n - (sum_a / n) * (sum_a / n);
    const double var_b = sum_bb / n - (sum_b / n) * (sum_b / n);
    const double correlation = cov / std::sqrt(var_a * var_b);
    // Independent uniforms: the sample correlation's standard deviation is 1/sqrt(n) = 0.0625.
    EXPECT_LT(std::abs(correlation), 0.25) << correlation;
}

// The SIMD path chosen for this CPU must give exactly the portable path's values, or images
// would depend on the machine. Random inputs cover every byte of the table lookups.
TEST(Sampler, SobolGroupPathsAgreeBitForBit) {
    Rng rng(2024);
    for (int i = 0; i < 100000; ++i) {
        const uint32_t index = rng.next_u32(), key = rng.next_u32();
        const detail::SobolGroupPaths paths = detail::sobol_group_by_each_path(index, key);
        for (int d = 0; d < 4; ++d) {
            ASSERT_EQ(paths.portable[d], paths.fastest[d])
                << "index " << index << ", key " << key << ", dimension " << d;
            ASSERT_GE(paths.portable[d], 0.0f);
            ASSERT_LT(paths.portable[d], 1.0f);
        }
    }
}
