// The .tza reader (denoise/tza.h) and the U-Net built from it (denoise/unet.h).
#include <glint/core/error.h>
#include <glint/denoise/tza.h>
#include <glint/denoise/unet.h>

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>

#include "weights.h"

namespace glint {
namespace {

// Appends a little-endian value.
template <typename T>
void put(std::vector<std::uint8_t>& bytes, T value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

struct FakeTensor {
    std::string name;
    std::vector<std::uint32_t> dims;
    std::string layout;
    char type;
};

// An archive of the given tensors, float data i * 0.5 (or the half-float 1.0 for 'h').
std::vector<std::uint8_t> make_archive(const std::vector<FakeTensor>& tensors,
                                       std::uint8_t major = 2) {
    std::vector<std::uint8_t> bytes;
    put<std::uint16_t>(bytes, 0x41D7);
    put<std::uint8_t>(bytes, major);
    put<std::uint8_t>(bytes, 0);
    put<std::uint64_t>(bytes, 0);  // table offset, patched below
    std::vector<std::uint64_t> offsets;
    for (const FakeTensor& t : tensors) {
        offsets.push_back(bytes.size());
        std::size_t count = 1;
        for (auto d : t.dims) count *= d;
        for (std::size_t i = 0; i < count; ++i) {
            if (t.type == 'f')
                put<float>(bytes, 0.5f * static_cast<float>(i));
            else
                put<std::uint16_t>(bytes, 0x3C00);
        }
    }
    const std::uint64_t table = bytes.size();
    std::memcpy(bytes.data() + 4, &table, 8);
    put<std::uint32_t>(bytes, static_cast<std::uint32_t>(tensors.size()));
    for (std::size_t k = 0; k < tensors.size(); ++k) {
        const FakeTensor& t = tensors[k];
        put<std::uint16_t>(bytes, static_cast<std::uint16_t>(t.name.size()));
        bytes.insert(bytes.end(), t.name.begin(), t.name.end());
        put<std::uint8_t>(bytes, static_cast<std::uint8_t>(t.dims.size()));
        for (auto d : t.dims) put<std::uint32_t>(bytes, d);
        bytes.insert(bytes.end(), t.layout.begin(), t.layout.end());
        put<char>(bytes, t.type);
        put<std::uint64_t>(bytes, offsets[k]);
    }
    return bytes;
}

const std::vector<FakeTensor> conv_tensors = {{"c.weight", {2, 1, 3, 3}, "oihw", 'f'},
                                              {"c.bias", {2}, "x", 'h'}};

std::string error_of(const std::vector<std::uint8_t>& bytes) {
    try {
        parse_tza(bytes, "fake.tza");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Tza, ReadsShapesLayoutsAndBothElementTypes) {
    const TensorArchive archive = parse_tza(make_archive(conv_tensors), "fake.tza");
    ASSERT_EQ(archive.size(), 2u);
    const Tensor& w = archive.at("c.weight");
    EXPECT_EQ(w.dims, (std::vector<int>{2, 1, 3, 3}));
    EXPECT_EQ(w.layout, "oihw");
    ASSERT_EQ(w.size(), 18u);
    EXPECT_EQ(w.values[17], 8.5f);
    EXPECT_EQ(archive.at("c.bias").values, (std::vector<float>{1.f, 1.f}));
}

TEST(Tza, HalfFloatsConvertExactly) {
    EXPECT_EQ(half_to_float(0x3C00), 1.f);
    EXPECT_EQ(half_to_float(0xC000), -2.f);
    EXPECT_EQ(half_to_float(0x7BFF), 65504.f);
    EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.f, -24));  // smallest subnormal
    EXPECT_EQ(half_to_float(0x3555), 0.333251953125f);
    EXPECT_TRUE(std::isinf(half_to_float(0x7C00)));
    EXPECT_TRUE(std::isnan(half_to_float(0x7E00)));
    EXPECT_EQ(std::signbit(half_to_float(0x8000)), true);
}

TEST(Tza, EveryTruncationIsAClearError) {
    const std::vector<std::uint8_t> whole = make_archive(conv_tensors);
    for (std::size_t size = 0; size < whole.size(); ++size) {
        const std::vector<std::uint8_t> cut(whole.begin(),
                                            whole.begin() + static_cast<std::ptrdiff_t>(size));
        const std::string message = error_of(cut);
        ASSERT_NE(message.find("fake.tza"), std::string::npos) << size;
        const bool says_why = message.find("truncated") != std::string::npos ||
                              message.find("past its end") != std::string::npos ||
                              message.find("outside the file") != std::string::npos;
        EXPECT_TRUE(says_why) << size << ": " << message;
    }
}

TEST(Tza, CorruptOrOtherVersionIsAClearError) {
    std::vector<std::uint8_t> bytes = make_archive(conv_tensors);
    bytes[0] ^= 0xff;
    EXPECT_NE(error_of(bytes).find("magic"), std::string::npos) << error_of(bytes);
    EXPECT_NE(error_of(make_archive(conv_tensors, 1)).find("version 1"), std::string::npos);
    EXPECT_NE(error_of(make_archive(conv_tensors, 3)).find("version 3"), std::string::npos);
    bytes = make_archive(conv_tensors);
    bytes[4] = 0xff;  // the table offset points past the end
    EXPECT_NE(error_of(bytes).find("past its end"), std::string::npos) << error_of(bytes);
    EXPECT_NE(error_of(make_archive({{"w", {2, 2}, "ab", 'f'}})).find("layout 'ab'"),
              std::string::npos);
    EXPECT_NE(error_of(make_archive({{"w", {2}, "x", 'd'}})).find("element type 'd'"),
              std::string::npos);
    // A tensor whose data offset points beyond the file.
    bytes = make_archive({{"w", {4}, "x", 'f'}});
    const std::size_t offset_at = bytes.size() - 8;
    bytes[offset_at] = 0xf0;
    EXPECT_NE(error_of(bytes).find("outside the file"), std::string::npos) << error_of(bytes);
}

TEST(Tza, MissingFileIsAClearError) {
    try {
        read_tza("/nonexistent/weights.tza");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/weights.tza"), std::string::npos);
    }
}

TEST(Tza, InstalledWeightsFileTruncatedIsAClearError) {
    const std::string path = test::installed_weights("rt_hdr_alb_nrm_small");
    std::ifstream file(path, std::ios::binary);
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                    std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 100u);
    bytes.erase(bytes.end() - 100, bytes.end());  // loses the end of the table
    EXPECT_NE(error_of(bytes).find("truncated"), std::string::npos) << error_of(bytes);
}

// The published networks have the shapes the U-Net expects: 9 inputs, the channel counts
// of each level, and 3 outputs.
TEST(UNet, InstalledNetworksHaveTheExpectedShapes) {
    struct Expected {
        const char* name;
        int inputs;
        std::size_t convolutions;
        int first_channels;
    };
    for (const Expected& e :
         {Expected{"rt_hdr_alb_nrm", 9, 16, 32}, Expected{"rt_hdr_alb_nrm_small", 9, 16, 32},
          Expected{"rt_hdr_calb_cnrm_large", 9, 19, 64}, Expected{"rt_alb_large", 3, 19, 64},
          Expected{"rt_nrm", 3, 16, 32}}) {
        const std::string path = test::installed_weights(e.name);
        const NetworkGraph graph = make_unet(read_tza(path), e.inputs, path);
        std::size_t convolutions = 0;
        for (const Layer& layer : graph.layers) convolutions += layer.kind == LayerKind::Conv;
        EXPECT_EQ(convolutions, e.convolutions) << e.name;
        EXPECT_EQ(graph.layers[1].channels, e.first_channels) << e.name;
        EXPECT_EQ(graph.output().channels, 3) << e.name;
        EXPECT_EQ(graph.max_level(), 4) << e.name;
    }
}

TEST(UNet, WrongInputChannelsOrMissingTensorIsAClearError) {
    const std::string path = test::installed_weights("rt_hdr_alb_nrm");
    const TensorArchive archive = read_tza(path);
    try {
        make_unet(archive, 6, path);  // trained on 9 channels
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("enc_conv0.weight' has shape [32, 9, 3, 3]"),
                  std::string::npos)
            << e.what();
    }
    TensorArchive partial = archive;
    partial.erase("dec_conv2b.bias");
    try {
        make_unet(partial, 9, path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no tensor 'dec_conv2b.bias'"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace glint
