// The mipmap pyramid (material/texture/mipmap.h): levels that keep the image's mean for
// any size, filtering in linear values for 8-bit sRGB images, and the anisotropic filter
// keeping what the trilinear one blurs.
#include <glint/core/rng.h>
#include <glint/material/texture/mipmap.h>

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

StoredImage float_image(int width, int height, Rng& rng) {
    StoredImage stored;
    stored.image = make_image(width, height, {"R", "G", "B"});
    for (float& v : stored.image.pixels) v = rng.next_float();
    return stored;
}

Rgb mean_of(const Image& image) {
    Rgb sum(0.0f);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            sum += Rgb(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
    return sum / static_cast<float>(image.width * image.height);
}

// A footprint larger than the image reads the last level, one texel.
Rgb top_level(const MipMap& mipmap) {
    return mipmap.lookup(Vec2(0.5f), Vec2(4.0f, 0.0f), Vec2(0.0f, 4.0f), TextureFilter::kTrilinear,
                         TextureWrap::kClamp);
}

}  // namespace

// Each halving averages the area its texels cover, odd sizes included (three taps with
// the overlaps' weights), so the one-texel top of the pyramid is the image's mean.
TEST(MipMap, EveryPyramidEndsAtTheImagesMean) {
    Rng rng(7);
    for (const auto& [width, height] :
         {std::pair{1, 1}, {2, 2}, {3, 5}, {7, 1}, {1, 9}, {13, 6}, {37, 29}, {64, 63}, {100, 3}}) {
        const StoredImage stored = float_image(width, height, rng);
        const MipMap mipmap(stored, false, "random");
        const Rgb expected = mean_of(stored.image), top = top_level(mipmap);
        const int expected_levels =
            1 + static_cast<int>(std::floor(std::log2(std::max(width, height))));
        EXPECT_EQ(mipmap.levels(), expected_levels) << width << "x" << height;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(top[c], expected[c], 2e-6f) << width << "x" << height << " channel " << c;
    }
}

// A black and white 8-bit sRGB checkerboard averages to linear 0.5, stored again as the
// nearest 8-bit sRGB code (188); averaging the codes first would give 0.214.
TEST(MipMap, EightBitImagesFilterInLinearValues) {
    StoredImage stored;
    stored.image = make_image(2, 2, {"R", "G", "B"});
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < 3; ++c) stored.image.at(x, y, c) = (x + y) % 2 ? 1.0f : 0.0f;
    stored.integer = true;
    stored.bits_per_value = 8;
    const MipMap srgb(stored, true, "checker");
    EXPECT_NEAR(top_level(srgb).g, 0.5f, 0.004f);
    const MipMap linear(stored, false, "checker");
    EXPECT_NEAR(top_level(linear).g, 128.0f / 255.0f, 1e-6f);
    // Level 0 returns the codes decoded exactly.
    const Rgb white = srgb.lookup(Vec2(0.75f, 0.25f), Vec2(0.0f), Vec2(0.0f),
                                  TextureFilter::kAnisotropic, TextureWrap::kRepeat);
    EXPECT_FLOAT_EQ(white.r, 1.0f);
}

// Vertical stripes a texel wide, seen with a footprint one texel across and 16 along them:
// the anisotropic filter keeps the stripe (it averages along the stripe only), trilinear
// filtering takes the level of the long side and returns the grey mean.
TEST(MipMap, AnisotropicFilterAveragesAlongTheLongSideOnly) {
    StoredImage stored;
    const int n = 64;
    stored.image = make_image(n, n, {"R", "G", "B"});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c) stored.image.at(x, y, c) = x % 2 ? 1.0f : 0.0f;
    const MipMap mipmap(stored, false, "stripes");
    const float texel = 1.0f / n;
    const Vec2 st((21 + 0.5f) * texel, 0.5f);  // the centre of a white column
    const Vec2 across(0.5f * texel, 0.0f), along(0.0f, 16.0f * texel);
    const float aniso =
        mipmap.lookup(st, across, along, TextureFilter::kAnisotropic, TextureWrap::kRepeat).r;
    const float trilinear =
        mipmap.lookup(st, across, along, TextureFilter::kTrilinear, TextureWrap::kRepeat).r;
    EXPECT_GT(aniso, 0.99f);
    EXPECT_NEAR(trilinear, 0.5f, 0.01f);
    // Which of the two vectors is the long one does not matter.
    const float turned =
        mipmap.lookup(st, along, across, TextureFilter::kAnisotropic, TextureWrap::kRepeat).r;
    EXPECT_EQ(turned, aniso);
}

}  // namespace glint
