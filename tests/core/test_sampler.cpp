#include <glint/core/error.h>
#include <glint/core/sampler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace glint;

TEST(Sampler, SameKeyGivesSameNumbers) {
    for (const char* name : {"independent", "stratified"}) {
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
    for (const char* name : {"independent", "stratified"}) {
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
