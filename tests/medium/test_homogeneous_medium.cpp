// A homogeneous slab: its transmittance is exp(-sigma_t d) per channel, in closed form and
// as delta tracking's probability of crossing without a collision (for each hero channel);
// ratio tracking estimates the same. Bad parameters name the script line.
#include <glint/core/error.h>
#include <glint/medium/delta_tracking.h>
#include <glint/medium/homogeneous_medium.h>
#include <glint/medium/registry.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>
#include <support/render_helpers.h>

#include <cmath>

using namespace glint;
using namespace glint::test;

namespace {

const Rgb kSigmaA(0.2f, 0.05f, 0.6f);
const Rgb kSigmaS(0.3f, 1.0f, 0.1f);
constexpr float kDepth = 1.7f;

double expected(int c) {
    const float sigma_t = kSigmaA[c] + kSigmaS[c];
    return std::exp(-static_cast<double>(sigma_t) * kDepth);
}

}  // namespace

TEST(HomogeneousSlab, ClosedFormTransmittancePerChannel) {
    const HomogeneousMedium medium(kSigmaA, kSigmaS, 0.0f);
    Rng rng(1);
    // A direction of length 2: t is in the ray's parameter, the distance twice that.
    const Ray ray{Vec3(0.0f), Vec3(0.0f, 0.0f, 2.0f)};
    const Spectrum T = medium.transmittance(ray, kDepth / 2.0f, rng);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(T.value(c), expected(c), 1e-6) << "channel " << c;
}

// The fraction of delta-tracking walks (hero c) that cross the slab with no collision is
// T_c, and the majorant transmittance they carry over is 1 in the hero channel (what
// volpath divides by).
TEST(HomogeneousSlab, DeltaTrackingCrossesWithProbabilityOfTransmittance) {
    const HomogeneousMedium medium(kSigmaA, kSigmaS, 0.0f);
    const Ray ray{Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f)};
    const int n = 200000;
    for (int hero = 0; hero < 3; ++hero) {
        Rng rng(7 + hero);
        int crossed = 0;
        for (int i = 0; i < n; ++i) {
            bool collided = false;
            const Spectrum T_maj = sample_collisions(
                medium, ray, kDepth, hero, rng,
                [&](float t, const MediumPoint&, const Spectrum&, const Spectrum&) {
                    EXPECT_LT(t, kDepth);
                    collided = true;
                    return false;
                });
            if (!collided) {
                ++crossed;
                EXPECT_NEAR(T_maj.value(hero), expected(hero), 1e-5);
            }
        }
        const double p = expected(hero);
        const double se = std::sqrt(p * (1.0 - p) / n);
        EXPECT_NEAR(crossed / static_cast<double>(n), p, 4.0 * se) << "hero " << hero;
    }
}

// Delta tracking's first collision, chi-square against its density sigma exp(-sigma t)
// (hero channel's sigma) over 20 bins of [0, d), the crossings without one as a 21st bin.
TEST(HomogeneousSlab, CollisionDistancesFollowTheirDensity) {
    const HomogeneousMedium medium(kSigmaA, kSigmaS, 0.0f);
    const Ray ray{Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f)};
    const int n = 100000, bins = 20;
    for (int hero = 0; hero < 3; ++hero) {
        const double sigma = kSigmaA[hero] + kSigmaS[hero];
        std::vector<int> counts(bins + 1, 0);
        Rng rng(11 + hero);
        for (int i = 0; i < n; ++i) {
            int bin = bins;
            sample_collisions(medium, ray, kDepth, hero, rng,
                              [&](float t, const MediumPoint&, const Spectrum&, const Spectrum&) {
                                  bin = std::min(bins - 1, static_cast<int>(t / kDepth * bins));
                                  return false;
                              });
            ++counts[bin];
        }
        double statistic = 0.0;
        for (int b = 0; b <= bins; ++b) {
            const double a = kDepth * b / bins, c = kDepth * (b + 1) / bins;
            const double p =
                b == bins ? std::exp(-sigma * kDepth) : std::exp(-sigma * a) - std::exp(-sigma * c);
            const double expected_count = p * n;
            statistic +=
                (counts[b] - expected_count) * (counts[b] - expected_count) / expected_count;
        }
        EXPECT_GT(chi_square_upper_tail(statistic, bins), 0.01) << "hero " << hero;
    }
}

TEST(HomogeneousSlab, RatioTrackingEstimatesTransmittance) {
    const HomogeneousMedium medium(kSigmaA, kSigmaS, 0.0f);
    const Ray ray{Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    Rng rng(3);
    const int n = 100000;
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        const Spectrum T = ratio_tracking_transmittance(medium, ray, kDepth, rng);
        for (int c = 0; c < 3; ++c) {
            sum[c] += T.value(c);
            sum2[c] += T.value(c) * T.value(c);
        }
    }
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / n;
        const double se = std::sqrt(std::max(0.0, sum2[c] / n - mean * mean) / n);
        EXPECT_NEAR(mean, expected(c), 4.0 * se + 1e-6) << "channel " << c;
    }
}

TEST(MediumParameters, DensityAndAlbedoGiveTheCoefficients) {
    Params p("medium", "test.lua:1");
    p.set("density", std::vector<double>{2.0, 4.0, 1.0});
    p.set("albedo", 0.75);
    p.set("scale", 0.5);
    const auto medium = make_medium(p);
    const MediumPoint point = medium->at(Vec3(0.0f));
    EXPECT_NEAR(point.sigma_s.value(1), 1.5f, 1e-6f);
    EXPECT_NEAR(point.sigma_a.value(1), 0.5f, 1e-6f);
    EXPECT_TRUE(medium->scatters());
}

TEST(MediumParameters, BadValuesNameTheLine) {
    const char* cases[] = {
        "glint.medium{ sigma_s = 1, g = 1 }",       "glint.medium{ sigma_a = -1 }",
        "glint.medium{ sigma_s = 1, density = 2 }", "glint.medium{ density = 1, albedo = 1.5 }",
        "glint.medium{ sigma_s = 1, scale = 0 }",   "glint.medium{ sigma_s = 1, colour = 2 }",
    };
    for (const char* line : cases) {
        const std::string scene = std::string("glint.camera{ medium = ") + line + " }\n";
        try {
            build_lua(scene, "media.lua");
            ADD_FAILURE() << "accepted: " << line;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("media.lua:1"), std::string::npos) << e.what();
        }
    }
}
