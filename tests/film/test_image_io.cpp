#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/film/image_io.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>

namespace glint {
namespace {

namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                (std::string("glint_image_io_") + info->name() + "_" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string file(const std::string& name) const { return (m_dir / name).string(); }
    std::set<std::string> listing() const {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(m_dir)) {
            names.insert(entry.path().filename().string());
        }
        return names;
    }

    fs::path m_dir;
};

Image rgb_row(std::initializer_list<float> values) {
    // One pixel per value, grey.
    Image img = make_image(static_cast<int>(values.size()), 1, {"R", "G", "B"});
    int x = 0;
    for (float v : values) {
        for (int c = 0; c < 3; ++c) img.at(x, 0, c) = v;
        ++x;
    }
    return img;
}

double srgb_decode(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

// read_image decodes PNGs to linear; the byte that was stored is the one whose decoding
// matches. Adjacent bytes decode at least 3e-4 apart, so a 1e-5 match is unambiguous.
int stored_byte(float linear) {
    int best = -1;
    double best_err = 1.0;
    for (int b = 0; b < 256; ++b) {
        const double err = std::abs(srgb_decode(b / 255.0) - linear);
        if (err < best_err) best = b, best_err = err;
    }
    EXPECT_LT(best_err, 1e-5) << "value " << linear << " is no 8-bit sRGB code";
    return best;
}

TEST_F(ImageIo, ExrRoundTripIsExactWithAovChannels) {
    Image img = make_image(5, 3,
                           {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X",
                            "normal.Y", "normal.Z", "depth.Z"});
    Rng rng(42);
    for (float& v : img.pixels) v = (rng.next_float() - 0.3f) * 1e3f * rng.next_float();
    img.at(0, 0, 0) = 1e-30f;
    img.at(1, 0, 0) = 65504.0f * 10.0f;  // beyond half range: must stay 32-bit
    const std::string path = file("round.exr");
    write_image(path, img);
    EXPECT_EQ(listing(), std::set<std::string>{"round.exr"});

    const Image back = read_image(path);
    ASSERT_EQ(back.width, 5);
    ASSERT_EQ(back.height, 3);
    ASSERT_EQ(back.channels.size(), img.channels.size());
    // OpenEXR orders channels by layer; compare by name.
    for (int c = 0; c < img.num_channels(); ++c) {
        const int bc = back.channel_index(img.channels[c]);
        ASSERT_GE(bc, 0) << img.channels[c];
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                ASSERT_EQ(back.at(x, y, bc), img.at(x, y, c)) << img.channels[c];
    }
}

TEST_F(ImageIo, PngEncodesSrgbCorrectlyRounded) {
    // The linear value whose sRGB code is exactly 127.5: a hair either side must round to
    // 127 and 128, which truncation or a gamma-2.2 curve would get wrong.
    const float half_code = static_cast<float>(srgb_decode(127.5 / 255.0));
    const Image img = rgb_row({0.0f, 1.0f, 0.5f, 2.0f, -1.0f, std::nanf(""), half_code * 0.9999f,
                               half_code * 1.0001f, 0.002f});
    const std::string path = file("codes.png");
    write_image(path, img);
    const Image back = read_image(path);
    ASSERT_EQ(back.width, img.width);
    ASSERT_GE(back.channel_index("B"), 0);
    const int expected[] = {0, 255, 188, 255, 0, 0, 127, 128, 7};  // 0.002 * 12.92 * 255 = 6.6
    for (int x = 0; x < img.width; ++x) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(stored_byte(back.at(x, 0, back.channel_index(img.channels[c]))), expected[x])
                << "pixel " << x;
        }
    }
}

TEST_F(ImageIo, PngExposureScalesLinearValues) {
    const std::string plus = file("plus.png"), plain = file("plain.png");
    write_image(plus, rgb_row({0.25f, 0.1f, 0.6f}), WriteOptions{1.0f});
    write_image(plain, rgb_row({0.5f, 0.2f, 1.2f}));
    const Image a = read_image(plus), b = read_image(plain);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_EQ(stored_byte(a.at(0, 0, 0)), 188);
    EXPECT_EQ(stored_byte(a.at(2, 0, 0)), 255);
    // Exposure is a display setting: EXR keeps the radiance as it is.
    write_image(file("raw.exr"), rgb_row({0.25f}), WriteOptions{3.0f});
    EXPECT_EQ(read_image(file("raw.exr")).at(0, 0, 0), 0.25f);
}

TEST_F(ImageIo, UnsupportedExtensionThrowsAndWritesNothing) {
    const std::string path = file("out.bmp");
    try {
        write_image(path, rgb_row({1.0f}));
        FAIL() << "unsupported extension accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find(".exr"), std::string::npos) << message;
        EXPECT_NE(message.find(".png"), std::string::npos) << message;
    }
    EXPECT_THROW(write_image(file("noextension"), rgb_row({1.0f})), Error);
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIo, MissingDirectoryThrowsAndLeavesNoTemporary) {
    for (const char* name : {"out.exr", "out.png"}) {
        const std::string path = (m_dir / "missing" / name).string();
        try {
            write_image(path, rgb_row({1.0f}));
            FAIL() << "wrote into a missing directory";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIo, FailedWriteKeepsThePreviousFile) {
    const std::string path = file("keep.png");
    write_image(path, rgb_row({0.5f}));
    // Two channels that are not R, G, B cannot become a PNG.
    Image odd = make_image(1, 1, {"U", "V"});
    EXPECT_THROW(write_image(path, odd), Error);
    EXPECT_EQ(listing(), std::set<std::string>{"keep.png"});
    EXPECT_EQ(stored_byte(read_image(path).at(0, 0, 0)), 188);
    // A successful write replaces it and leaves no temporary beside it.
    write_image(path, rgb_row({1.0f}));
    EXPECT_EQ(listing(), std::set<std::string>{"keep.png"});
    EXPECT_EQ(stored_byte(read_image(path).at(0, 0, 0)), 255);
}

TEST_F(ImageIo, ReadErrorsNameThePath) {
    const std::string missing = file("nothing.exr");
    try {
        read_image(missing);
        FAIL() << "read a missing file";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    const std::string garbage = file("garbage.exr");
    std::ofstream(garbage) << "not an image";
    EXPECT_THROW(read_image(garbage), Error);
}

TEST(CompareImages, IdenticalImagesGiveZero) {
    Image img = make_image(4, 4, {"R", "G", "B"});
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = 0.1f * (i % 7);
    const CompareResult r = compare_images(img, img);
    EXPECT_EQ(r.rel_mse, 0.0);
    EXPECT_EQ(r.rmse, 0.0);
    EXPECT_EQ(r.test_mean, r.ref_mean);
}

TEST(CompareImages, KnownPerturbation) {
    Image ref = make_image(3, 2, {"R", "G", "B"});
    for (float& v : ref.pixels) v = 0.5f;
    // Same values, channels stored in another order plus an extra one: matched by name.
    Image test = make_image(3, 2, {"B", "G", "R", "depth.Z"});
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            test.at(x, y, 0) = 0.5f;
            test.at(x, y, 1) = 0.5f;
            test.at(x, y, 2) = 0.6f;  // R is 0.1 too bright everywhere
            test.at(x, y, 3) = 100.0f;
        }
    }
    const CompareResult r = compare_images(test, ref);
    const double d2 = std::pow(0.6 - 0.5, 2);  // in float: (0.6f - 0.5f)^2
    EXPECT_NEAR(r.rel_mse, d2 / (0.25 + 1e-2) / 3.0, 1e-7);
    EXPECT_NEAR(r.rmse, std::sqrt(d2 / 3.0), 1e-6);
    EXPECT_NEAR(r.test_mean[0], 0.6, 1e-6);
    EXPECT_NEAR(r.test_mean[1], 0.5, 1e-6);
    EXPECT_NEAR(r.ref_mean[0], 0.5, 1e-6);
}

TEST(CompareImages, MismatchThrows) {
    const Image a = make_image(2, 2, {"R", "G", "B"});
    EXPECT_THROW(compare_images(a, make_image(2, 3, {"R", "G", "B"})), Error);
    EXPECT_THROW(compare_images(a, make_image(2, 2, {"Y"})), Error);
}

}  // namespace
}  // namespace glint
