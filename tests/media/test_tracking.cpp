// Delta and ratio tracking through a heterogeneous grid against the transmittance from
// numerical quadrature of the optical depth, and against each other.
#include <glint/core/rng.h>
#include <glint/media/fbm_cloud.h>
#include <glint/media/tracking.h>
#include <support/chi_square.h>

#include <gtest/gtest.h>

namespace glint {
namespace {

struct TestRay {
    Vec3 o, d;
    float t_max;
};

// The optical depth integral of density along o + t d over [a, b] (midpoint rule, fine
// enough that its error is far below the tests' noise).
double optical_depth(const VoxelGrid& grid, const TestRay& ray, double a, double b) {
    const int steps = 20000;
    const double h = (b - a) / steps;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        sum += grid.density(ray.o + float(a + (i + 0.5) * h) * ray.d);
    }
    return sum * h;
}

VoxelGrid test_cloud() {
    return make_fbm_cloud({.resolution = 24, .frequency = 4.0f, .coverage = 0.8f},
                          Bounds3{Vec3(0.0f), Vec3(1.0f)});
}

// Rays through the box in several directions, some ending inside it, of non-unit speed.
std::vector<TestRay> test_rays() {
    return {{Vec3(-0.2f, 0.5f, 0.5f), Vec3(1.0f, 0.0f, 0.0f), kInfinity},
            {Vec3(-0.1f, -0.1f, 0.2f), Vec3(0.5f, 0.55f, 0.3f), kInfinity},
            {Vec3(0.5f, 0.45f, 0.55f), Vec3(-0.3f, 0.2f, -0.9f), 0.4f},
            {Vec3(1.2f, 0.3f, 0.7f), Vec3(-2.0f, 0.4f, -0.2f), 0.5f}};
}

constexpr float kSigmaT = 6.0f;

TEST(Tracking, DeltaAndRatioTrackingMatchTheQuadratureTransmittance) {
    const VoxelGrid cloud = test_cloud();
    for (const int resolution : {1, 8}) {
        const MajorantGrid majorants(cloud, resolution);
        Rng rng(99);
        const auto uniform = [&] { return rng.next_float(); };
        for (const TestRay& ray : test_rays()) {
            const double t_end = std::min<double>(ray.t_max, 4.0);
            const double expected = std::exp(-kSigmaT * optical_depth(cloud, ray, 0.0, t_end));
            const int n = 40000;
            double ratio_sum = 0.0, ratio_sum2 = 0.0;
            int escaped = 0;
            for (int i = 0; i < n; ++i) {
                const float r =
                    ratio_tracking(cloud, majorants, ray.o, ray.d, ray.t_max, kSigmaT, uniform);
                ratio_sum += r;
                ratio_sum2 += double(r) * r;
                if (!delta_tracking(cloud, majorants, ray.o, ray.d, ray.t_max, kSigmaT, uniform)) {
                    ++escaped;
                }
            }
            const double ratio = ratio_sum / n;
            const double ratio_error =
                std::sqrt(std::max(0.0, ratio_sum2 / n - ratio * ratio) / n) + 1e-6;
            const double delta = double(escaped) / n;
            const double delta_error = std::sqrt(expected * (1.0 - expected) / n) + 1e-6;
            SCOPED_TRACE(::testing::Message()
                         << "resolution " << resolution << " expected " << expected);
            EXPECT_GT(expected, 0.05);
            EXPECT_LT(expected, 0.95);
            EXPECT_NEAR(ratio, expected, 4.5 * ratio_error);
            EXPECT_NEAR(delta, expected, 4.5 * delta_error);
            EXPECT_NEAR(ratio, delta, 4.5 * std::hypot(ratio_error, delta_error));
        }
    }
}

TEST(Tracking, RatioTrackingHandlesEachChannel) {
    const VoxelGrid cloud = test_cloud();
    const MajorantGrid majorants(cloud);
    Rng rng(5);
    const auto uniform = [&] { return rng.next_float(); };
    const TestRay ray = test_rays()[1];
    const double depth = optical_depth(cloud, ray, 0.0, 4.0);
    const Spectrum sigma_t = uplift(Rgb(2.0f, 4.0f, 8.0f), RgbRole::unbounded);
    const int n = 40000;
    Spectrum sum(0.0f);
    for (int i = 0; i < n; ++i) {
        sum += ratio_tracking(cloud, majorants, ray.o, ray.d, ray.t_max, sigma_t, uniform);
    }
    const Rgb mean = to_rgb(sum * (1.0f / n));
    const float sigmas[3] = {2.0f, 4.0f, 8.0f};
    const float means[3] = {mean.r, mean.g, mean.b};
    for (int c = 0; c < 3; ++c) {
        const double expected = std::exp(-sigmas[c] * depth);
        // Ratio tracking's estimates lie in [0, 1]: a variance bound of T(1 - T) per sample.
        EXPECT_NEAR(means[c], expected, 4.5 * std::sqrt(expected * (1 - expected) / n) + 1e-5)
            << "channel " << c;
    }
}

// The collision distance of delta tracking has density sigma_t(t) T(t): its distribution
// over bins of t (and the escape bin) against the quadrature's, by a chi-square test.
TEST(Tracking, DeltaTrackingSamplesTheFreeFlightDistribution) {
    const VoxelGrid cloud = test_cloud();
    const MajorantGrid majorants(cloud);
    const TestRay ray = test_rays()[0];
    const double t_end = 1.2;  // the ray leaves the box at 1.2
    const int bins = 24, n = 100000;
    std::vector<double> expected(bins + 1);
    double depth = 0.0, previous_transmittance = 1.0;
    for (int b = 0; b < bins; ++b) {
        depth += optical_depth(cloud, ray, t_end * b / bins, t_end * (b + 1) / bins);
        const double transmittance = std::exp(-kSigmaT * depth);
        expected[b] = n * (previous_transmittance - transmittance);
        previous_transmittance = transmittance;
    }
    expected[bins] = n * previous_transmittance;
    std::vector<double> observed(bins + 1, 0.0);
    Rng rng(17);
    const auto uniform = [&] { return rng.next_float(); };
    for (int i = 0; i < n; ++i) {
        const auto t = delta_tracking(cloud, majorants, ray.o, ray.d, ray.t_max, kSigmaT, uniform);
        observed[t ? std::min(bins - 1, int(*t / t_end * bins)) : bins] += 1.0;
    }
    double statistic = 0.0;
    int dof = -1;
    for (int b = 0; b <= bins; ++b) {
        if (expected[b] < 5.0) continue;
        statistic += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
        ++dof;
    }
    EXPECT_GT(test::chi_square_upper_tail(statistic, dof), 0.001) << "chi2 " << statistic;
}

}  // namespace
}  // namespace glint
