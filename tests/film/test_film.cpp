#include <glint/core/error.h>
#include <glint/film/film.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace glint {
namespace {

TEST(Film, ChannelsAndSize) {
    const Film plain(4, 3, false);
    EXPECT_EQ(plain.width(), 4);
    EXPECT_EQ(plain.height(), 3);
    EXPECT_FALSE(plain.has_aovs());
    const Image a = plain.resolve();
    EXPECT_EQ(a.width, 4);
    EXPECT_EQ(a.height, 3);
    EXPECT_EQ(a.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(a.pixels.size(), 4u * 3u * 3u);

    const Film with(2, 2, true);
    const Image b = with.resolve();
    EXPECT_EQ(b.channels,
              (std::vector<std::string>{"R", "G", "B", "albedo.R", "albedo.G", "albedo.B",
                                        "normal.X", "normal.Y", "normal.Z", "depth.Z"}));
    EXPECT_THROW(Film(0, 5, false), Error);
}

TEST(Film, WeightedMeanPerPixel) {
    Film film(3, 2, false);
    film.add_sample({1, 0}, uplift(Rgb(1.0f, 2.0f, 3.0f), RgbRole::unbounded), 1.0f, nullptr);
    film.add_sample({1, 0}, uplift(Rgb(4.0f, 0.0f, 1.0f), RgbRole::unbounded), 3.0f, nullptr);
    // Negative weights (Mitchell lobes) enter the same mean.
    film.add_sample({2, 1}, Spectrum(2.0f), 2.0f, nullptr);
    film.add_sample({2, 1}, Spectrum(5.0f), -0.5f, nullptr);
    const Image img = film.resolve();
    EXPECT_FLOAT_EQ(img.at(1, 0, 0), (1.0f + 12.0f) / 4.0f);
    EXPECT_FLOAT_EQ(img.at(1, 0, 1), 2.0f / 4.0f);
    EXPECT_FLOAT_EQ(img.at(1, 0, 2), (3.0f + 3.0f) / 4.0f);
    EXPECT_FLOAT_EQ(img.at(2, 1, 0), (4.0f - 2.5f) / 1.5f);
    // Untouched pixels and pixels whose weights cancel are black, not NaN.
    EXPECT_EQ(img.at(0, 0, 0), 0.0f);
    Film cancel(1, 1, false);
    cancel.add_sample({0, 0}, Spectrum(3.0f), 1.0f, nullptr);
    cancel.add_sample({0, 0}, Spectrum(3.0f), -1.0f, nullptr);
    EXPECT_EQ(cancel.resolve().at(0, 0, 1), 0.0f);
}

TEST(Film, RowMajorTopRowFirst) {
    Film film(2, 2, false);
    film.add_sample({1, 0}, Spectrum(7.0f), 1.0f, nullptr);
    const Image img = film.resolve();
    EXPECT_EQ(img.pixels[(0 * 2 + 1) * 3], 7.0f);
}

TEST(Film, NonFiniteSamplesAreSkippedAndCounted) {
    Film film(2, 1, false);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    film.add_sample({0, 0}, Spectrum(2.0f), 1.0f, nullptr);
    film.add_sample({0, 0}, uplift(Rgb(nan, 1.0f, 1.0f), RgbRole::unbounded), 1.0f, nullptr);
    film.add_sample({0, 0}, uplift(Rgb(1.0f, inf, 1.0f), RgbRole::unbounded), 1.0f, nullptr);
    film.add_sample({0, 0}, Spectrum(1.0f), nan, nullptr);
    film.add_sample({1, 0}, Spectrum(-inf), 1.0f, nullptr);
    const Image img = film.resolve();
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(img.at(0, 0, c), 2.0f);
        EXPECT_EQ(img.at(1, 0, c), 0.0f);
    }
    EXPECT_EQ(film.non_finite_samples(), 4u);
    film.clear();
    EXPECT_EQ(film.non_finite_samples(), 0u);
    EXPECT_EQ(film.resolve().at(0, 0, 0), 0.0f);
}

TEST(Film, AovsUseAbsoluteWeights) {
    Film film(1, 1, true);
    const AovSample first{uplift(Rgb(0.2f, 0.4f, 0.6f), RgbRole::unbounded), Vec3(0.0f, 0.0f, 1.0f),
                          2.0f};
    const AovSample second{Spectrum(1.0f), Vec3(1.0f, 0.0f, 0.0f), 6.0f};
    film.add_sample({0, 0}, Spectrum(1.0f), 3.0f, &first);
    film.add_sample({0, 0}, Spectrum(1.0f), -1.0f, &second);
    // A sample without features still counts towards radiance only.
    film.add_sample({0, 0}, Spectrum(1.0f), 1.0f, nullptr);
    const Image img = film.resolve();
    const auto at = [&](const char* name) { return img.at(0, 0, img.channel_index(name)); };
    EXPECT_FLOAT_EQ(at("R"), 1.0f);
    EXPECT_FLOAT_EQ(at("albedo.R"), (3 * 0.2f + 1.0f) / 4);
    EXPECT_FLOAT_EQ(at("albedo.G"), (3 * 0.4f + 1.0f) / 4);
    EXPECT_FLOAT_EQ(at("albedo.B"), (3 * 0.6f + 1.0f) / 4);
    EXPECT_FLOAT_EQ(at("normal.X"), 0.25f);
    EXPECT_FLOAT_EQ(at("normal.Y"), 0.0f);
    EXPECT_FLOAT_EQ(at("normal.Z"), 0.75f);
    EXPECT_FLOAT_EQ(at("depth.Z"), 3.0f);
}

TEST(Film, AovIgnoredWithoutAovChannels) {
    Film film(1, 1, false);
    const AovSample aov{Spectrum(1.0f), Vec3(0.0f, 1.0f, 0.0f), 1.0f};
    film.add_sample({0, 0}, Spectrum(0.5f), 1.0f, &aov);
    const Image img = film.resolve();
    EXPECT_EQ(img.channels.size(), 3u);
    EXPECT_EQ(img.at(0, 0, 0), 0.5f);
}

TEST(Film, RejectsPixelsOutside) {
    Film film(2, 2, false);
    EXPECT_THROW(film.add_sample({2, 0}, Spectrum(1.0f), 1.0f, nullptr), Error);
    EXPECT_THROW(film.add_sample({0, -1}, Spectrum(1.0f), 1.0f, nullptr), Error);
}

TEST(Film, OrderOfPixelsDoesNotMatter) {
    // What thread-count independence rests on: pixels are independent accumulators, so
    // filling them in another order (as other tile schedules would) gives the same bits.
    Film forward(8, 8, false), backward(8, 8, false);
    const auto value = [](int x, int y, int s) {
        return uplift(Rgb(0.1f * x + 0.37f * s, 0.01f * y * s, 1.0f / (1 + x + y + s)),
                      RgbRole::unbounded);
    };
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int s = 0; s < 5; ++s)
                forward.add_sample({x, y}, value(x, y, s), 0.3f + s, nullptr);
    for (int y = 7; y >= 0; --y)
        for (int x = 7; x >= 0; --x)
            for (int s = 0; s < 5; ++s)
                backward.add_sample({x, y}, value(x, y, s), 0.3f + s, nullptr);
    EXPECT_EQ(forward.resolve().pixels, backward.resolve().pixels);
}

}  // namespace
// Splats: each lands in the pixel that contains its film position (x right, y down, pixel
// (i, j) covering [i, i + 1) x [j, j + 1)), scaled by the splat scale on top of the mean of
// the samples.
TEST(Film, SplatsLandInTheirPixelAndAreScaled) {
    Film film(4, 3, false);
    film.add_sample({2, 1}, uplift(Rgb(1.0f, 2.0f, 3.0f), RgbRole::unbounded), 1.0f, nullptr);
    const Splat splats[] = {
        {Vec2(2.5f, 1.5f), uplift(Rgb(0.5f, 1.0f, 1.5f), RgbRole::unbounded)},
        {Vec2(2.0f, 1.99f),
         uplift(Rgb(0.25f, 0.0f, 0.0f), RgbRole::unbounded)},  // the same pixel, at its edges
        {Vec2(0.1f, 2.9f), uplift(Rgb(4.0f, 5.0f, 6.0f), RgbRole::unbounded)},   // bottom-left
        {Vec2(3.99f, 0.0f), uplift(Rgb(7.0f, 8.0f, 9.0f), RgbRole::unbounded)},  // top-right
    };
    film.add_splats(splats);
    film.set_splat_scale(2.0);
    const Image image = film.resolve();
    EXPECT_FLOAT_EQ(image.at(2, 1, 0), 1.0f + 2.0f * 0.75f);
    EXPECT_FLOAT_EQ(image.at(2, 1, 1), 2.0f + 2.0f * 1.0f);
    EXPECT_FLOAT_EQ(image.at(2, 1, 2), 3.0f + 2.0f * 1.5f);
    EXPECT_FLOAT_EQ(image.at(0, 2, 1), 10.0f);
    EXPECT_FLOAT_EQ(image.at(3, 0, 2), 18.0f);
    float total = 0.0f;
    for (float v : image.pixels) total += v;
    EXPECT_FLOAT_EQ(total, 6.0f + 2.0f * (3.0f + 0.25f + 15.0f + 24.0f));
    EXPECT_EQ(film.non_finite_samples(), 0u);
}

TEST(Film, SplatsOutsideAreIgnoredAndNonFiniteOnesCounted) {
    Film film(3, 2, false);
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Splat splats[] = {
        {Vec2(-0.01f, 1.0f), Spectrum(1.0f)},
        {Vec2(3.0f, 1.0f), Spectrum(1.0f)},
        {Vec2(1.0f, -0.5f), Spectrum(1.0f)},
        {Vec2(1.0f, 2.0f), Spectrum(1.0f)},
        {Vec2(1e30f, 1.0f), Spectrum(1.0f)},
        {Vec2(1.0f, 1.0f), uplift(Rgb(nan, 1.0f, 1.0f), RgbRole::unbounded)},
        {Vec2(1.0f, 1.0f), Spectrum(inf)},
        {Vec2(nan, 1.0f), Spectrum(1.0f)},
    };
    film.add_splats(splats);
    const Image image = film.resolve();
    for (float v : image.pixels) EXPECT_EQ(v, 0.0f);
    EXPECT_EQ(film.non_finite_samples(), 3u);
    film.clear();
    EXPECT_EQ(film.non_finite_samples(), 0u);
}

// Without splats, resolve() is the samples' weighted mean exactly as before, bit for bit.
TEST(Film, ResolveWithoutSplatsIsTheWeightedMean) {
    Film film(2, 2, false);
    film.set_splat_scale(3.0);
    film.add_sample({0, 0}, uplift(Rgb(0.1f, 0.2f, 0.3f), RgbRole::unbounded), 0.7f, nullptr);
    film.add_sample({0, 0}, uplift(Rgb(0.4f, 0.5f, 0.9f), RgbRole::unbounded), 0.3f, nullptr);
    film.add_splats({});
    const Image image = film.resolve();
    // As the film accumulates: in double, the float weights, then times the inverse sum.
    const double w1 = 0.7f, w2 = 0.3f, inv = 1.0 / (w1 + w2);
    EXPECT_EQ(image.at(0, 0, 0), static_cast<float>((w1 * 0.1f + w2 * 0.4f) * inv));
    EXPECT_EQ(image.at(0, 0, 2), static_cast<float>((w1 * 0.3f + w2 * 0.9f) * inv));
    EXPECT_EQ(image.at(1, 0, 1), 0.0f);
}

}  // namespace glint

namespace glint {
namespace {

TEST(FilmHalves, EvenAndOddSamplesSplitAndTheWholeStaysTheSame) {
    Film plain(2, 1, true);
    Film split(2, 1, true, Vec2i(0, 0), true);
    EXPECT_FALSE(plain.has_halves());
    EXPECT_TRUE(split.has_halves());
    const float values[] = {1.0f, 2.0f, 4.0f, 8.0f, 16.0f};
    for (int k = 0; k < 5; ++k) {
        const AovSample aov{Spectrum(0.1f * k), Vec3(0, 0, 1), static_cast<float>(k)};
        for (Film* film : {&plain, &split}) {
            film->add_sample(Vec2i(1, 0), Spectrum(values[k]), 1.0f, &aov, k);
            film->add_sample(Vec2i(0, 0), Spectrum(1.0f), 0.5f, &aov, k);
        }
    }
    EXPECT_EQ(split.resolve().pixels, plain.resolve().pixels);
    const Image even = split.resolve_half(0), odd = split.resolve_half(1);
    EXPECT_EQ(even.channels, plain.resolve().channels);
    EXPECT_FLOAT_EQ(even.at(1, 0, 0), (1.0f + 4.0f + 16.0f) / 3.0f);
    EXPECT_FLOAT_EQ(odd.at(1, 0, 0), (2.0f + 8.0f) / 2.0f);
    EXPECT_FLOAT_EQ(even.at(1, 0, even.channel_index("depth.Z")), 2.0f);  // (0 + 2 + 4) / 3
    EXPECT_FLOAT_EQ(odd.at(1, 0, odd.channel_index("depth.Z")), 2.0f);    // (1 + 3) / 2
    EXPECT_FLOAT_EQ(odd.at(0, 0, 0), 1.0f);
    // A window keeps its pixels' halves; a film without halves has none to give.
    const Film right = split.window(Vec2i(1, 0), 1, 1);
    EXPECT_TRUE(right.has_halves());
    EXPECT_FLOAT_EQ(right.resolve_half(1).at(0, 0, 0), 5.0f);
    EXPECT_THROW(plain.resolve_half(0), Error);
    split.clear();
    EXPECT_EQ(split.resolve_half(0).at(1, 0, 0), 0.0f);
}

}  // namespace
}  // namespace glint
