#include <glint/film/image_io.h>

#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/strings.h>
#include <glint/film/output_batch.h>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

namespace glint {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSupported = ".exr, .png";

double srgb_encode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

uint8_t to_srgb8(float linear, double scale, Tonemap curve) {
    // tone_curve sends NaN and negative values to black.
    const double v = tone_curve(curve, static_cast<double>(linear) * scale);
    if (!(v > 0.0)) return 0;
    if (v >= 1.0) return 255;
    return static_cast<uint8_t>(std::floor(srgb_encode(v) * 255.0 + 0.5));
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
    std::vector<uint8_t> out(static_cast<std::size_t>(image.width) *
                             static_cast<std::size_t>(image.height) *
                             static_cast<std::size_t>(channels_out));
    std::size_t k = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < channels_out; ++c)
                out[k++] = to_srgb8(image.at(x, y, src[c]), scale, options.tonemap);
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
    auto in = OIIO::ImageInput::open(file);
    if (!in) throw Error(fmt::format("the written file does not read back ({})", OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<unsigned char> pixels(spec.image_bytes(/*native=*/true));
    const bool ok = spec.width == width && spec.height == height &&
                    in->read_image(0, 0, 0, spec.nchannels, spec.format, pixels.data());
    const std::string reason = in->geterror();
    in->close();
    if (!ok) {
        throw Error(fmt::format("the written file is incomplete (disk full or file too large?){}",
                                reason.empty() ? "" : ": " + reason));
    }
}

void write_with_oiio(const fs::path& file, const OIIO::ImageSpec& spec, const void* data) {
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out) throw Error(OIIO::geterror());
    if (!out->open(file.string(), spec)) throw Error(out->geterror());
    if (!out->write_image(spec.format, data)) {
        const std::string message = out->geterror();
        out->close();
        throw Error(message);
    }
    if (!out->close()) throw Error(out->geterror());
}

}  // namespace

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
        OIIO::ImageSpec spec(image.width, image.height, image.num_channels(),
                             OIIO::TypeDesc::FLOAT);
        spec.channelnames = image.channels;
        spec.alpha_channel = image.channel_index("A");
        spec.attribute("compression", "zip");
        // OpenEXR stamps files with the current time (capDate) unless told otherwise; a
        // fixed stamp keeps a render's file identical bit for bit, run after run.
        spec.attribute("DateTime", "1970:01:01 00:00:00");
        for (const auto& [name, value] : image.attributes) spec.attribute("glint:" + name, value);
        write_with_oiio(file, spec, image.pixels.data());
    } else {
        int channels = 0;
        const std::vector<uint8_t> bytes = encode_png_pixels(image, options, channels);
        OIIO::ImageSpec spec(image.width, image.height, channels, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", "sRGB");
        write_with_oiio(file, spec, bytes.data());
    }
    sync_file(file);
    verify_written(file, image.width, image.height);
}

Image read_image(const std::string& path) {
    std::error_code ec;
    const uintmax_t file_bytes = fs::file_size(path, ec);
    if (ec) throw Error(fmt::format("cannot read '{}': {}", path, ec.message()));
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw Error(fmt::format("cannot read '{}': {}", path, OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    check_image_header(path, spec.width, spec.height, spec.nchannels, spec.format.size(),
                       file_bytes);
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.channelnames;
    image.channels.resize(static_cast<std::size_t>(spec.nchannels));
    for (int c = 0; c < spec.nchannels; ++c) {
        if (image.channels[c].empty()) image.channels[c] = fmt::format("channel{}", c);
    }
    image.pixels.resize(static_cast<std::size_t>(spec.width) *
                        static_cast<std::size_t>(spec.height) *
                        static_cast<std::size_t>(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
        throw Error(fmt::format("cannot read '{}': {}", path, in->geterror()));
    }
    const bool is_float = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                          spec.format.basetype == OIIO::TypeDesc::HALF ||
                          spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    const std::string colorspace = spec.get_string_attribute("oiio:ColorSpace");
    if (!is_float && OIIO::Strutil::iequals(colorspace, "sRGB")) {
        const int alpha = spec.alpha_channel;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            if (static_cast<int>(i % static_cast<std::size_t>(spec.nchannels)) == alpha) continue;
            image.pixels[i] = srgb_decode(image.pixels[i]);
        }
    }
    for (const OIIO::ParamValue& param : spec.extra_attribs) {
        const std::string name = param.name().string();
        if (name.rfind("glint:", 0) == 0 && param.type() == OIIO::TypeDesc::STRING)
            image.attributes.emplace_back(name.substr(6), param.get_string());
    }
    in->close();
    return image;
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
