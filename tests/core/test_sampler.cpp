#include <glint/core/error.h>
#include <glint/core/sampler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
        for (const auto& pair : points) {
            // Elementary intervals of shape 2^-a x 2^-(k-a) each hold exactly one point.
            const int k = static_cast<int>(std::log2(count));
            for (int a = 0; a <= k; ++a) {
                const int nx = 1 << a, ny = 1 << (k - a);
                std::vector<int> hits(count, 0);
                for (const Vec2& p : pair) ++hits[static_cast<int>(p.y * ny) * nx + static_cast<int>(p.x * nx)];
                for (int h : hits) EXPECT_EQ(h, 1) << count << " samples, intervals " << nx << "x" << ny;
            }
        }
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
