#include <glint/spectral/rgb_uplift.h>

#include <glint/spectral/illuminants.h>
#include <glint/spectral/rgb_uplift_table.h>
#include <glint/spectral/sigmoid_fit.h>

#include <algorithm>
#include <cmath>

namespace glint::spectral {
namespace {

constexpr int kN = data::kUpliftResolution;
constexpr int kPolishSteps = 10;
constexpr double kPolishTolerance = 1e-5;

const std::array<float, 3>& table_entry(int l, int zi, int yi, int xi) {
    return data::kUpliftCoefficients[static_cast<size_t>(((l * kN + zi) * kN + yi) * kN + xi)];
}

// The constant spectrum v as a sigmoid polynomial: S(c2) = v.
SigmoidPolynomial constant_spectrum(float v) {
    if (v <= 0.0f) return {0.0f, 0.0f, -INFINITY};
    if (v >= 1.0f) return {0.0f, 0.0f, INFINITY};
    return {0.0f, 0.0f, (v - 0.5f) / std::sqrt(v * (1.0f - v))};
}

// D65 scaled to luminance 1: the shape an RGB emitter's spectrum takes.
float d65(float nm) {
    static const TabulatedSpectrum* const table = named_illuminant("D65");
    return table->eval(nm);
}

}  // namespace

float SigmoidPolynomial::eval(float nm) const {
    const float x = (m_c[0] * nm + m_c[1]) * nm + m_c[2];
    if (std::isinf(x)) return x > 0.0f ? 1.0f : 0.0f;
    return 0.5f + x / (2.0f * std::sqrt(1.0f + x * x));
}

SigmoidPolynomial uplift_coefficients(const Rgb& colour) {
    const Rgb rgb = colour.clamped(0.0f, 1.0f);
    if (rgb.r == rgb.g && rgb.g == rgb.b) return constant_spectrum(rgb.r);

    const int l = rgb.r >= rgb.g ? (rgb.r >= rgb.b ? 0 : 2) : (rgb.g >= rgb.b ? 1 : 2);
    const float z = rgb[l];
    const float x = rgb[(l + 1) % 3] / z * (kN - 1);
    const float y = rgb[(l + 2) % 3] / z * (kN - 1);

    const auto& zs = data::kUpliftZ;
    const int zi = std::clamp(
        static_cast<int>(std::upper_bound(zs.begin(), zs.end(), z) - zs.begin()) - 1, 0, kN - 2);
    const int xi = std::min(static_cast<int>(x), kN - 2);
    const int yi = std::min(static_cast<int>(y), kN - 2);
    const float dz = (z - zs[zi]) / (zs[zi + 1] - zs[zi]);
    const float dx = x - xi, dy = y - yi;

    std::array<float, 3> c{};
    for (int k = 0; k < 3; ++k) {
        const auto lerp = [](float a, float b, float t) { return a + t * (b - a); };
        const auto at = [&](int dzi, int dyi, int dxi) {
            return table_entry(l, zi + dzi, yi + dyi, xi + dxi)[static_cast<size_t>(k)];
        };
        c[static_cast<size_t>(k)] = lerp(
            lerp(lerp(at(0, 0, 0), at(0, 0, 1), dx), lerp(at(0, 1, 0), at(0, 1, 1), dx), dy),
            lerp(lerp(at(1, 0, 0), at(1, 0, 1), dx), lerp(at(1, 1, 0), at(1, 1, 1), dx), dy), dz);
    }
    // Trilinear interpolation of the coefficients misses the colour by up to ~1e-2 where they
    // change fast (near white and the gamut's edges); Gauss–Newton steps from there bring it
    // under 1e-5 (none where the table already is that close).
    const auto polished = fit_sigmoid_polynomial({rgb.r, rgb.g, rgb.b}, {c[0], c[1], c[2]},
                                                 kPolishTolerance, kPolishSteps);
    const auto nm = to_nm_coefficients(polished.coefficients);
    return {static_cast<float>(nm[0]), static_cast<float>(nm[1]), static_cast<float>(nm[2])};
}

float uplifted_rgb(const Rgb& rgb, RgbRole role, float nm) {
    if (role == RgbRole::reflectance) return uplift_coefficients(rgb).eval(nm);
    // Unbounded: a scale times a spectrum in [0, 1] whose brightest channel is ½, the middle of
    // the table, where the fit has the most freedom.
    const float scale = 2.0f * std::max(rgb.max_value(), 0.0f);
    if (scale == 0.0f) return 0.0f;
    const float value = scale * uplift_coefficients(rgb / scale).eval(nm);
    return role == RgbRole::illuminant ? value * d65(nm) : value;
}

}  // namespace glint::spectral
