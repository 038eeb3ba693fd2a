#include <glint/core/error.h>
#include <glint/film/image_io.h>
#include <glint/film/tonemap.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

namespace glint {
namespace {

constexpr Tonemap kCurves[] = {Tonemap::clip, Tonemap::reinhard, Tonemap::filmic};

TEST(Tonemap, EveryCurveMapsZeroToZeroAndStaysInTheUnitInterval) {
    for (Tonemap curve : kCurves) {
        SCOPED_TRACE(tonemap_name(curve));
        EXPECT_EQ(tone_curve(curve, 0.0), 0.0);
        EXPECT_EQ(tone_curve(curve, -3.0), 0.0);
        EXPECT_EQ(tone_curve(curve, std::nan("")), 0.0);
        EXPECT_LE(tone_curve(curve, std::numeric_limits<double>::infinity()), 1.0);
        EXPECT_GT(tone_curve(curve, std::numeric_limits<double>::infinity()), 0.99);
        for (double x = 1e-4; x < 1e4; x *= 1.1) {
            const double y = tone_curve(curve, x);
            EXPECT_GT(y, 0.0) << x;
            EXPECT_LE(y, 1.0) << x;
        }
    }
}

TEST(Tonemap, EveryCurveIsMonotone) {
    for (Tonemap curve : kCurves) {
        SCOPED_TRACE(tonemap_name(curve));
        double previous = 0.0;
        // Fine steps over [0, 20], where filmic reaches its clamp, then coarser ones.
        for (double x = 0.0; x < 1e5; x += x < 20.0 ? 1e-3 : x * 0.01) {
            const double y = tone_curve(curve, x);
            ASSERT_GE(y, previous) << "at " << x;
            previous = y;
        }
    }
}

TEST(Tonemap, ClipIsTheIdentityUpToOneThenSaturates) {
    for (double x : {1e-6, 0.01, 0.5, 0.999}) EXPECT_EQ(tone_curve(Tonemap::clip, x), x);
    for (double x : {1.0, 1.0001, 7.0, 1e30}) EXPECT_EQ(tone_curve(Tonemap::clip, x), 1.0);
}

TEST(Tonemap, ReinhardIsXOverOnePlusX) {
    for (double x : {1e-3, 0.25, 1.0, 3.0, 99.0}) {
        EXPECT_DOUBLE_EQ(tone_curve(Tonemap::reinhard, x), x / (1.0 + x));
    }
    EXPECT_DOUBLE_EQ(tone_curve(Tonemap::reinhard, 1.0), 0.5);
}

TEST(Tonemap, FilmicMatchesNarkowiczsAcesFitAtKnownPoints) {
    // f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), evaluated by hand.
    EXPECT_NEAR(tone_curve(Tonemap::filmic, 0.18), 0.266899, 1e-6);  // 18 % grey
    EXPECT_NEAR(tone_curve(Tonemap::filmic, 1.0), 2.54 / 3.16, 1e-12);
    EXPECT_NEAR(tone_curve(Tonemap::filmic, 0.01), 0.000551 / 0.146143, 1e-9);
    // A toe below the identity in the shadows, above it in the mid-tones, and saturated
    // beyond the point where the fit crosses 1 (about 7.24).
    EXPECT_LT(tone_curve(Tonemap::filmic, 0.02), 0.02);
    EXPECT_GT(tone_curve(Tonemap::filmic, 0.5), 0.5);
    EXPECT_LT(tone_curve(Tonemap::filmic, 7.0), 1.0);
    EXPECT_EQ(tone_curve(Tonemap::filmic, 7.5), 1.0);
}

TEST(Tonemap, EachStopOfExposureDoublesTheInput) {
    for (Tonemap curve : kCurves) {
        for (double x : {0.01, 0.1, 0.3}) {
            for (float stops : {-2.0f, 1.0f, 3.0f}) {
                EXPECT_DOUBLE_EQ(tone_map_value({curve, stops}, x),
                                 tone_curve(curve, x * std::exp2(static_cast<double>(stops))));
            }
            EXPECT_DOUBLE_EQ(tone_map_value({curve, 1.0f}, x),
                             tone_map_value({curve, 0.0f}, 2 * x));
        }
    }
}

TEST(Tonemap, NamesRoundTripAndUnknownOnesListTheKnown) {
    for (Tonemap curve : kCurves) EXPECT_EQ(parse_tonemap(tonemap_name(curve)), curve);
    try {
        parse_tonemap("aces2");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("clip, reinhard, filmic"), std::string::npos);
    }
}

TEST(Tonemap, ImageVersionMapsRgbAndLeavesOtherChannels) {
    Image image = make_image(2, 1, {"R", "G", "B", "depth.Z"});
    const float values[] = {0.5f, 1.0f, 3.0f, 7.0f, 0.0f, 0.25f, -1.0f, 9.0f};
    for (int i = 0; i < 8; ++i) image.pixels[i] = values[i];
    tone_map(image, {Tonemap::reinhard, 1.0f});
    EXPECT_FLOAT_EQ(image.at(0, 0, 0), 0.5f);  // 2 * 0.5 = 1 -> 1/2
    EXPECT_FLOAT_EQ(image.at(0, 0, 2), 6.0f / 7.0f);
    EXPECT_EQ(image.at(0, 0, 3), 7.0f);
    EXPECT_EQ(image.at(1, 0, 2), 0.0f);
    EXPECT_EQ(image.at(1, 0, 3), 9.0f);
}

class TonemapOutput : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = std::filesystem::temp_directory_path() /
                (std::string("glint_tonemap_") + info->name() + "_" + std::to_string(::getpid()));
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::string file(const std::string& name) const { return (m_dir / name).string(); }
    std::filesystem::path m_dir;
};

Image row(std::initializer_list<float> values) {
    Image image = make_image(static_cast<int>(values.size()), 1, {"R", "G", "B"});
    int x = 0;
    for (float v : values) {
        for (int c = 0; c < 3; ++c) image.at(x, 0, c) = v;
        ++x;
    }
    return image;
}

TEST_F(TonemapOutput, PngStoresTheCurveSrgbEncoded) {
    const Image image = row({0.25f, 1.0f, 4.0f, 100.0f});
    for (Tonemap curve : kCurves) {
        const std::string path = file(tonemap_name(curve) + ".png");
        write_image(path, image, WriteOptions{1.0f, curve});
        const Image back = read_image(path);
        for (int x = 0; x < image.width; ++x) {
            const double expected = tone_map_value({curve, 1.0f}, image.at(x, 0, 0));
            // read_image decodes sRGB; 8-bit quantisation leaves half a code of error.
            EXPECT_NEAR(back.at(x, 0, 0), expected, 0.01 * expected + 2e-3)
                << tonemap_name(curve) << " pixel " << x;
        }
    }
}

TEST_F(TonemapOutput, ExrStaysLinearWhateverTheCurve) {
    const Image image = row({0.25f, 3.0f, 1e4f});
    for (Tonemap curve : kCurves) {
        const std::string path = file(tonemap_name(curve) + ".exr");
        write_image(path, image, WriteOptions{2.0f, curve});
        EXPECT_EQ(read_image(path).pixels, image.pixels) << tonemap_name(curve);
    }
}

}  // namespace
}  // namespace glint
