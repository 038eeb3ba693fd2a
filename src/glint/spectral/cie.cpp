#include <glint/spectral/cie.h>

#include <glint/spectral/cie_data.h>

#include <cmath>

namespace glint::spectral {
namespace {

// sRGB primaries with the D65 white (IEC 61966-2-1), XYZ → linear RGB and back.
constexpr double kXyzToRgb[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                    {-0.9692660, 1.8760108, 0.0415560},
                                    {0.0556434, -0.2040259, 1.0572252}};
constexpr double kRgbToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                    {0.2126729, 0.7151522, 0.0721750},
                                    {0.0193339, 0.1191920, 0.9503041}};

}  // namespace

Xyz cie_xyz(double nm) {
    const double u = (nm - data::kCieFirstNm) / data::kStepNm;
    if (!(u >= 0.0) || u > data::kCieSamples - 1) return {};
    const int i = std::min(static_cast<int>(u), data::kCieSamples - 2);
    const double t = u - i;
    const auto& a = data::kCie1931[i];
    const auto& b = data::kCie1931[i + 1];
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

double cie_y_integral() {
    double sum = 0.0;
    for (const auto& xyz : data::kCie1931) sum += xyz[1];
    return sum * data::kStepNm;
}

Rgb xyz_to_rec709(const Xyz& c) {
    const double v[3] = {c.x, c.y, c.z};
    double out[3];
    for (int r = 0; r < 3; ++r)
        out[r] = kXyzToRgb[r][0] * v[0] + kXyzToRgb[r][1] * v[1] + kXyzToRgb[r][2] * v[2];
    return {static_cast<float>(out[0]), static_cast<float>(out[1]), static_cast<float>(out[2])};
}

Xyz rec709_to_xyz(const Rgb& c) {
    const double v[3] = {c.r, c.g, c.b};
    double out[3];
    for (int r = 0; r < 3; ++r)
        out[r] = kRgbToXyz[r][0] * v[0] + kRgbToXyz[r][1] * v[1] + kRgbToXyz[r][2] * v[2];
    return {out[0], out[1], out[2]};
}

Chromaticity chromaticity(const Xyz& c) {
    const double sum = c.x + c.y + c.z;
    if (sum == 0.0) return {};
    return {c.x / sum, c.y / sum};
}

}  // namespace glint::spectral
