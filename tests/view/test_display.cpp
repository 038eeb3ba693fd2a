// What the viewer's window shows: with `clip`, the bytes of `glint render`'s PNG output.
#include <glint/core/error.h>
#include <glint/film/image_io.h>
#include <glint/view/display.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace glint {
namespace {

Image ramp() {
    // Values from black to well past white, with a NaN and a negative value.
    Image image = make_image(64, 4, {"R", "G", "B"});
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = std::pow(2.0f, (x - 48) / 4.0f) * (1.0f + 0.3f * c + 0.1f * y);
        }
    }
    image.at(0, 0, 0) = std::nanf("");
    image.at(1, 0, 1) = -1.0f;
    return image;
}

// The ramp, and below it every 8-bit code's neighbourhood: values spread evenly through
// [0, 1.1), where the codes change at thresholds the display looks up.
Image test_image() {
    const Image top = ramp();
    Image image = make_image(64, top.height + 256, {"R", "G", "B"});
    std::copy(top.pixels.begin(), top.pixels.end(), image.pixels.begin());
    for (int y = top.height; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const int i = ((y - top.height) * image.width + x) * 3 + c;
                image.at(x, y, c) = 1.1f * static_cast<float>(i) / (256 * 64 * 3);
            }
        }
    }
    return image;
}

TEST(Display, ClipShowsThePngBytes) {
    const Image image = test_image();
    for (const float exposure : {0.0f, -1.5f, 2.0f}) {
        const std::string path =
            (std::filesystem::path(testing::TempDir()) / "glint_display_test.png").string();
        write_image(path, image, WriteOptions{exposure});
        // The PNG's bytes: read back (to linear) and encoded without exposure.
        const std::vector<uint8_t> png = display_pixels(read_image(path), ToneMapping{});
        EXPECT_EQ(display_pixels(image, ToneMapping{Tonemap::clip, exposure}), png) << exposure;
        std::filesystem::remove(path);
    }
}

TEST(Display, ReinhardNeverClipsAndKeepsOrder) {
    const std::vector<uint8_t> shown = display_pixels(ramp(), ToneMapping{Tonemap::reinhard, 0.0f});
    const int w = 64;
    for (int x = 1; x < w; ++x) {
        EXPECT_LT(shown[(3 * w + x) * 4 + 2], 255) << x;  // even 2^4 * 1.9 stays below white
        EXPECT_GE(shown[(3 * w + x) * 4 + 2], shown[(3 * w + x - 1) * 4 + 2]) << x;
    }
    EXPECT_EQ(shown[3], 255);  // alpha
}

TEST(Display, SavedScreenshotHasTheShownBytes) {
    std::vector<uint8_t> rgba(256 * 4);
    for (int v = 0; v < 256; ++v) {
        rgba[v * 4] = static_cast<uint8_t>(v);
        rgba[v * 4 + 1] = static_cast<uint8_t>(255 - v);
        rgba[v * 4 + 2] = static_cast<uint8_t>((v * 7) % 256);
        rgba[v * 4 + 3] = 255;
    }
    const Image image = image_from_display(rgba, 256, 1);
    EXPECT_EQ(display_pixels(image, ToneMapping{}), rgba);
    const std::string path =
        (std::filesystem::path(testing::TempDir()) / "glint_display_shot.png").string();
    write_image(path, image);
    EXPECT_EQ(display_pixels(read_image(path), ToneMapping{}), rgba);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace glint
