// CIE tables, standard illuminants and the blackbody, against published chromaticities.
#include <glint/spectral/blackbody.h>
#include <glint/spectral/cie.h>
#include <glint/spectral/illuminants.h>
#include <glint/spectral/spectrum_to_rgb.h>
#include <glint/spectral/tabulated_spectrum.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace glint::spectral {
namespace {

Xyz integrate_xyz(const std::function<double(double)>& f) {
    Xyz sum;
    for (double nm = 360.0; nm <= 830.0; nm += 1.0) {
        const Xyz cmf = cie_xyz(nm);
        sum.x += f(nm) * cmf.x;
        sum.y += f(nm) * cmf.y;
        sum.z += f(nm) * cmf.z;
    }
    return sum;
}

Chromaticity of_illuminant(const char* name) {
    const TabulatedSpectrum* s = named_illuminant(name);
    return chromaticity(integrate_xyz([s](double nm) { return s->eval(float(nm)); }));
}

Chromaticity of_blackbody(double kelvin) {
    return chromaticity(integrate_xyz([kelvin](double nm) { return blackbody(nm, kelvin); }));
}

// CIE 1960 (u, v), where correlated colour temperature is measured.
std::pair<double, double> uv(const Chromaticity& c) {
    const double d = -2.0 * c.x + 12.0 * c.y + 3.0;
    return {4.0 * c.x / d, 6.0 * c.y / d};
}

TEST(SpectralCie, TheObserverIsTheStandardOne) {
    EXPECT_NEAR(cie_y_integral(), 106.857, 0.01);  // ∫ȳ dλ of the 5 nm table
    EXPECT_DOUBLE_EQ(cie_xyz(555.0).y, 1.0);
    EXPECT_NEAR(cie_xyz(557.5).x, 0.5 * (0.5120501 + 0.5945), 1e-7);  // linear between entries
    EXPECT_EQ(cie_xyz(200.0).y, 0.0);
    EXPECT_EQ(cie_xyz(900.0).x, 0.0);
}

TEST(SpectralCie, Rec709MatricesAreInverse) {
    const Rgb rgb(0.3f, 0.6f, 0.9f);
    const Rgb back = xyz_to_rec709(rec709_to_xyz(rgb));
    EXPECT_NEAR(back.r, rgb.r, 1e-6);
    EXPECT_NEAR(back.g, rgb.g, 1e-6);
    EXPECT_NEAR(back.b, rgb.b, 1e-6);
}

// Published white points (CIE 015:2018, 2° observer).
TEST(SpectralIlluminants, WhitePointsMatchTheStandard) {
    struct Expected {
        const char* name;
        double x, y;
    };
    for (const Expected& e : {Expected{"D65", 0.31272, 0.32903}, Expected{"A", 0.44758, 0.40745},
                              Expected{"F2", 0.37208, 0.37529}, Expected{"F7", 0.31292, 0.32933},
                              Expected{"F11", 0.38052, 0.37713}}) {
        const Chromaticity c = of_illuminant(e.name);
        EXPECT_NEAR(c.x, e.x, 5e-4) << e.name;
        EXPECT_NEAR(c.y, e.y, 5e-4) << e.name;
    }
}

TEST(SpectralIlluminants, HaveUnitLuminanceAndNamesAreCaseInsensitive) {
    for (const std::string& name : illuminant_names()) {
        const TabulatedSpectrum* s = named_illuminant(name);
        ASSERT_NE(s, nullptr) << name;
        EXPECT_NEAR(emission_to_rgb([s](double nm) { return s->eval(float(nm)); }).luminance(), 1.0,
                    2e-3)
            << name;
    }
    EXPECT_EQ(named_illuminant("d65"), named_illuminant("D65"));
    EXPECT_EQ(named_illuminant("D66"), nullptr);
    EXPECT_EQ(illuminant_names().size(), 14u);
}

TEST(SpectralBlackbody, FollowsPlanckAndWien) {
    // Planck's law at 5000 K, 500 nm: 1.2107e13 W·sr⁻¹·m⁻³ = 1.2107e4 per nm.
    EXPECT_NEAR(blackbody(500.0, 5000.0) / 1.2107e4, 1.0, 1e-3);
    EXPECT_NEAR(blackbody_normalized(2.897771955e6 / 5000.0, 5000.0), 1.0, 1e-12);
    for (double nm = 300.0; nm < 1000.0; nm += 7.0)
        EXPECT_LE(blackbody_normalized(nm, 5000.0), 1.0);
    EXPECT_EQ(blackbody(500.0, 0.0), 0.0);
    EXPECT_EQ(blackbody(500.0, -10.0), 0.0);
}

// The Planckian locus at known temperatures (CIE 015:2018, Table of Planckian chromaticities).
TEST(SpectralBlackbody, LiesOnThePlanckianLocus) {
    struct Point {
        double kelvin, x, y;
    };
    for (const Point& p : {Point{2856.0, 0.44757, 0.40745}, Point{6504.0, 0.31352, 0.32363},
                           Point{4000.0, 0.38045, 0.37676}}) {
        const Chromaticity c = of_blackbody(p.kelvin);
        EXPECT_NEAR(c.x, p.x, 1e-3) << p.kelvin;
        EXPECT_NEAR(c.y, p.y, 1e-3) << p.kelvin;
    }
}

// D65's correlated colour temperature is 6504 K: the point of the blackbody locus nearest to
// D65's white in CIE 1960 uv is 6504 K's. (D65 itself lies Δuv ≈ 0.0032 off the locus, so the
// 6504 K blackbody's xy differs from D65's by ≈ 0.005 in y: a fact of the standard.)
TEST(SpectralBlackbody, D65sCorrelatedColourTemperatureIs6504K) {
    const auto [u65, v65] = uv(of_illuminant("D65"));
    double best_kelvin = 0.0, best_distance = 1e9;
    for (double kelvin = 6000.0; kelvin <= 7000.0; kelvin += 1.0) {
        const auto [u, v] = uv(of_blackbody(kelvin));
        const double distance = std::hypot(u - u65, v - v65);
        if (distance < best_distance) {
            best_distance = distance;
            best_kelvin = kelvin;
        }
    }
    EXPECT_NEAR(best_kelvin, 6504.0, 15.0);
    EXPECT_NEAR(best_distance, 0.0032, 3e-4);
}

TEST(SpectralTabulated, InterpolatesAndIsZeroOutside) {
    const TabulatedSpectrum s({{400.0f, 1.0f}, {500.0f, 3.0f}, {600.0f, 2.0f}});
    EXPECT_FLOAT_EQ(s.eval(450.0f), 2.0f);
    EXPECT_FLOAT_EQ(s.eval(550.0f), 2.5f);
    EXPECT_FLOAT_EQ(s.eval(400.0f), 1.0f);
    EXPECT_FLOAT_EQ(s.eval(600.0f), 2.0f);
    EXPECT_EQ(s.eval(399.0f), 0.0f);
    EXPECT_EQ(s.eval(601.0f), 0.0f);
}

TEST(SpectralTabulated, RejectsBadTables) {
    EXPECT_TRUE(TabulatedSpectrum::check({}).has_value());
    EXPECT_TRUE(TabulatedSpectrum::check({{500.0f, 1.0f}, {450.0f, 1.0f}}).has_value());
    EXPECT_TRUE(TabulatedSpectrum::check({{500.0f, 1.0f}}).has_value());
    EXPECT_TRUE(TabulatedSpectrum::check({{400.0f, 1.0f}, {500.0f, -1.0f}}).has_value());
    EXPECT_TRUE(TabulatedSpectrum::check({{-5.0f, 1.0f}, {500.0f, 1.0f}}).has_value());
    EXPECT_TRUE(TabulatedSpectrum::check({{400.0f, 1.0f}, {500.0f, NAN}}).has_value());
    EXPECT_FALSE(TabulatedSpectrum::check({{400.0f, 1.0f}, {500.0f, 1.0f}}).has_value());
    EXPECT_THROW(TabulatedSpectrum({{500.0f, 1.0f}, {500.0f, 2.0f}}), std::invalid_argument);
}

}  // namespace
}  // namespace glint::spectral
