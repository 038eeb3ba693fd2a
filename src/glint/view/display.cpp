#include <glint/core/error.h>
#include <glint/view/display.h>

#include <fmt/format.h>

#include <cmath>

namespace glint {
namespace {

// The sRGB transfer and rounding of film/image_io.cpp's PNG encoding, so that `clip`
// shows the bytes `glint render` writes.
uint8_t to_srgb8(double v) {
    if (!(v > 0.0)) return 0;  // NaN too
    if (v >= 1.0) return 255;
    const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<uint8_t>(std::floor(encoded * 255.0 + 0.5));
}

}  // namespace

DisplayToneMap parse_display_tone_map(const std::string& name) {
    if (name == "clip") return DisplayToneMap::clip;
    if (name == "reinhard") return DisplayToneMap::reinhard;
    throw Error(fmt::format("unknown tone mapping '{}' (expected: clip, reinhard)", name));
}

std::vector<uint8_t> display_pixels(const Image& image, float exposure, DisplayToneMap tone_map) {
    const int channel[3] = {image.channel_index("R"), image.channel_index("G"),
                            image.channel_index("B")};
    if (channel[0] < 0 || channel[1] < 0 || channel[2] < 0)
        throw Error("the viewer shows images with channels R, G and B");
    const double scale = std::exp2(static_cast<double>(exposure));
    std::vector<uint8_t> out(static_cast<size_t>(image.width) * image.height * 4);
    size_t k = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                double v = static_cast<double>(image.at(x, y, channel[c])) * scale;
                if (tone_map == DisplayToneMap::reinhard && v > 0.0) v = v / (1.0 + v);
                out[k++] = to_srgb8(v);
            }
            out[k++] = 255;
        }
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
