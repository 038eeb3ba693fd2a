#include <glint/core/error.h>
#include <glint/view/display.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace glint {
namespace {

// The sRGB transfer and rounding of film/image_io.cpp's PNG encoding, so that `clip`
// shows the bytes `glint render` writes.
uint8_t srgb8_direct(double v) {
    if (!(v > 0.0)) return 0;  // NaN too
    if (v >= 1.0) return 255;
    const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<uint8_t>(std::floor(encoded * 255.0 + 0.5));
}

// srgb8_direct without a pow per channel (30-50 ms for a 512 x 512 image, too slow for the
// window's frame loop). The code is monotonic in v; [0, 1) is cut into kBuckets equal
// buckets (v * kBuckets is exact: a power of two), narrower than the closest two thresholds
// where the code changes (1 / (255 * 12.92) apart near black), so a bucket holds at most one:
// the code is the bucket's first code, plus one at or past its threshold. Thresholds, the
// smallest double with each code, are found once by bisection.
class SrgbEncoder {
public:
    SrgbEncoder() {
        std::array<double, 256> threshold{};  // threshold[b]: the smallest v with code b
        for (int b = 1; b < 256; ++b) {
            double below = 0.0, at = 1.0;  // code(below) < b <= code(at)
            for (;;) {
                const double middle = below + (at - below) * 0.5;
                if (middle <= below || middle >= at) break;  // adjacent doubles
                (srgb8_direct(middle) >= b ? at : below) = middle;
            }
            threshold[b] = at;
        }
        for (int i = 0; i < kBuckets; ++i) {
            const double start = static_cast<double>(i) / kBuckets;
            const double end = static_cast<double>(i + 1) / kBuckets;
            const uint8_t code = srgb8_direct(start);
            m_base[i] = code;
            m_split[i] = code < 255 && threshold[code + 1] < end ? threshold[code + 1] : 2.0;
            if (code < 254 && threshold[code + 2] < end)
                throw Error("display encoding: two sRGB thresholds in one bucket");
        }
    }
    uint8_t operator()(double v) const {
        if (!(v > 0.0)) return 0;
        if (v >= 1.0) return 255;
        const int i = static_cast<int>(v * kBuckets);
        return static_cast<uint8_t>(m_base[i] + (v >= m_split[i] ? 1 : 0));
    }

private:
    static constexpr int kBuckets = 8192;
    std::array<uint8_t, kBuckets> m_base;
    std::array<double, kBuckets> m_split;  // the bucket's threshold, or 2 when it has none
};

}  // namespace

std::vector<uint8_t> display_pixels(const Image& image, const ToneMapping& mapping) {
    const int channel[3] = {image.channel_index("R"), image.channel_index("G"),
                            image.channel_index("B")};
    if (channel[0] < 0 || channel[1] < 0 || channel[2] < 0)
        throw Error("the viewer shows images with channels R, G and B");
    static const SrgbEncoder to_srgb8;
    const double scale = std::exp2(static_cast<double>(mapping.exposure));
    const size_t count = static_cast<size_t>(image.width) * image.height;
    const size_t stride = image.channels.size();
    std::vector<uint8_t> out(count * 4);
    const float* pixel = image.pixels.data();
    for (size_t i = 0; i < count; ++i, pixel += stride) {
        for (int c = 0; c < 3; ++c) {
            // As the PNG writer does (film/image_io.cpp): the curve of the scaled value.
            const double v =
                tone_curve(mapping.curve, static_cast<double>(pixel[channel[c]]) * scale);
            out[i * 4 + c] = to_srgb8(v);
        }
        out[i * 4 + 3] = 255;
    }
    return out;
}

Image image_from_display(const std::vector<uint8_t>& rgba, int width, int height) {
    if (rgba.size() != static_cast<size_t>(width) * height * 4)
        throw Error("display pixels do not match the image size");
    Image image = make_image(width, height, {"R", "G", "B"});
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                // The middle of the byte's interval, decoded: it encodes back to the byte.
                const double e = rgba[(static_cast<size_t>(y) * width + x) * 4 + c] / 255.0;
                image.at(x, y, c) = static_cast<float>(
                    e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4));
            }
        }
    }
    return image;
}

}  // namespace glint
