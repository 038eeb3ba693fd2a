// Tiling (denoise/tiling.h) and the transfer functions (denoise/transfer.h).
#include <glint/core/error.h>
#include <glint/denoise/tiling.h>
#include <glint/denoise/transfer.h>
#include <glint/film/image_io.h>

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

// Every pixel is kept by exactly one tile; a kept pixel is at least `overlap` pixels from
// its tile's edges unless it is that close to the image's edge; tiles lie in the image.
void expect_valid_plan(int width, int height, int max_tile) {
    const TilePlan plan = plan_denoise_tiles(width, height, max_tile);
    EXPECT_LE(plan.width, max_tile);
    EXPECT_LE(plan.height, max_tile);
    EXPECT_EQ(plan.width % denoise_tile_alignment, 0);
    EXPECT_EQ(plan.height % denoise_tile_alignment, 0);
    std::vector<int> kept(static_cast<std::size_t>(width) * height, 0);
    const int ov = denoise_tile_overlap;
    for (const DenoiseTile& t : plan.tiles) {
        EXPECT_GE(t.x, 0);
        EXPECT_GE(t.y, 0);
        if (width >= plan.width) {
            EXPECT_LE(t.x + plan.width, width);
        }
        if (height >= plan.height) {
            EXPECT_LE(t.y + plan.height, height);
        }
        EXPECT_TRUE(t.keep_x0 == 0 || t.keep_x0 >= t.x + ov) << width;
        EXPECT_TRUE(t.keep_y0 == 0 || t.keep_y0 >= t.y + ov) << height;
        EXPECT_TRUE(t.keep_x1 == width || t.keep_x1 <= t.x + plan.width - ov) << width;
        EXPECT_TRUE(t.keep_y1 == height || t.keep_y1 <= t.y + plan.height - ov) << height;
        for (int y = t.keep_y0; y < t.keep_y1; ++y)
            for (int x = t.keep_x0; x < t.keep_x1; ++x)
                ++kept[static_cast<std::size_t>(y) * width + x];
    }
    for (int count : kept)
        ASSERT_EQ(count, 1) << width << " x " << height << " in tiles of " << max_tile;
}

TEST(DenoiseTiles, CoverEveryPixelOnceWithTheOverlapInside) {
    for (int size : {1, 15, 16, 17, 200, 256, 257, 300, 511, 700, 1000, 1500})
        for (int other : {1, 37, 256, 900}) {
            expect_valid_plan(size, other, 256);
            expect_valid_plan(other, size, 512);
        }
}

TEST(DenoiseTiles, SmallImageIsOnePaddedTile) {
    const TilePlan plan = plan_denoise_tiles(100, 30, 1024);
    ASSERT_EQ(plan.tiles.size(), 1u);
    EXPECT_EQ(plan.width, 112);
    EXPECT_EQ(plan.height, 32);
}

TEST(DenoiseTiles, BadSizesThrow) {
    EXPECT_THROW(plan_denoise_tiles(0, 10, 256), Error);
    EXPECT_THROW(plan_denoise_tiles(10, 10, 200), Error);  // not a multiple of 16
    EXPECT_THROW(plan_denoise_tiles(10, 10, 192), Error);  // no room inside the overlap
}

TEST(DenoiseTransfer, PuIsNormalisedMonotonicAndInvertible) {
    EXPECT_NEAR(pu_forward(65504.f), 1.f, 1e-6f);
    EXPECT_EQ(pu_forward(0.f), 0.f);
    float previous = -1.f;
    for (float y = 1e-8f; y < 6e4f; y *= 1.37f) {
        const float x = pu_forward(y);
        EXPECT_GT(x, previous) << y;
        previous = x;
        EXPECT_NEAR(pu_inverse(x), y, 2e-4f * y + 1e-9f) << y;
    }
}

TEST(DenoiseTransfer, SrgbRoundTrips) {
    for (float y = 0.f; y <= 1.f; y += 0.01f)
        EXPECT_NEAR(srgb_to_linear(srgb_forward(y)), y, 1e-6f);
    EXPECT_NEAR(srgb_forward(1.f), 1.f, 1e-6f);
}

TEST(DenoiseTransfer, AutoexposureBringsMeanLogLuminanceToMiddleGrey) {
    Image image = make_image(40, 20, {"R", "G", "B"});
    for (float& v : image.pixels) v = 4.f;
    EXPECT_NEAR(autoexposure(image), 0.18f / 4.f, 1e-6f);
    // Two halves of luminance 1 and 16: geometric mean 4 over the bins.
    Image halves = make_image(32, 16, {"R", "G", "B"});
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            for (int c = 0; c < 3; ++c) halves.at(x, y, c) = x < 16 ? 1.f : 16.f;
    EXPECT_NEAR(autoexposure(halves), 0.18f / 4.f, 1e-6f);
    Image black = make_image(8, 8, {"R", "G", "B"});
    EXPECT_EQ(autoexposure(black), 1.f);
}

}  // namespace
}  // namespace glint
