#include <glint/film/image_io.h>

#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/strings.h>
#include <glint/film/output_batch.h>

#include <glint/film/image_codecs.h>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

namespace glint {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSupported = ".exr, .png";

uint8_t to_srgb8(float linear, double scale, Tonemap curve) {
    // tone_curve sends NaN and negative values to black.
    const double v = tone_curve(curve, static_cast<double>(linear) * scale);
    if (!(v > 0.0)) return 0;
    if (v >= 1.0) return 255;
    return static_cast<uint8_t>(std::floor(linear_to_srgb(v) * 255.0 + 0.5));
}

std::vector<uint8_t> encode_png_pixels(const Image& image, const WriteOptions& options,
                                       int& channels_out) {
    int src[3];
    const int r = image.channel_index("R"), g = image.channel_index("G"),
              b = image.channel_index("B");
    if (r >= 0 && g >= 0 && b >= 0) {
        src[0] = r, src[1] = g, src[2] = b;
        channels_out = 3;
    } else if (image.num_channels() == 1) {
        src[0] = 0;
        channels_out = 1;
    } else {
        throw Error("PNG output needs channels R, G and B, or a single channel");
    }
    const double scale = std::exp2(static_cast<double>(options.exposure));
    auto encode = [&](float value) -> uint8_t {
        if (options.srgb) return to_srgb8(value, scale, options.tonemap);
        if (!(value > 0.0f)) return 0;  // NaN too
        if (value >= 1.0f) return 255;
        return static_cast<uint8_t>(std::lround(value * 255.0f));
    };
    std::vector<uint8_t> out(static_cast<std::size_t>(image.width) *
                             static_cast<std::size_t>(image.height) *
                             static_cast<std::size_t>(channels_out));
    std::size_t k = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < channels_out; ++c) out[k++] = encode(image.at(x, y, src[c]));
        }
    }
    return out;
}

// Encoders built on stdio can lose a failed write (ENOSPC, EFBIG) in a buffer they never
// check; fsync reports what the kernel could not store, and verify_written what was lost.
void sync_file(const std::string& file) {
    const int fd = ::open(file.c_str(), O_RDONLY);
    if (fd < 0) throw Error(std::strerror(errno));
    const int synced = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (synced != 0) throw Error(std::strerror(error));
}

void verify_written(const std::string& file, int width, int height) {
    StoredImage written;
    try {
        written = read_stored_image(file);
    } catch (const Error& e) {
        throw Error(fmt::format("the written file is incomplete (disk full or file too large?): {}",
                                e.what()));
    }
    if (written.image.width != width || written.image.height != height)
        throw Error("the written file does not read back at its size");
}

// The first bytes of an OpenEXR file, and of a TIFF one (either byte order).
constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr unsigned char kTiffLittle[4] = {'I', 'I', 42, 0}, kTiffBig[4] = {'M', 'M', 0, 42};

StoredImage read_by_signature(const std::string& path, uint64_t file_bytes, bool eight_bit_codes) {
    unsigned char head[4] = {0, 0, 0, 0};
    {
        std::FILE* file = std::fopen(path.c_str(), "rb");
        if (!file) throw Error(std::strerror(errno));
        const size_t got = std::fread(head, 1, sizeof head, file);
        std::fclose(file);
        if (got == 0) throw Error("the file is empty");
    }
    if (std::memcmp(head, kExrMagic, 4) == 0) return read_exr(path, file_bytes);
    if (head[0] == 'P' && (head[1] == 'F' || head[1] == 'f') && std::isspace(head[2]))
        return read_pfm(path, file_bytes);
    if (std::memcmp(head, kTiffLittle, 4) == 0 || std::memcmp(head, kTiffBig, 4) == 0)
        throw Error("TIFF files are not read; convert it to OpenEXR or PNG");
    return read_stb(path, file_bytes, eight_bit_codes);
}

}  // namespace

double linear_to_srgb(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

float srgb_to_linear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

void write_image(const std::string& path, const Image& image, const WriteOptions& options) {
    OutputBatch batch;
    batch.add(path, image, options);
    batch.commit();
}

void write_image_file(const std::string& file, const Image& image, const WriteOptions& options) {
    const std::string ext = lower_extension(file);
    if (ext != ".exr" && ext != ".png")
        throw Error(fmt::format("unsupported extension '{}'; supported: {}", ext, kSupported));
    if (image.width <= 0 || image.height <= 0 || image.channels.empty() ||
        image.pixels.size() != image.index(0, image.height, 0)) {
        throw Error(fmt::format("image is empty or its pixel buffer does not match {}x{}x{}",
                                image.width, image.height, image.channels.size()));
    }
    if (ext == ".exr") {
        write_exr(file, image, options.half);
    } else {
        int channels = 0;
        const std::vector<uint8_t> codes = encode_png_pixels(image, options, channels);
        write_png(file, image.width, image.height, channels, codes);
    }
    sync_file(file);
    verify_written(file, image.width, image.height);
}

StoredImage read_stored_image(const std::string& path, bool eight_bit_codes) {
    std::error_code ec;
    const uintmax_t file_bytes = fs::file_size(path, ec);
    if (ec) throw Error(fmt::format("cannot read '{}': {}", path, ec.message()));
    try {
        return read_by_signature(path, file_bytes, eight_bit_codes);
    } catch (const Error& e) {
        // A decoder's reason may quote bytes of the damaged file.
        const std::string message = printable_text(e.what());
        // check_image_header's messages, and OpenEXR's, name the image already.
        if (message.find(path) != std::string::npos) throw Error(message);
        throw Error(fmt::format("cannot read '{}': {}", path, message));
    }
}

Image read_image(const std::string& path) {
    StoredImage stored = read_stored_image(path);
    if (stored.integer) {
        Image& image = stored.image;
        const size_t channels = image.channels.size();
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            if (static_cast<int>(i % channels) == stored.alpha) continue;
            image.pixels[i] = srgb_to_linear(image.pixels[i]);
        }
    }
    return std::move(stored.image);
}

CompareResult compare_images(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height) {
        throw Error(fmt::format("cannot compare a {}x{} image with a {}x{} reference", test.width,
                                test.height, reference.width, reference.height));
    }
    int tc[3], rc[3];
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        tc[c] = test.channel_index(names[c]);
        rc[c] = reference.channel_index(names[c]);
        if (tc[c] < 0 || rc[c] < 0) {
            throw Error(fmt::format("cannot compare images: channel {} missing from the {}",
                                    names[c], tc[c] < 0 ? "test image" : "reference"));
        }
    }
    CompareResult result{0.0, 0.0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0};
    double sq_sum = 0.0;
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double t = test.at(x, y, tc[c]);
                const double r = reference.at(x, y, rc[c]);
                if (!std::isfinite(t) || !std::isfinite(r)) ++result.non_finite;
                const double d2 = (t - r) * (t - r);
                // The 1e-2 keeps near-black reference pixels from dominating the mean.
                result.rel_mse += d2 / (r * r + 1e-2);
                sq_sum += d2;
                result.test_mean[c] += t;
                result.ref_mean[c] += r;
            }
        }
    }
    const double pixels = static_cast<double>(test.width) * static_cast<double>(test.height);
    if (pixels > 0.0) {
        result.rel_mse /= 3.0 * pixels;
        result.rmse = std::sqrt(sq_sum / (3.0 * pixels));
        for (int c = 0; c < 3; ++c) {
            result.test_mean[c] /= pixels;
            result.ref_mean[c] /= pixels;
        }
    }
    // NaN already propagates through the sums; an infinity against an infinity would not.
    if (result.non_finite > 0) result.rel_mse = result.rmse = std::nan("");
    return result;
}

}  // namespace glint
