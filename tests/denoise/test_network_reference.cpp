// glint's network denoiser against an independent implementation of the same filter: OIDN's
// "rt" U-Net with OIDN's input and output processing, run by TensorFlow.js. The fixture in
// data/ holds a small noisy render with its features and that implementation's output; its
// README says how both were made. Agreement to float rounding means that the transfer
// function, the exposure, the feature encodings, the padding to a multiple of 16, the
// layers and the output clamp are all what OIDN does.
#include <glint/denoise/network_denoiser.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "weights.h"

namespace glint {
namespace {

// A fixture file: width, height and channels as little-endian int32, then the pixels'
// channels interleaved as float32, rows top first.
Image read_fixture(const std::string& name, const std::vector<std::string>& channels) {
    const std::string path = fmt::format("{}/tests/denoise/data/{}", GLINT_SOURCE_DIR, name);
    std::ifstream file(path, std::ios::binary);
    std::int32_t dims[3] = {0, 0, 0};
    if (!file.read(reinterpret_cast<char*>(dims), sizeof(dims)))
        throw std::runtime_error(path + ": cannot read the header");
    if (dims[2] != static_cast<std::int32_t>(channels.size()))
        throw std::runtime_error(path + ": unexpected channel count");
    Image image = make_image(dims[0], dims[1], channels);
    if (!file.read(reinterpret_cast<char*>(image.pixels.data()),
                   static_cast<std::streamsize>(image.pixels.size() * sizeof(float))))
        throw std::runtime_error(path + ": truncated");
    return image;
}

TEST(NetworkDenoiserReference, MatchesTensorFlowJsRunOfOidnNetwork) {
    test::installed_weights("rt_hdr_alb_nrm");
    const Image input = read_fixture(
        "oidn_reference_input.bin",
        {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z"});
    const Image expected = read_fixture("oidn_reference_output.bin", {"R", "G", "B"});
    ASSERT_EQ(input.width, expected.width);
    ASSERT_EQ(input.height, expected.height);
    // Not a multiple of 16 either way, so the zero padding is part of what is compared.
    ASSERT_NE(input.width % 16, 0);
    ASSERT_NE(input.height % 16, 0);
    NetworkDenoiseSettings settings;
    settings.threads = 1;
    settings.border_margin = 0;  // zeros beyond the border, as OIDN
    const Image result = denoise_network(input, settings);
    double difference = 0.0, norm = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
        const double d = static_cast<double>(result.pixels[i]) - expected.pixels[i];
        difference += d * d;
        norm += static_cast<double>(expected.pixels[i]) * expected.pixels[i];
        // Relative, with a floor below the image's darkest visible values.
        worst = std::max(worst, std::abs(d) / (std::abs(expected.pixels[i]) + 1e-2));
    }
    const double relative_l2 = std::sqrt(difference / norm);
    fmt::print("against TensorFlow.js: relative L2 difference {:.2e}, largest {:.2e}\n",
               relative_l2, worst);
    // Both sum float32 products in different orders: measured 2.6e-6 and 6.9e-6. The bounds
    // leave room for other kernels (AVX2 / AVX-512) but not for any change of the processing:
    // the normals left in [-1, 1], or no exposure, differ by more than 1e-2.
    EXPECT_LT(relative_l2, 1e-4);
    EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace glint
