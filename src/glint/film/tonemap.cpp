#include <glint/film/tonemap.h>

#include <glint/core/error.h>

#include <fmt/format.h>

#include <cmath>

namespace glint {

Tonemap parse_tonemap(std::string_view name) {
    if (name == "clip") return Tonemap::clip;
    if (name == "reinhard") return Tonemap::reinhard;
    if (name == "filmic") return Tonemap::filmic;
    throw Error(fmt::format("unknown tonemap '{}' (expected: clip, reinhard, filmic)", name));
}

std::string tonemap_name(Tonemap curve) {
    switch (curve) {
        case Tonemap::reinhard:
            return "reinhard";
        case Tonemap::filmic:
            return "filmic";
        case Tonemap::clip:
            break;
    }
    return "clip";
}

double tone_curve(Tonemap curve, double x) {
    // !(x > 0) also sends NaN to black, as the PNG writer always did.
    if (!(x > 0.0)) return 0.0;
    switch (curve) {
        case Tonemap::reinhard:
            // An infinite input would give inf / inf; the curve's limit is 1.
            return std::isinf(x) ? 1.0 : x / (1.0 + x);
        case Tonemap::filmic: {
            // The rational fit's numerator and denominator are both increasing for x > 0
            // and its derivative's numerator, (ad - bc) x^2 + 2ae x + be, is positive: the
            // curve is monotone. It passes 1 near x = 7.24 (2.51 / 2.43 > 1 at infinity),
            // where the clamp takes over: highlights burn out smoothly, not at 1.
            if (std::isinf(x)) return 1.0;
            constexpr double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
            return std::min(1.0, x * (a * x + b) / (x * (c * x + d) + e));
        }
        case Tonemap::clip:
            break;
    }
    return std::min(1.0, x);
}

double tone_map_value(const ToneMapping& mapping, double linear) {
    return tone_curve(mapping.curve, linear * std::exp2(static_cast<double>(mapping.exposure)));
}

void tone_map(Image& image, const ToneMapping& mapping) {
    int channels[3];
    int count = 3;
    channels[0] = image.channel_index("R");
    channels[1] = image.channel_index("G");
    channels[2] = image.channel_index("B");
    if (channels[0] < 0 || channels[1] < 0 || channels[2] < 0) {
        if (image.num_channels() != 1)
            throw Error("tone mapping needs channels R, G and B, or a single channel");
        channels[0] = 0;
        count = 1;
    }
    const double scale = std::exp2(static_cast<double>(mapping.exposure));
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int k = 0; k < count; ++k) {
                float& value = image.at(x, y, channels[k]);
                value = static_cast<float>(
                    tone_curve(mapping.curve, static_cast<double>(value) * scale));
            }
        }
    }
}

}  // namespace glint
