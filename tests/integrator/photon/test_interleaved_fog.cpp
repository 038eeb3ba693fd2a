// Interleaved single scattering (integrator/photon/interleaved_fog.h) on synthetic legs:
// one pixel per 2 x 2 block is picked, each in turn; a pixel reads only estimates of legs
// like its own, so nothing crosses a silhouette; every pixel with a leg reads at least one
// estimate; a smooth field comes back as it was.
#include <glint/core/rng.h>
#include <glint/integrator/photon/interleaved_fog.h>
#include <glint/medium/homogeneous_medium.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace glint;

namespace {

// Two media: the legs compare them by identity alone.
const Medium* fog_medium() {
    static const HomogeneousMedium fog(Rgb(0.01f), Rgb(0.1f), 0.0f);
    return &fog;
}
const Medium* smoke_medium() {
    static const HomogeneousMedium smoke(Rgb(0.02f), Rgb(0.3f), 0.5f);
    return &smoke;
}

DeferredLeg leg_of(const Medium* medium, float start, float length) {
    DeferredLeg leg;
    leg.medium = medium;
    leg.start = start;
    leg.length = length;
    return leg;
}

// Fills `fog` for `pass` with leg(x, y), estimates every pixel that estimates() picks with
// value(x, y), and returns how many did.
int run_pass(InterleavedFog& fog, Vec2i size, int pass,
             const std::function<DeferredLeg(int, int)>& leg,
             const std::function<float(int, int)>& value) {
    fog.reset(size, pass);
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            fog.leg(x, y) = leg(x, y);
            fog.finish_leg(x, y);
        }
    }
    int estimated = 0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            if (!fog.estimates(x, y)) continue;
            fog.set_estimate(x, y, Spectrum(value(x, y)));
            ++estimated;
        }
    }
    return estimated;
}

}  // namespace

TEST(InterleavedFog, PicksOnePixelPerBlockAndEachInTurn) {
    const Vec2i size(8, 6);
    InterleavedFog fog;
    std::vector<int> picks(static_cast<size_t>(size.x * size.y), 0);
    constexpr int kPasses = 400;
    for (int pass = 0; pass < kPasses; ++pass) {
        fog.reset(size, pass);
        for (int by = 0; by < size.y; by += 2) {
            for (int bx = 0; bx < size.x; bx += 2) {
                int in_block = 0;
                for (int y = by; y < by + 2; ++y)
                    for (int x = bx; x < bx + 2; ++x)
                        if (fog.picked(x, y)) {
                            ++in_block;
                            ++picks[static_cast<size_t>(y * size.x + x)];
                        }
                EXPECT_EQ(in_block, 1) << "block " << bx << ", " << by << ", pass " << pass;
            }
        }
    }
    // About a quarter of the passes each (100 +- 8.7 for independent choices).
    for (int count : picks) {
        EXPECT_GT(count, 60);
        EXPECT_LT(count, 140);
    }
}

TEST(InterleavedFog, SmoothFogIsSharedAndComesBackAsItWas) {
    const Vec2i size(16, 12);
    InterleavedFog fog;
    for (int pass = 0; pass < 8; ++pass) {
        // Alike legs everywhere (a floor seen at a slant: lengths within 1 % of a neighbour's).
        const int estimated = run_pass(
            fog, size, pass,
            [](int x, int y) {
                return leg_of(fog_medium(), 1.0f, 4.0f * (1.0f + 0.002f * (x + y)));
            },
            [](int, int) { return 0.25f; });
        EXPECT_EQ(estimated, size.x * size.y / 4) << "one pixel per block, no other";
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                EXPECT_FLOAT_EQ(fog.reconstruct(x, y).value(0), 0.25f) << x << ", " << y;
    }
}

TEST(InterleavedFog, NeverReadsAcrossASilhouette) {
    // An object in front of the fog on the left (short legs), the far wall on the right
    // (legs three times as long), and another medium in a band along the bottom: each
    // pixel's estimate says which it is, and must be the only kind it reads.
    const Vec2i size(15, 11);
    const auto leg = [](int x, int y) {
        if (y >= 8) return leg_of(smoke_medium(), 1.0f, 2.0f);
        return leg_of(fog_medium(), 1.0f, x < 7 ? 1.0f : 3.0f);
    };
    const auto kind = [](int x, int y) { return y >= 8 ? 5.0f : x < 7 ? 1.0f : 3.0f; };
    InterleavedFog fog;
    for (int pass = 0; pass < 16; ++pass) {
        const int estimated = run_pass(fog, size, pass, leg, kind);
        EXPECT_LT(estimated, size.x * size.y / 2) << "most pixels share";
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                EXPECT_FLOAT_EQ(fog.reconstruct(x, y).value(0), kind(x, y)) << x << ", " << y;
    }
}

TEST(InterleavedFog, PixelsWithoutALegReadNothingAndLegsAtInfinityShare) {
    // A chequer of sky seen through fog (infinite legs) and pixels that see no fog.
    const Vec2i size(10, 10);
    InterleavedFog fog;
    for (int pass = 0; pass < 8; ++pass) {
        run_pass(
            fog, size, pass,
            [](int x, int y) {
                return (x / 3 + y / 3) % 2 == 0 ? leg_of(fog_medium(), 0.5f, kInfinity)
                                                : leg_of(nullptr, 0.0f, 0.0f);
            },
            [](int, int) { return 2.0f; });
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                const bool has_leg = (x / 3 + y / 3) % 2 == 0;
                EXPECT_EQ(fog.estimates(x, y) && !has_leg, false);
                EXPECT_FLOAT_EQ(fog.reconstruct(x, y).value(0), has_leg ? 2.0f : 0.0f);
            }
        }
    }
}

TEST(InterleavedFog, LegsAreAlikeWithinFivePercent) {
    EXPECT_TRUE(InterleavedFog::alike(leg_of(fog_medium(), 1.0f, 2.0f),
                                      leg_of(fog_medium(), 1.04f, 2.09f)));
    EXPECT_FALSE(
        InterleavedFog::alike(leg_of(fog_medium(), 1.0f, 2.0f), leg_of(fog_medium(), 1.0f, 2.2f)));
    EXPECT_FALSE(
        InterleavedFog::alike(leg_of(fog_medium(), 1.0f, 2.0f), leg_of(fog_medium(), 1.2f, 2.0f)));
    EXPECT_FALSE(InterleavedFog::alike(leg_of(fog_medium(), 1.0f, 2.0f),
                                       leg_of(smoke_medium(), 1.0f, 2.0f)));
    EXPECT_TRUE(InterleavedFog::alike(leg_of(fog_medium(), 0.0f, kInfinity),
                                      leg_of(fog_medium(), 0.0f, kInfinity)));
    EXPECT_FALSE(InterleavedFog::alike(leg_of(fog_medium(), 0.0f, kInfinity),
                                       leg_of(fog_medium(), 0.0f, 1e30f)));
    EXPECT_FALSE(InterleavedFog::alike(leg_of(nullptr, 0.0f, 1.0f), leg_of(nullptr, 0.0f, 1.0f)));
}

// estimates() and reconstruct() against their definitions, neighbour by neighbour, on
// random windows (odd sizes, so that blocks at the edges are cut), random picks and legs of
// two media, none, and lengths that jump: estimates(), which looks only at the picked
// pixels of the blocks round a pixel, and reconstruct() must give the same answers and
// the same bits.
TEST(InterleavedFog, FastPathsAgreeWithTheDefinitions) {
    Rng rng(0x6f67u);
    const Medium* media[3] = {fog_medium(), smoke_medium(), nullptr};
    int estimating = 0, sharing = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const Vec2i size(1 + static_cast<int>(rng.next_float() * 13.0f),
                         1 + static_cast<int>(rng.next_float() * 11.0f));
        std::vector<DeferredLeg> legs;
        for (int i = 0; i < size.x * size.y; ++i) {
            const float u = rng.next_float();
            legs.push_back(
                leg_of(media[u < 0.6f   ? 0
                             : u < 0.8f ? 1
                                        : 2],
                       1.0f, rng.next_float() < 0.7f ? 2.0f + 0.05f * rng.next_float() : 4.0f));
        }
        const auto leg = [&](int x, int y) { return legs[static_cast<size_t>(y * size.x + x)]; };
        InterleavedFog fog;
        run_pass(fog, size, trial, leg, [&](int x, int y) { return 1.0f + x + 0.37f * y; });
        const auto inside = [&](int x, int y) {
            return x >= 0 && y >= 0 && x < size.x && y < size.y;
        };
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                bool expected = false;
                if (leg(x, y).medium) {
                    expected = fog.picked(x, y);
                    bool neighbour_alike = false;
                    for (int ny = y - 1; ny <= y + 1; ++ny)
                        for (int nx = x - 1; nx <= x + 1; ++nx)
                            if (inside(nx, ny) && fog.picked(nx, ny) &&
                                InterleavedFog::alike(leg(x, y), leg(nx, ny)))
                                neighbour_alike = true;
                    expected = expected || !neighbour_alike;
                }
                ASSERT_EQ(fog.estimates(x, y), expected) << trial << ": " << x << ", " << y;
                estimating += expected && !fog.picked(x, y);
                // The mean of the alike neighbours that estimated, in row order.
                Spectrum sum(0.0f);
                int count = 0;
                for (int ny = y - 1; ny <= y + 1; ++ny) {
                    for (int nx = x - 1; nx <= x + 1; ++nx) {
                        if (!inside(nx, ny) || !fog.estimates(nx, ny) ||
                            !InterleavedFog::alike(leg(x, y), leg(nx, ny)))
                            continue;
                        sum += Spectrum(1.0f + nx + 0.37f * ny);
                        ++count;
                    }
                }
                sharing += count > 1;
                const Spectrum mean = count > 0 ? sum / static_cast<float>(count) : Spectrum(0.0f);
                ASSERT_EQ(fog.reconstruct(x, y).value(0), mean.value(0)) << x << ", " << y;
            }
        }
    }
    // Both ways out of estimates() and the mean over several were taken.
    EXPECT_GT(estimating, 100);
    EXPECT_GT(sharing, 100);
}
