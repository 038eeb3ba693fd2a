// The network denoiser as a whole (denoise/network_denoiser.h).
#include <glint/core/error.h>
#include <glint/denoise/network_denoiser.h>

#include <gtest/gtest.h>

#include <utility>

#include "weights.h"

namespace glint {
namespace {

TEST(NetworkDenoiser, MissingWeightsNameTheInstallStep) {
    NetworkDenoiseSettings settings;
    settings.weights_dir = "/nonexistent/glint-weights";
    Image image = make_image(
        16, 16,
        {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z"});
    try {
        denoise_network(image, settings);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("/nonexistent/glint-weights/rt_hdr_alb_nrm.tza"), std::string::npos)
            << message;
        EXPECT_NE(message.find("scripts/install-deps.sh"), std::string::npos) << message;
    }
}

// The mirrored border margin (32 pixels) is wider than these images: the mirroring repeats
// until it covers it, and only the image's own pixels come back.
TEST(NetworkDenoiser, ImagesNarrowerThanTheBorderMarginAreDenoised) {
    test::installed_weights("rt_hdr_alb_nrm");
    for (const auto& [w, h] : {std::pair{1, 1}, std::pair{5, 3}, std::pair{2, 40}}) {
        Image image = make_image(w, h,
                                 {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X",
                                  "normal.Y", "normal.Z"});
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                for (int c = 0; c < 6; ++c) image.at(x, y, c) = 0.5f;
                image.at(x, y, 8) = 1.f;
            }
        }
        NetworkDenoiseSettings settings;
        const Image result = denoise_network(image, settings);
        ASSERT_EQ(result.width, w);
        ASSERT_EQ(result.height, h);
        for (float v : result.pixels) EXPECT_NEAR(v, 0.5f, 0.05f) << w << " x " << h;
    }
}

TEST(NetworkDenoiser, NegativeBorderMarginIsAClearError) {
    test::installed_weights("rt_hdr_alb_nrm");
    Image image = make_image(
        16, 16,
        {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z"});
    NetworkDenoiseSettings settings;
    settings.border_margin = -1;
    EXPECT_THROW(denoise_network(image, settings), Error);
}

}  // namespace
}  // namespace glint
