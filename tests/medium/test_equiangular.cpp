// Equiangular distance sampling (medium/equiangular.h): chi-square of its distances against
// its density over bins of the segment, for a light beside, ahead of and behind the ray's
// start (and far behind it, where the angles crowd near pi / 2), on finite and infinite
// segments; the density integrates to one; degenerate cases
// (the light on the ray's line, an empty segment) give no sampler.
#include <glint/core/rng.h>
#include <glint/medium/equiangular.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace glint;
using namespace glint::test;

namespace {

struct Case {
    const char* name;
    Vec3 light;
    float t_end;  // may be infinite
};

const Ray kRay{Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f)};

const Case kCases[] = {
    {"beside the middle", Vec3(0.3f, 0.0f, 1.0f), 2.0f},
    {"close beside the start", Vec3(0.0f, 0.05f, 0.02f), 3.0f},
    {"ahead of the end", Vec3(0.5f, 0.2f, 5.0f), 2.0f},
    {"behind the start", Vec3(0.0f, 1.0f, -2.0f), 4.0f},
    {"infinite segment", Vec3(0.2f, 0.1f, 1.5f), kInfinity},
    // The segment subtends 1e-6 rad at an angle of almost pi/2: the spread of two angles
    // there would keep about three bits.
    {"far behind the start", Vec3(0.0f, 0.01f, -100.0f), 1.0f},
};

// The bins' edges: uniform over [0, t_end), or for an infinite segment uniform in the
// angle (the density's own spread), so that each bin expects enough samples.
float edge(const Case& c, const Equiangular& e, int b, int bins) {
    if (!std::isinf(c.t_end)) return c.t_end * static_cast<float>(b) / static_cast<float>(bins);
    if (b == bins) return kInfinity;
    return std::max(0.0f, e.sample(static_cast<float>(b) / static_cast<float>(bins)));
}

// The density's integral over [a, b) by Simpson's rule on 64 panels (a, b finite), or in
// closed form through the angle where b is infinite.
double integral(const Equiangular& e, float a, float b) {
    if (std::isinf(b)) {
        const double theta_a = std::atan((static_cast<double>(a) - e.delta) / e.D);
        return (0.5 * kPi - theta_a) / static_cast<double>(e.spread);
    }
    const int panels = 64;
    const double h = (static_cast<double>(b) - a) / panels;
    double sum = 0.0;
    for (int i = 0; i <= panels; ++i) {
        const double weight = i == 0 || i == panels ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
        sum += weight * e.pdf(static_cast<float>(a + i * h));
    }
    return sum * h / 3.0;
}

}  // namespace

TEST(Equiangular, DistancesFollowTheirDensity) {
    const int n = 200000, bins = 40;
    for (const Case& c : kCases) {
        const std::optional<Equiangular> e = Equiangular::towards(kRay, c.light, c.t_end);
        ASSERT_TRUE(e) << c.name;
        std::vector<float> edges(bins + 1);
        for (int b = 0; b <= bins; ++b) edges[static_cast<size_t>(b)] = edge(c, *e, b, bins);
        std::vector<int> counts(bins, 0);
        Rng rng(17);
        for (int i = 0; i < n; ++i) {
            const float t = std::min(std::max(e->sample(rng.next_float()), 0.0f), c.t_end);
            ASSERT_TRUE(std::isfinite(t)) << c.name;
            const auto upper = std::upper_bound(edges.begin(), edges.end(), t);
            const int b = std::clamp(static_cast<int>(upper - edges.begin()) - 1, 0, bins - 1);
            ++counts[static_cast<size_t>(b)];
        }
        double statistic = 0.0, total = 0.0;
        for (int b = 0; b < bins; ++b) {
            const double p =
                integral(*e, edges[static_cast<size_t>(b)], edges[static_cast<size_t>(b) + 1]);
            total += p;
            const double expected_count = p * n;
            ASSERT_GT(expected_count, 5.0) << c.name << " bin " << b;
            const double d = counts[static_cast<size_t>(b)] - expected_count;
            statistic += d * d / expected_count;
        }
        EXPECT_NEAR(total, 1.0, 1e-3) << c.name;
        EXPECT_GT(chi_square_upper_tail(statistic, bins - 1), 0.01) << c.name;
    }
}

// A planted error the chi-square must see: the density of a light 10 % farther from the
// ray than the one sampled.
TEST(Equiangular, ChiSquareSeesAWrongDensity) {
    const int n = 200000, bins = 40;
    const Case& c = kCases[0];
    const Equiangular e = *Equiangular::towards(kRay, c.light, c.t_end);
    const Equiangular wrong =
        *Equiangular::towards(kRay, c.light * Vec3(1.1f, 1.1f, 1.0f), c.t_end);
    std::vector<int> counts(bins, 0);
    Rng rng(5);
    for (int i = 0; i < n; ++i) {
        const float t = std::clamp(e.sample(rng.next_float()), 0.0f, c.t_end);
        ++counts[static_cast<size_t>(std::min(bins - 1, static_cast<int>(t / c.t_end * bins)))];
    }
    double statistic = 0.0;
    for (int b = 0; b < bins; ++b) {
        const double p = integral(wrong, c.t_end * b / bins, c.t_end * (b + 1) / bins);
        const double d = counts[static_cast<size_t>(b)] - p * n;
        statistic += d * d / (p * n);
    }
    EXPECT_LT(chi_square_upper_tail(statistic, bins - 1), 1e-6);
}

TEST(Equiangular, NoSamplerWithoutAnAngle) {
    EXPECT_FALSE(Equiangular::towards(kRay, Vec3(0.0f, 0.0f, 1.0f), 2.0f));  // on the line
    EXPECT_FALSE(Equiangular::towards(kRay, Vec3(0.0f, 1.0f, 1.0f), 0.0f));  // empty segment
    EXPECT_TRUE(Equiangular::towards(kRay, Vec3(0.0f, 1.0f, 1.0f), 1.0f));
}
