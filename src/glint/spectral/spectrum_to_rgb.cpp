#include <glint/spectral/spectrum_to_rgb.h>

#include <glint/spectral/cie.h>
#include <glint/spectral/cie_data.h>

namespace glint::spectral {
namespace {

double sample_nm(size_t i) {
    return data::kCieFirstNm + data::kStepNm * static_cast<double>(i);
}

// Rec.709 of ∫ f · w · x̄ȳz̄ dλ at the table's wavelengths (a 5 nm Riemann sum, which the
// uplift's fit uses too, so that its round trip is exact up to the fit).
Rgb weighted_rgb(const std::function<double(double)>& f, const std::array<double, 95>& weight) {
    Xyz sum;
    for (size_t i = 0; i < data::kCieSamples; ++i) {
        const double value = f(sample_nm(i)) * weight[i];
        const auto& cmf = data::kCie1931[i];
        sum.x += value * cmf[0];
        sum.y += value * cmf[1];
        sum.z += value * cmf[2];
    }
    return xyz_to_rec709(sum);
}

std::array<double, 95> uniform_weight() {
    std::array<double, 95> w{};
    w.fill(1.0 / (cie_y_integral() / data::kStepNm));
    return w;
}

}  // namespace

Rgb emission_to_rgb(const std::function<double(double)>& f) {
    static const std::array<double, 95> weight = uniform_weight();
    return weighted_rgb(f, weight);
}

const ReflectanceWeights& reflectance_weights() {
    static const ReflectanceWeights weights = [] {
        ReflectanceWeights w{};
        std::array<double, 95> d65{};
        for (size_t i = 0; i < d65.size(); ++i) d65[i] = data::kD65[i];
        const Rgb white = weighted_rgb([](double) { return 1.0; }, d65);
        for (size_t i = 0; i < data::kCieSamples; ++i) {
            const auto& cmf = data::kCie1931[i];
            const Rgb rgb = xyz_to_rec709({cmf[0] * d65[i], cmf[1] * d65[i], cmf[2] * d65[i]});
            w.per_sample[i] = {rgb.r / white.r, rgb.g / white.g, rgb.b / white.b};
        }
        return w;
    }();
    return weights;
}

Rgb quantity_to_rgb(const std::function<double(double)>& f) {
    const ReflectanceWeights& w = reflectance_weights();
    double rgb[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < w.per_sample.size(); ++i) {
        const double value = f(w.wavelength(i));
        for (int c = 0; c < 3; ++c) rgb[c] += value * w.per_sample[i][c];
    }
    return {static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2])};
}

}  // namespace glint::spectral
