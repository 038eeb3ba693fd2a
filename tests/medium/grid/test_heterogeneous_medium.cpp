// A heterogeneous medium through the Medium interface: its majorant segments bound its
// extinction, and delta tracking (sample_collisions) and ratio tracking (transmittance)
// agree with the transmittance from numerical quadrature of the optical depth, and with
// each other, for a fine majorant grid and for one global majorant.
#include <glint/medium/delta_tracking.h>
#include <glint/medium/grid/fbm_cloud.h>
#include <glint/medium/heterogeneous_medium.h>
#include <support/chi_square.h>

#include <gtest/gtest.h>

namespace glint {
namespace {

// The cloud over the unit box, moved and stretched into the scene, so that the map from
// the scene to the grid is exercised. Extinction 1.5 per unit at density 1, albedo 0.5.
HeterogeneousMedium test_medium(int majorant_resolution, Rgb sigma_t = Rgb(1.5f)) {
    VoxelGrid cloud = make_fbm_cloud({.resolution = 24, .frequency = 4.0f, .coverage = 0.8f},
                                     Bounds3{Vec3(0.0f), Vec3(1.0f)});
    const Transform grid_to_world =
        Transform::translate(Vec3(1.0f, -0.5f, 0.0f)) * Transform::scale(Vec3(2.0f, 1.0f, 1.5f));
    return HeterogeneousMedium(std::move(cloud), grid_to_world, sigma_t * 0.5f, sigma_t * 0.5f,
                               0.0f, majorant_resolution);
}

// Rays in scene space (the box spans [1, 3] x [-0.5, 0.5] x [0, 1.5]), some ending inside,
// some with a direction that is not unit length.
std::vector<Ray> test_rays() {
    return {Ray{Vec3(0.5f, 0.0f, 0.75f), Vec3(1.0f, 0.0f, 0.0f)},
            Ray{Vec3(0.8f, -0.6f, 0.1f), Vec3(0.8f, 0.45f, 0.5f)},
            Ray{Vec3(2.0f, -0.05f, 0.8f), Vec3(-0.6f, 0.2f, -0.9f), 0.0f, 0.7f},
            Ray{Vec3(3.4f, -0.2f, 1.0f), Vec3(-3.0f, 0.4f, -0.3f), 0.0f, 0.6f}};
}

// The optical depth (extinction integral, channel 0) along ray over parameters [a, b].
double optical_depth(const Medium& medium, const Ray& ray, double a, double b) {
    const int steps = 20000;
    const double h = (b - a) / steps;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const MediumPoint p = medium.at(ray.at(float(a + (i + 0.5) * h)));
        sum += (p.sigma_a + p.sigma_s).value(0);
    }
    return sum * h * glm::length(ray.direction);
}

float ray_end(const Ray& ray) {
    return std::min(ray.t_max, 4.0f);
}

TEST(HeterogeneousMedium, MajorantSegmentsBoundTheExtinctionAlongRays) {
    const HeterogeneousMedium medium = test_medium(16);
    Rng rng(3);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o(4.0f * rng.next_float(), 2.0f * rng.next_float() - 1.0f,
                     2.0f * rng.next_float() - 0.25f);
        const Vec3 d = glm::normalize(
            Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
        const Ray ray{o, d};
        float previous_end = 0.0f;
        medium.majorants(ray, 5.0f, [&](const MajorantSegment& segment) {
            EXPECT_GE(segment.t_min, previous_end);
            previous_end = segment.t_max;
            for (int k = 0; k <= 8; ++k) {
                const float t = segment.t_min + (segment.t_max - segment.t_min) * k / 8.0f;
                const MediumPoint p = medium.at(ray.at(t));
                EXPECT_LE((p.sigma_a + p.sigma_s).max_value(),
                          segment.sigma_maj.max_value() * (1.0f + 1e-5f));
            }
            return true;
        });
    }
}

// The escape fraction of delta tracking (channel 0 as hero) over n walks.
double delta_tracking_escapes(const Medium& medium, const Ray& ray, int n, Rng& rng) {
    int escaped = 0;
    for (int i = 0; i < n; ++i) {
        bool collided = false;
        sample_collisions(
            medium, ray, ray_end(ray), 0, rng,
            [&](float, const MediumPoint& p, const Spectrum& sigma_maj, const Spectrum&) {
                // A real collision with probability sigma_t / sigma_maj.
                collided = rng.next_float() * sigma_maj.value(0) < (p.sigma_a + p.sigma_s).value(0);
                return !collided;
            });
        escaped += collided ? 0 : 1;
    }
    return double(escaped) / n;
}

TEST(HeterogeneousMedium, DeltaAndRatioTrackingAgreeWithQuadrature) {
    for (const int resolution : {1, 16}) {
        const HeterogeneousMedium medium = test_medium(resolution);
        Rng rng(99);
        for (const Ray& ray : test_rays()) {
            const double expected = std::exp(-optical_depth(medium, ray, 0.0, ray_end(ray)));
            const int n = 40000;
            double sum = 0.0, sum2 = 0.0;
            for (int i = 0; i < n; ++i) {
                const float r = medium.transmittance(ray, ray_end(ray), rng).value(0);
                sum += r;
                sum2 += double(r) * r;
            }
            const double ratio = sum / n;
            const double ratio_error =
                std::sqrt(std::max(0.0, sum2 / n - ratio * ratio) / n) + 1e-6;
            const double delta = delta_tracking_escapes(medium, ray, n, rng);
            const double delta_error = std::sqrt(expected * (1.0 - expected) / n) + 1e-6;
            SCOPED_TRACE(::testing::Message()
                         << "majorant resolution " << resolution << ", expected " << expected);
            // A ray that saw only empty space or only opaque cloud would test nothing.
            EXPECT_GT(expected, 0.05);
            EXPECT_LT(expected, 0.95);
            EXPECT_NEAR(ratio, expected, 4.5 * ratio_error);
            EXPECT_NEAR(delta, expected, 4.5 * delta_error);
            EXPECT_NEAR(ratio, delta, 4.5 * std::hypot(ratio_error, delta_error));
        }
    }
}

TEST(HeterogeneousMedium, RatioTrackingHandlesEachChannel) {
    const float sigmas[3] = {2.0f, 4.0f, 8.0f};
    const HeterogeneousMedium medium = test_medium(16, Rgb(sigmas[0], sigmas[1], sigmas[2]));
    const HeterogeneousMedium grey = test_medium(16, Rgb(1.0f));
    Rng rng(5);
    const Ray ray = test_rays()[1];
    const double depth = optical_depth(grey, ray, 0.0, ray_end(ray));
    const int n = 40000;
    Spectrum sum(0.0f);
    for (int i = 0; i < n; ++i) sum += medium.transmittance(ray, ray_end(ray), rng);
    for (int c = 0; c < 3; ++c) {
        const double expected = std::exp(-sigmas[c] * depth);
        // Ratio tracking's estimates lie in [0, 1]: a variance of at most T(1 - T).
        EXPECT_NEAR(sum.value(c) / n, expected,
                    4.5 * std::sqrt(expected * (1 - expected) / n) + 1e-5)
            << "channel " << c;
    }
}

// The collision distance of delta tracking has density sigma_t(t) T(t): its histogram over
// bins of t (and the escape bin) against the quadrature's, by a chi-square test.
TEST(HeterogeneousMedium, DeltaTrackingSamplesTheFreeFlightDistribution) {
    const HeterogeneousMedium medium = test_medium(16);
    const Ray ray = test_rays()[0];
    const double t_end = 2.5;  // the ray leaves the box at t = 2.5
    const int bins = 25, n = 100000;
    std::vector<double> expected(bins + 1);
    double depth = 0.0, previous = 1.0;
    for (int b = 0; b < bins; ++b) {
        depth += optical_depth(medium, ray, t_end * b / bins, t_end * (b + 1) / bins);
        const double transmittance = std::exp(-depth);
        expected[b] = n * (previous - transmittance);
        previous = transmittance;
    }
    expected[bins] = n * previous;
    std::vector<double> observed(bins + 1, 0.0);
    Rng rng(17);
    for (int i = 0; i < n; ++i) {
        float hit = -1.0f;
        sample_collisions(
            medium, ray, kInfinity, 0, rng,
            [&](float t, const MediumPoint& p, const Spectrum& sigma_maj, const Spectrum&) {
                if (rng.next_float() * sigma_maj.value(0) < (p.sigma_a + p.sigma_s).value(0)) {
                    hit = t;
                    return false;
                }
                return true;
            });
        observed[hit >= 0.0f ? std::min(bins - 1, int(hit / t_end * bins)) : bins] += 1.0;
    }
    double statistic = 0.0;
    int dof = -1;
    for (int b = 0; b <= bins; ++b) {
        if (expected[b] < 5.0) {
            EXPECT_LT(observed[b], 30.0) << "bin " << b;
            continue;
        }
        statistic += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
        ++dof;
    }
    EXPECT_GT(test::chi_square_upper_tail(statistic, dof), 0.001) << "chi-square " << statistic;
}

}  // namespace
}  // namespace glint
