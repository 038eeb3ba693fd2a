// Measured conductors and dispersive dielectrics: their data, and what RGB mode makes of it.
#include <glint/spectral/conductors.h>
#include <glint/spectral/dispersion.h>
#include <glint/spectral/spectrum_to_rgb.h>

#include <gtest/gtest.h>

#include <cmath>

namespace glint::spectral {
namespace {

// Normal-incidence reflectance of a metal with complex index η + ik, from air.
double normal_reflectance(ComplexIor n) {
    const double a = n.eta - 1.0, b = n.eta + 1.0, k2 = double(n.k) * n.k;
    return (a * a + k2) / (b * b + k2);
}

Rgb reflectance_colour(const char* metal) {
    const ConductorData* c = named_conductor(metal);
    return quantity_to_rgb([c](double nm) { return normal_reflectance(c->eval(float(nm))); });
}

TEST(SpectralConductors, GoldIsYellowSilverIsWhite) {
    const Rgb gold = reflectance_colour("Au");
    EXPECT_GT(gold.r, 0.85f);
    EXPECT_GT(gold.r, gold.g);
    EXPECT_GT(gold.g, gold.b);
    EXPECT_LT(gold.b, 0.5f * gold.r);

    const Rgb silver = reflectance_colour("Ag");
    EXPECT_GT(silver.min_value(), 0.85f);
    EXPECT_GT(silver.min_value() / silver.max_value(), 0.9f);

    const Rgb copper = reflectance_colour("Cu");
    EXPECT_GT(copper.r, copper.g);
    EXPECT_GT(copper.g, copper.b);
    EXPECT_LT(copper.g, 0.8f * copper.r);

    const Rgb aluminium = reflectance_colour("Al");
    EXPECT_GT(aluminium.min_value(), 0.85f);
}

// RGB mode's η and k: gold's η is small in red and large in blue, its k the reverse.
TEST(SpectralConductors, RgbEtaAndKAreSane) {
    const ConductorData* gold = named_conductor("gold");
    ASSERT_NE(gold, nullptr);
    const Rgb eta = quantity_to_rgb([gold](double nm) { return gold->eval(float(nm)).eta; });
    const Rgb k = quantity_to_rgb([gold](double nm) { return gold->eval(float(nm)).k; });
    EXPECT_LT(eta.r, 0.4f);
    EXPECT_GT(eta.b, 1.0f);
    EXPECT_GT(k.r, 3.0f);
    EXPECT_LT(k.b, k.r);
}

TEST(SpectralConductors, NamesAndInterpolation) {
    EXPECT_EQ(named_conductor("AU"), named_conductor("gold"));
    EXPECT_EQ(named_conductor("aluminum"), named_conductor("Al"));
    EXPECT_EQ(named_conductor("unobtainium"), nullptr);
    EXPECT_GE(conductor_names().size(), 4u);
    // Johnson & Christy's gold at 0.5486 and 0.5821 µm: halfway between is halfway in η and k.
    const ComplexIor mid = named_conductor("Au")->eval(0.5f * (548.6f + 582.1f));
    EXPECT_NEAR(mid.eta, 0.5 * (0.43 + 0.29), 1e-5);
    EXPECT_NEAR(mid.k, 0.5 * (2.455 + 2.863), 1e-5);
}

TEST(SpectralDispersion, PresetsHaveTheirCatalogueIndices) {
    EXPECT_NEAR(named_dielectric("BK7")->reference(), 1.5168, 5e-5);
    EXPECT_NEAR(named_dielectric("BK7")->abbe_number(), 64.17, 0.05);
    EXPECT_NEAR(named_dielectric("fused silica")->reference(), 1.4585, 5e-5);
    EXPECT_NEAR(named_dielectric("Fused_Silica")->abbe_number(), 67.8, 0.1);
    EXPECT_NEAR(named_dielectric("diamond")->reference(), 2.4175, 5e-4);
    EXPECT_NEAR(named_dielectric("water")->reference(), 1.3330, 5e-4);
    EXPECT_FALSE(named_dielectric("glass of unknown make").has_value());
    // Normal dispersion: blue bends more than red.
    for (const std::string& name : dielectric_names()) {
        const auto ior = named_dielectric(name);
        EXPECT_GT(ior->eval(420.0), ior->eval(680.0)) << name;
        EXPECT_TRUE(ior->is_dispersive());
    }
}

TEST(SpectralDispersion, AbbeAndCauchyForms) {
    const DispersiveIor flint = DispersiveIor::from_abbe(1.62, 36.4);
    EXPECT_NEAR(flint.reference(), 1.62, 1e-12);
    EXPECT_NEAR(flint.abbe_number(), 36.4, 1e-9);
    EXPECT_FALSE(DispersiveIor::from_abbe(1.5, 0.0).is_dispersive());
    EXPECT_EQ(DispersiveIor::from_abbe(1.5, 0.0).eval(400.0), 1.5);
    const DispersiveIor cauchy = DispersiveIor::cauchy(1.5, 0.004);
    EXPECT_NEAR(cauchy.eval(500.0), 1.5 + 0.004 / 0.25, 1e-12);
    EXPECT_EQ(DispersiveIor::constant(1.33).abbe_number(), INFINITY);
}

TEST(SpectralDispersion, RejectsBadSellmeierTerms) {
    EXPECT_TRUE(DispersiveIor::check_sellmeier({}, {}).has_value());
    EXPECT_TRUE(DispersiveIor::check_sellmeier({1.0, 0.2}, {0.01}).has_value());
    EXPECT_TRUE(DispersiveIor::check_sellmeier({1.0}, {-0.01}).has_value());
    EXPECT_FALSE(DispersiveIor::check_sellmeier({1.0}, {0.01}).has_value());
    EXPECT_THROW(DispersiveIor::sellmeier({1.0}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace glint::spectral
