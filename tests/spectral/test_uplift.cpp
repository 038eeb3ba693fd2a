// The RGB uplift (Jakob & Hanika 2019 with glint's own fitted table): colours survive the
// trip to a spectrum and back, and reflectances stay physical.
#include <glint/core/rng.h>
#include <glint/spectral/cie.h>
#include <glint/spectral/rgb_uplift.h>
#include <glint/spectral/sigmoid_fit.h>
#include <glint/spectral/spectrum_to_rgb.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace glint::spectral {
namespace {

float largest_difference(const Rgb& a, const Rgb& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// A regular grid over the sRGB cube plus random colours (fixed seed): the sampled gamut.
std::vector<Rgb> sampled_gamut() {
    std::vector<Rgb> colours;
    constexpr int kSteps = 11;
    for (int r = 0; r < kSteps; ++r)
        for (int g = 0; g < kSteps; ++g)
            for (int b = 0; b < kSteps; ++b)
                colours.emplace_back(r / float(kSteps - 1), g / float(kSteps - 1),
                                     b / float(kSteps - 1));
    Rng rng(2019);
    for (int i = 0; i < 3000; ++i)
        colours.emplace_back(rng.next_float(), rng.next_float(), rng.next_float());
    return colours;
}

TEST(SpectralUplift, ReflectanceRoundTripsOverTheSrgbGamut) {
    float worst = 0.0f;
    Rgb worst_colour;
    for (const Rgb& rgb : sampled_gamut()) {
        const SigmoidPolynomial s = uplift_coefficients(rgb);
        const Rgb back = quantity_to_rgb([&](double nm) { return s.eval(float(nm)); });
        if (largest_difference(rgb, back) > worst) {
            worst = largest_difference(rgb, back);
            worst_colour = rgb;
        }
    }
    EXPECT_LT(worst, 1e-3f) << "worst at (" << worst_colour.r << ", " << worst_colour.g << ", "
                            << worst_colour.b << ")";
}

TEST(SpectralUplift, ReflectancesStayAtMostOneAtEveryWavelength) {
    for (const Rgb& rgb : {Rgb(1.0f), Rgb(1.0f, 1.0f, 0.999f), Rgb(0.0f, 1.0f, 1.0f),
                           Rgb(1.0f, 0.0f, 0.0f), Rgb(2.0f, 3.0f, 0.5f)}) {
        for (float nm = kLambdaMin; nm <= kLambdaMax; nm += 0.25f) {
            const float v = uplifted_rgb(rgb, RgbRole::reflectance, nm);
            ASSERT_LE(v, 1.0f) << nm << " nm";
            ASSERT_GE(v, 0.0f) << nm << " nm";
        }
    }
    EXPECT_EQ(uplifted_rgb(Rgb(1.0f), RgbRole::reflectance, 550.0f), 1.0f);
    EXPECT_EQ(uplifted_rgb(Rgb(0.0f), RgbRole::reflectance, 550.0f), 0.0f);
}

TEST(SpectralUplift, TheFitReachesTheGamutCorners) {
    for (const auto& target : {std::array<double, 3>{1, 0, 0}, std::array<double, 3>{0, 1, 0},
                               std::array<double, 3>{0, 0, 1}, std::array<double, 3>{1, 1, 0},
                               std::array<double, 3>{0.2, 0.5, 0.9}}) {
        const SigmoidFit fit = fit_sigmoid_polynomial(target, {0.0, 0.0, 0.0});
        EXPECT_LT(fit.residual, 1e-6) << target[0] << " " << target[1] << " " << target[2];
    }
}

TEST(SpectralUplift, UnboundedValuesRoundTrip) {
    for (const Rgb& rgb : {Rgb(2.5f, 1.0f, 0.1f), Rgb(0.05f, 0.3f, 4.0f), Rgb(7.0f)}) {
        const Rgb back = quantity_to_rgb(
            [&](double nm) { return uplifted_rgb(rgb, RgbRole::unbounded, float(nm)); });
        EXPECT_LT(largest_difference(rgb, back) / rgb.max_value(), 1e-3f);
    }
}

// An RGB emitter's spectrum is the uplifted colour times D65: its colour is the Rgb up to the
// difference between the tabulated D65's white and sRGB's stated white point (≈ 1e-3).
TEST(SpectralUplift, IlluminantsKeepTheirColour) {
    for (const Rgb& rgb : {Rgb(1.0f), Rgb(3.0f, 2.0f, 1.0f), Rgb(0.2f, 0.4f, 0.9f)}) {
        const Rgb back = emission_to_rgb(
            [&](double nm) { return uplifted_rgb(rgb, RgbRole::illuminant, float(nm)); });
        EXPECT_LT(largest_difference(rgb, back) / rgb.max_value(), 3e-3f);
    }
}

}  // namespace
}  // namespace glint::spectral
