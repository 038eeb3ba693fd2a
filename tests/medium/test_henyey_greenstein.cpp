// Henyey-Greenstein: sampling against its density (chi-square) for forward, backward and
// even scattering; the density normalised over the sphere, with mean cosine g.
#include <glint/medium/henyey_greenstein.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>

#include <cmath>

using namespace glint;
using namespace glint::test;

class HenyeyGreensteinSampling : public ::testing::TestWithParam<float> {};

TEST_P(HenyeyGreensteinSampling, MatchesItsDensity) {
    const HenyeyGreenstein phase(GetParam());
    // An oblique wo, so that the sampled frame is not the test's own.
    const Vec3 wo = glm::normalize(Vec3(0.3f, -0.5f, 0.8f));
    const ChiSquareResult result = chi_square_directions(
        [&](const Vec2& u, float) -> std::optional<Vec3> {
            const PhaseSample s = phase.sample(wo, u);
            EXPECT_NEAR(s.p, phase.eval(wo, s.wi), 1e-3f * s.p);
            return s.wi;
        },
        [&](const Vec3& wi) { return static_cast<double>(phase.eval(wo, wi)); });
    EXPECT_TRUE(result.passed) << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 1e-3);
}

// The mean cosine of the scattering angle (between the light's direction before, -wi, and
// after, wo) is g: the sign convention that g > 0 scatters forwards.
TEST_P(HenyeyGreensteinSampling, MeanCosineIsG) {
    const float g = GetParam();
    const HenyeyGreenstein phase(g);
    const Vec3 wo(0.0f, 0.0f, 1.0f);
    double sum = 0.0;
    const int n = 400;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Vec2 u((i + 0.5f) / n, (j + 0.5f) / n);
            sum += glm::dot(wo, -phase.sample(wo, u).wi);
        }
    }
    EXPECT_NEAR(sum / (n * n), g, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(SeveralG, HenyeyGreensteinSampling,
                         ::testing::Values(-0.7f, -0.3f, 0.0f, 0.0005f, 0.4f, 0.85f),
                         [](const ::testing::TestParamInfo<float>& info) {
                             return "g" + std::to_string(info.index);
                         });
