// The colour module: Rgb (what scenes, textures and the film hold) and the opaque Spectrum a
// path carries, with uplift / to_rgb between them.
#include <glint/core/spectrum.h>
#include <glint/material/fresnel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <type_traits>

namespace glint {
namespace {

// Outside the colour module a Spectrum's values can be neither read nor written one by one,
// nor can it be made from three numbers except through uplift: so a spectral mode can
// change what it holds without touching its callers. Checked here, at compile time.
template <typename T>
concept ExposesChannels = requires(T t) {
    t.r;
}
|| requires(T t) {
    t[0];
};
static_assert(!ExposesChannels<Spectrum>);
static_assert(ExposesChannels<Rgb>);
static_assert(!std::is_constructible_v<Spectrum, float, float, float>);
static_assert(std::is_constructible_v<Rgb, float, float, float>);

Spectrum reflectance(float r, float g, float b) {
    return uplift(Rgb(r, g, b), RgbRole::reflectance);
}

TEST(Colour, UpliftAndToRgbAreInversesForEveryRole) {
    const Rgb rgb(0.25f, 0.5f, 2.0f);
    for (RgbRole role : {RgbRole::reflectance, RgbRole::illuminant, RgbRole::unbounded}) {
        EXPECT_EQ(to_rgb(uplift(rgb, role)), rgb);
    }
    EXPECT_EQ(to_rgb(Spectrum(0.75f)), Rgb(0.75f));
}

TEST(Colour, LuminanceIsRec709AndWhiteIsOne) {
    EXPECT_NEAR(Rgb(1.0f).luminance(), 1.0f, 1e-6f);
    EXPECT_NEAR(Rgb(1.0f, 0.0f, 0.0f).luminance(), 0.2126f, 1e-7f);
    EXPECT_NEAR(Rgb(0.0f, 1.0f, 0.0f).luminance(), 0.7152f, 1e-7f);
    EXPECT_NEAR(Rgb(0.0f, 0.0f, 1.0f).luminance(), 0.0722f, 1e-7f);
    const Rgb rgb(0.3f, 0.6f, 0.1f);
    EXPECT_EQ(uplift(rgb, RgbRole::unbounded).luminance(), rgb.luminance());
}

TEST(Colour, SpectrumArithmeticIsPerValue) {
    const Spectrum a = reflectance(0.5f, 0.25f, 1.0f), b = reflectance(2.0f, 4.0f, 0.0f);
    EXPECT_EQ(to_rgb(a * b), Rgb(1.0f, 1.0f, 0.0f));
    EXPECT_EQ(to_rgb(a + b), Rgb(2.5f, 4.25f, 1.0f));
    EXPECT_EQ(to_rgb(b - a), Rgb(1.5f, 3.75f, -1.0f));
    EXPECT_EQ(to_rgb(a / b), Rgb(0.25f, 0.0625f, 0.0f));  // 0 where the divisor is 0
    EXPECT_EQ(to_rgb(min(a, b)), Rgb(0.5f, 0.25f, 0.0f));
    EXPECT_EQ(to_rgb(max(a, b)), Rgb(2.0f, 4.0f, 1.0f));
    EXPECT_EQ(to_rgb(a.map([](float v) { return 2.0f * v; })), Rgb(1.0f, 0.5f, 2.0f));
    EXPECT_EQ(to_rgb(map(a, b, [](float x, float y) { return x - y; })), Rgb(-1.5f, -3.75f, 1.0f));
}

TEST(Colour, SpectrumRangeChecks) {
    const Spectrum s = reflectance(0.5f, -0.25f, 1.5f);
    EXPECT_EQ(s.min_value(), -0.25f);
    EXPECT_EQ(s.max_value(), 1.5f);
    EXPECT_FALSE(s.is_non_negative());
    EXPECT_TRUE(reflectance(0.0f, 0.5f, 1.0f).is_non_negative());
    EXPECT_EQ(to_rgb(s.clamped(0.0f, 1.0f)), Rgb(0.5f, 0.0f, 1.0f));
    EXPECT_TRUE(s.is_finite());
    EXPECT_FALSE(reflectance(0.0f, std::numeric_limits<float>::infinity(), 0.0f).is_finite());
    EXPECT_FALSE(reflectance(std::nanf(""), 0.0f, 0.0f).is_finite());
    EXPECT_TRUE(Spectrum(0.0f).is_black());
    EXPECT_FALSE(reflectance(0.0f, 0.0f, 1e-30f).is_black());
}

TEST(Colour, StoredValuesRoundTripBitForBit) {
    const Spectrum s = uplift(Rgb(0.1f, 3.0e7f, 1.0e-20f), RgbRole::unbounded);
    const auto values = s.stored();
    static_assert(values.size() == Spectrum::kStoredValues);
    EXPECT_EQ(Spectrum::from_stored(values), s);
}

// The Spectrum form of the metal Fresnel term is the scalar formula at each value.
TEST(Colour, ConductorFresnelIsTheScalarFormulaPerValue) {
    const Rgb eta(0.2f, 0.9f, 1.2f), k(3.6f, 2.6f, 2.4f);
    for (float cos_theta : {0.05f, 0.4f, 1.0f}) {
        const Rgb f = to_rgb(fresnel_conductor(cos_theta, uplift(eta, RgbRole::unbounded),
                                               uplift(k, RgbRole::unbounded)));
        for (int c = 0; c < 3; ++c) EXPECT_EQ(f[c], fresnel_conductor(cos_theta, eta[c], k[c]));
    }
}

}  // namespace
}  // namespace glint
