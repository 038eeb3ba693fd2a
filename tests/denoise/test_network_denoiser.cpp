// The network denoiser as a whole (denoise/network_denoiser.h).
#include <glint/core/error.h>
#include <glint/denoise/network_denoiser.h>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace glint
