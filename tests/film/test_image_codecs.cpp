// The image formats behind read_image and write_image (film/image_codecs.h): PFM in both
// byte orders, half-float EXR, raw (non-sRGB) PNG, the format told by the file's bytes,
// and TIFF refused with a reason.
#include <glint/core/error.h>
#include <glint/film/image_io.h>

#include <gtest/gtest.h>
#include <support/test_util.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace glint {
namespace {

using glint::test::TempDir;

// A PFM file: `values` row by row from the image's top, written bottom row first as the
// format stores them, in the byte order the scale's sign names.
void write_pfm(const std::string& path, const char* kind, int width, int height, float scale,
               const std::vector<float>& values) {
    std::ofstream out(path, std::ios::binary);
    out << kind << "\n" << width << " " << height << "\n" << scale << "\n";
    const bool little = scale < 0.0f;
    const size_t row = values.size() / static_cast<size_t>(height);
    for (int y = height - 1; y >= 0; --y) {
        for (size_t i = 0; i < row; ++i) {
            uint32_t bits;
            std::memcpy(&bits, &values[static_cast<size_t>(y) * row + i], sizeof bits);
            if (little != (std::endian::native == std::endian::little))
                bits = __builtin_bswap32(bits);
            out.write(reinterpret_cast<const char*>(&bits), sizeof bits);
        }
    }
}

// A PNG of 16-bit grey samples (`values`, row by row), written by hand: the deflate stream
// in one stored (uncompressed) block, so no compressor is needed. glint itself writes only
// 8-bit PNGs, and 16-bit ones are what Blender and Substance export for smooth gradients.
void write_png16_grey(const std::string& path, int width, int height,
                      const std::vector<uint16_t>& values) {
    auto crc32 = [](const std::string& bytes) {
        uint32_t crc = 0xffffffffu;
        for (unsigned char byte : bytes) {
            crc ^= byte;
            for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
        return crc ^ 0xffffffffu;
    };
    auto be32 = [](uint32_t v) {
        return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                           static_cast<char>(v >> 8), static_cast<char>(v)};
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return be32(static_cast<uint32_t>(data.size())) + type + data + be32(crc32(type + data));
    };
    std::string raw;  // each row: filter type 0, then big-endian samples
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        for (int x = 0; x < width; ++x) {
            const uint16_t v = values[static_cast<size_t>(y * width + x)];
            raw.push_back(static_cast<char>(v >> 8));
            raw.push_back(static_cast<char>(v & 0xff));
        }
    }
    uint32_t a = 1, b = 0;  // Adler-32 of the raw bytes
    for (unsigned char byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    const uint16_t len = static_cast<uint16_t>(raw.size());
    std::string zlib = {0x78, 0x01, 0x01};  // zlib header; final stored block
    zlib += {static_cast<char>(len & 0xff), static_cast<char>(len >> 8),
             static_cast<char>(~len & 0xff), static_cast<char>((~len >> 8) & 0xff)};
    zlib += raw + be32((b << 16) | a);
    const std::string header = be32(static_cast<uint32_t>(width)) +
                               be32(static_cast<uint32_t>(height)) +
                               std::string{16, 0, 0, 0, 0};  // 16 bits, grey, no interlace
    std::ofstream out(path, std::ios::binary);
    out << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("IHDR", header) << chunk("IDAT", zlib)
        << chunk("IEND", "");
}

std::string error_of(const std::string& path) {
    try {
        read_image(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ImageCodecs, PfmReadsBothByteOrdersTopRowFirst) {
    TempDir dir;
    const std::vector<float> rgb = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};  // 2 x 2, RGB
    write_pfm(dir.file("little.pfm"), "PF", 2, 2, -1.0f, rgb);
    const Image little = read_image(dir.file("little.pfm"));
    ASSERT_EQ(little.width, 2);
    ASSERT_EQ(little.height, 2);
    EXPECT_EQ(little.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(little.pixels, rgb);

    // Big-endian grey, with a scale of 2 that multiplies the values.
    write_pfm(dir.file("big.pfm"), "Pf", 3, 1, 2.0f, {0.5f, -1.0f, 8.0f});
    const Image big = read_image(dir.file("big.pfm"));
    EXPECT_EQ(big.channels, (std::vector<std::string>{"Y"}));
    EXPECT_EQ(big.pixels, (std::vector<float>{1.0f, -2.0f, 16.0f}));
}

TEST(ImageCodecs, DamagedPfmNamesTheFileAndTheFault) {
    TempDir dir;
    write_pfm(dir.file("short.pfm"), "PF", 4, 4, -1.0f, std::vector<float>(3 * 4 * 4, 1.0f));
    std::filesystem::resize_file(dir.file("short.pfm"), 60);
    const std::string truncated = error_of(dir.file("short.pfm"));
    EXPECT_NE(truncated.find("short.pfm"), std::string::npos) << truncated;
    EXPECT_NE(truncated.find("ends early"), std::string::npos) << truncated;

    std::ofstream(dir.file("words.pfm")) << "PF\nwide 4\n-1\n";
    const std::string words = error_of(dir.file("words.pfm"));
    EXPECT_NE(words.find("width"), std::string::npos) << words;

    // The message quotes the header's bytes only as printable text.
    std::ofstream(dir.file("binary.pfm"), std::ios::binary) << "PF\n4\xf9\x01 4\n-1\n";
    const std::string binary = error_of(dir.file("binary.pfm"));
    EXPECT_NE(binary.find("'4?\?'"), std::string::npos) << binary;
}

TEST(ImageCodecs, HalfExrKeepsHalfValuesExactly) {
    TempDir dir;
    // Values a half holds exactly: multiples of 1/64 below 32, the largest half and zero.
    Image image = make_image(64, 64, {"R", "G", "B"});
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>((i * 7919) % 2048) / 64.0f;
    image.pixels[0] = 65504.0f;
    image.pixels[1] = -2.0f;
    WriteOptions half;
    half.half = true;
    write_image(dir.file("half.exr"), image, half);
    const Image back = read_image(dir.file("half.exr"));
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    int mismatches = 0;
    for (const char* name : {"R", "G", "B"}) {  // OpenEXR stores channels sorted by name
        const int in = image.channel_index(name), out = back.channel_index(name);
        ASSERT_GE(out, 0) << name;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                mismatches += back.at(x, y, out) != image.at(x, y, in);
    }
    EXPECT_EQ(mismatches, 0);
    // Half the bytes of the float file, give or take the header.
    write_image(dir.file("float.exr"), image);
    EXPECT_LT(std::filesystem::file_size(dir.file("half.exr")),
              std::filesystem::file_size(dir.file("float.exr")));
}

TEST(ImageCodecs, RawPngStoresTheValuesThemselves) {
    TempDir dir;
    Image image = make_image(4, 1, {"R", "G", "B"});
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) image.at(x, 0, c) = static_cast<float>(x * 60 + c) / 255.0f;
    WriteOptions raw;
    raw.srgb = false;
    write_image(dir.file("normals.png"), image, raw);
    const StoredImage stored = read_stored_image(dir.file("normals.png"));
    EXPECT_TRUE(stored.integer);
    EXPECT_EQ(stored.bits_per_value, 8);
    EXPECT_EQ(stored.alpha, -1);
    EXPECT_EQ(stored.image.pixels, image.pixels);

    // Asked for codes (as textures are), the same values as bytes, and no floats.
    const StoredImage codes = read_stored_image(dir.file("normals.png"), true);
    EXPECT_TRUE(codes.image.pixels.empty());
    ASSERT_EQ(codes.codes.size(), image.pixels.size());
    for (size_t i = 0; i < codes.codes.size(); ++i)
        EXPECT_EQ(codes.codes[i] / 255.0f, image.pixels[i]) << i;
}

// 16-bit PNG samples come back as code / 65535, finer than 8 bits can say, and marked as
// integer (sRGB-encoded) data: read_image decodes them.
TEST(ImageCodecs, SixteenBitPngKeepsItsPrecision) {
    TempDir dir;
    const std::vector<uint16_t> codes = {0, 1, 257, 32768, 65534, 65535};
    write_png16_grey(dir.file("ramp.png"), 3, 2, codes);
    const StoredImage stored = read_stored_image(dir.file("ramp.png"));
    EXPECT_TRUE(stored.integer);
    EXPECT_EQ(stored.bits_per_value, 16);
    ASSERT_EQ(stored.image.width, 3);
    ASSERT_EQ(stored.image.height, 2);
    EXPECT_EQ(stored.image.channels, (std::vector<std::string>{"Y"}));
    for (size_t i = 0; i < codes.size(); ++i)
        EXPECT_FLOAT_EQ(stored.image.pixels[i], codes[i] / 65535.0f) << i;
    EXPECT_TRUE(read_stored_image(dir.file("ramp.png"), true).codes.empty());  // 8-bit only
    const Image decoded = read_image(dir.file("ramp.png"));
    EXPECT_NEAR(decoded.pixels[3], srgb_to_linear(32768.0f / 65535.0f), 1e-7f);
}

// A JPEG read by glint (stb) against the same file read by libjpeg (data/README.md): JPEG
// decoders differ a little in their inverse DCT and chroma upsampling, so the bound is on
// the difference in 8-bit sRGB codes: at most 3 for any value, a quarter on average. The
// wrong transfer curve or channel order would miss it by tens of codes.
TEST(ImageCodecs, JpegReadsAsLibjpegDoes) {
    const std::string data = std::string(GLINT_SOURCE_DIR) + "/tests/film/data/";
    const Image jpeg = read_image(data + "gradient.jpg");
    const Image libjpeg = read_image(data + "gradient-libjpeg.exr");
    ASSERT_EQ(jpeg.width, 40);
    ASSERT_EQ(jpeg.height, 24);
    ASSERT_EQ(libjpeg.width, jpeg.width);
    ASSERT_EQ(libjpeg.height, jpeg.height);
    double largest = 0.0, sum = 0.0;
    int count = 0;
    for (const char* name : {"R", "G", "B"}) {
        const int a = jpeg.channel_index(name), b = libjpeg.channel_index(name);
        ASSERT_GE(a, 0) << name;
        ASSERT_GE(b, 0) << name;
        for (int y = 0; y < jpeg.height; ++y) {
            for (int x = 0; x < jpeg.width; ++x) {
                const double codes = 255.0 * std::abs(linear_to_srgb(jpeg.at(x, y, a)) -
                                                      linear_to_srgb(libjpeg.at(x, y, b)));
                largest = std::max(largest, codes);
                sum += codes;
                ++count;
            }
        }
    }
    EXPECT_LE(largest, 3.0);
    EXPECT_LE(sum / count, 0.25);
}

TEST(ImageCodecs, FormatComesFromTheBytesNotTheName) {
    TempDir dir;
    Image grey = make_image(2, 2, {"Y"});
    grey.pixels = {0.0f, 1.0f, 1.0f, 0.0f};
    write_image(dir.file("grey.png"), grey);
    std::filesystem::rename(dir.file("grey.png"), dir.file("misnamed.exr"));
    const Image back = read_image(dir.file("misnamed.exr"));
    EXPECT_EQ(back.channels, (std::vector<std::string>{"Y"}));
    EXPECT_EQ(back.pixels, grey.pixels);
}

TEST(ImageCodecs, TiffAndUnknownFilesAreRefusedWithAReason) {
    TempDir dir;
    std::ofstream(dir.file("scan.tif"), std::ios::binary) << std::string("II*\0", 4) << "rest";
    const std::string tiff = error_of(dir.file("scan.tif"));
    EXPECT_NE(tiff.find("scan.tif"), std::string::npos) << tiff;
    EXPECT_NE(tiff.find("TIFF"), std::string::npos) << tiff;

    std::ofstream(dir.file("notes.png")) << "shopping list";
    const std::string unknown = error_of(dir.file("notes.png"));
    EXPECT_NE(unknown.find("notes.png"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("not an image glint reads"), std::string::npos) << unknown;

    std::ofstream(dir.file("empty.exr")).flush();
    EXPECT_NE(error_of(dir.file("empty.exr")).find("empty"), std::string::npos);
}

}  // namespace glint
