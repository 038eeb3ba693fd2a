#include <glint/denoise/transfer.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// The PU fit: a * y below y0, b * y^c + d up to y1, e * ln(y + f) + g above; x0 and x1 are
// the curve's values at y0 and y1.
constexpr float pu_a = 1.41283765e+03f;
constexpr float pu_b = 1.64593172e+00f;
constexpr float pu_c = 4.31384981e-01f;
constexpr float pu_d = -2.94139609e-03f;
constexpr float pu_e = 1.92653254e-01f;
constexpr float pu_f = 6.26026094e-03f;
constexpr float pu_g = 9.98620152e-01f;
constexpr float pu_y0 = 1.57945760e-06f;
constexpr float pu_y1 = 3.22087631e-02f;
constexpr float pu_x0 = 2.23151711e-03f;
constexpr float pu_x1 = 3.70974749e-01f;
constexpr float largest_half = 65504.f;

float pu_raw(float y) {
    if (y <= pu_y0) return pu_a * y;
    if (y <= pu_y1) return pu_b * std::pow(y, pu_c) + pu_d;
    return pu_e * std::log(y + pu_f) + pu_g;
}

float pu_raw_inverse(float x) {
    if (x <= pu_x0) return x / pu_a;
    if (x <= pu_x1) return std::pow((x - pu_d) / pu_b, 1.f / pu_c);
    return std::exp((x - pu_g) / pu_e) - pu_f;
}

const float pu_norm = pu_raw(largest_half);

float luminance(float r, float g, float b) {
    return 0.212671f * r + 0.715160f * g + 0.072169f * b;
}

float sanitized(float v) {
    return std::isfinite(v) ? std::max(v, 0.f) : 0.f;
}

}  // namespace

float pu_forward(float y) {
    return pu_raw(y) / pu_norm;
}
float pu_inverse(float x) {
    return pu_raw_inverse(x * pu_norm);
}

float srgb_forward(float y) {
    return y <= 0.0031308f ? 12.92f * y : 1.055f * std::pow(y, 1.f / 2.4f) - 0.055f;
}

float autoexposure(const Image& image) {
    constexpr int max_bin = 16;
    constexpr float key = 0.18f, darkest = 1e-8f;
    const int bins_y = (image.height + max_bin - 1) / max_bin;
    const int bins_x = (image.width + max_bin - 1) / max_bin;
    double log_sum = 0.0;
    long count = 0;
    for (int by = 0; by < bins_y; ++by) {
        const int y0 = by * image.height / bins_y, y1 = (by + 1) * image.height / bins_y;
        for (int bx = 0; bx < bins_x; ++bx) {
            const int x0 = bx * image.width / bins_x, x1 = (bx + 1) * image.width / bins_x;
            double sum = 0.0;
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x)
                    sum += luminance(sanitized(image.at(x, y, 0)), sanitized(image.at(x, y, 1)),
                                     sanitized(image.at(x, y, 2)));
            const double mean = sum / static_cast<double>((y1 - y0) * (x1 - x0));
            if (mean > darkest) {
                log_sum += std::log2(mean);
                ++count;
            }
        }
    }
    if (count == 0) return 1.f;
    return static_cast<float>(key / std::exp2(log_sum / static_cast<double>(count)));
}

}  // namespace glint
