#include <glint/integrator/transport/spectral_model.h>

#include <array>
#include <cmath>

namespace glint {

namespace {

// A stand-in until the spectral data module's tables land: the CIE 1931 2° observer by
// the multi-lobe Gaussian fit of Wyman, Sloan and Shirley (JCGT 2013, their eq. 2), within
// about 1 % of the tabulated functions.
double lobe(double nm, double mean, double sigma_below, double sigma_above) {
    const double t = (nm - mean) / (nm < mean ? sigma_below : sigma_above);
    return std::exp(-0.5 * t * t);
}

Rgb observer_xyz_to_rec709(double nm) {
    const double x = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                     0.065 * lobe(nm, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
    // CIE XYZ to linear Rec.709 (IEC 61966-2-1).
    return {static_cast<float>(3.2404542 * x - 1.5371385 * y - 0.4985314 * z),
            static_cast<float>(-0.9692660 * x + 1.8760108 * y + 0.0415560 * z),
            static_cast<float>(0.0556434 * x - 0.2040259 * y + 1.0572252 * z)};
}

// The white of an illuminant Rgb (1, 1, 1): a black body at D65's correlated colour
// temperature, 6504 K, normalised to 1 at 560 nm; its small tint from D65 is removed by
// the observer's normalisation below.
float white_illuminant(float nm) {
    auto planck = [](double lambda_nm) {
        const double l = lambda_nm * 1e-9;
        return 1.0 / (l * l * l * l * l * (std::exp(1.4387769e-2 / (l * 6504.0)) - 1.0));
    };
    return static_cast<float>(planck(nm) / planck(560.0));
}

// Three smooth bands that sum to 1 at every wavelength: blue below ~490 nm, red above
// ~585 nm, green between. A colour is the mix of them whose film colour under the white
// illuminant is that colour (a 3×3 solve), so the round trip is exact and white is 1.
std::array<float, 3> bands(float nm) {
    auto rise = [](float x) { return 1.0f / (1.0f + std::exp(-x)); };
    const float blue = 1.0f - rise((nm - 490.0f) / 12.0f);
    const float red = rise((nm - 585.0f) / 12.0f);
    return {red, 1.0f - red - blue, blue};
}

constexpr float kMin = 360.0f, kMax = 830.0f;

struct Calibration {
    std::array<float, 3> white;                 // ∫ W(λ) observer(λ) dλ per channel
    std::array<std::array<float, 3>, 3> solve;  // band weights from an Rgb
};

Calibration calibrate() {
    Calibration c{};
    std::array<std::array<double, 3>, 3> a{};  // a[channel][band]
    std::array<double, 3> white{};
    for (float nm = kMin; nm <= kMax; nm += 0.5f) {
        const Rgb o = observer_xyz_to_rec709(nm);
        const double w = white_illuminant(nm) * 0.5;
        const std::array<float, 3> b = bands(nm);
        for (int ch = 0; ch < 3; ++ch) {
            white[ch] += w * o[ch];
            for (int k = 0; k < 3; ++k) a[ch][k] += w * o[ch] * b[k];
        }
    }
    for (int ch = 0; ch < 3; ++ch) {
        c.white[ch] = static_cast<float>(white[ch]);
        for (int k = 0; k < 3; ++k) a[ch][k] /= white[ch];
    }
    // The inverse of a by cofactors.
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            c.solve[i][j] =
                static_cast<float>((a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det);
        }
    }
    return c;
}

const Calibration& calibration() {
    static const Calibration c = calibrate();
    return c;
}

float uplift_value(const Rgb& rgb, RgbRole role, float nm) {
    const Calibration& c = calibration();
    const std::array<float, 3> b = bands(nm);
    float value = 0.0f;
    for (int k = 0; k < 3; ++k) {
        const float weight = c.solve[k][0] * rgb.r + c.solve[k][1] * rgb.g + c.solve[k][2] * rgb.b;
        value += weight * b[k];
    }
    // Saturated colours near the gamut's edge ask for slightly negative bands.
    value = std::max(value, 0.0f);
    if (role == RgbRole::reflectance) value = std::min(value, 1.0f);
    if (role == RgbRole::illuminant) value *= white_illuminant(nm);
    return value;
}

Rgb observer(float nm) {
    const Calibration& c = calibration();
    const Rgb o = observer_xyz_to_rec709(nm);
    return {o.r / c.white[0], o.g / c.white[1], o.b / c.white[2]};
}

uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace

const SpectralModel& spectral_model() {
    static const SpectralModel model{&uplift_value, &observer};
    return model;
}

WavelengthContext path_wavelengths(uint64_t key) {
    // A salt keeps this draw apart from every other use of the same key.
    const uint64_t bits = mix(key ^ 0x5eec7a1c0ffee123ULL);
    const float u = static_cast<float>(bits >> 40) * 0x1p-24f;
    return {SampledWavelengths::sample_visible(u), &spectral_model()};
}

}  // namespace glint
