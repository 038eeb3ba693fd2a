// The photon map's k-nearest-neighbour query against brute force, and its radiance estimate
// on a uniformly lit plane (exact irradiance, within noise).
#include <glint/core/interaction.h>
#include <glint/integrator/photon/photon_map.h>
#include <glint/material/lambertian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace glint;

namespace {

using Found = std::vector<std::pair<float, uint32_t>>;

// Points in a cube, on two planes meeting at an edge (as photons on surfaces lie, with
// many equal coordinates), and in a tight cluster.
std::vector<Photon> random_photons(int n, int layout, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Photon> photons;
    for (int i = 0; i < n; ++i) {
        Vec3 p;
        if (layout == 0) {
            p = Vec3(u(rng), u(rng), u(rng));
        } else if (layout == 1) {
            const float a = u(rng), b = u(rng);
            p = u(rng) < 0.5f ? Vec3(a, 0.0f, b) : Vec3(a, b, 0.0f);
        } else {
            p = Vec3(0.5f) + 0.01f * Vec3(u(rng), u(rng), u(rng));
        }
        photons.push_back({p, Vec3(0, 1, 0), Spectrum(1.0f)});
    }
    return photons;
}

// The k nearest photons with d^2 < max_distance2, by sorting all of them.
std::vector<uint32_t> brute_force(const PhotonMap& map, const Vec3& p, int k, float max_distance2) {
    Found all;
    for (size_t i = 0; i < map.size(); ++i) {
        const float d2 = length_squared(map[i].p - p);
        if (d2 < max_distance2) all.emplace_back(d2, static_cast<uint32_t>(i));
    }
    std::sort(all.begin(), all.end());
    std::vector<uint32_t> indices;
    for (size_t i = 0; i < all.size() && static_cast<int>(i) < k; ++i)
        indices.push_back(all[i].second);
    std::sort(indices.begin(), indices.end());
    return indices;
}

}  // namespace

TEST(PhotonMap, NearestMatchesBruteForce) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    int compared = 0, full = 0, capped = 0;
    for (int layout = 0; layout < 3; ++layout) {
        for (int n : {1, 7, 100, 3000}) {
            const PhotonMap map(random_photons(n, layout, rng));
            ASSERT_EQ(map.size(), static_cast<size_t>(n));
            for (int q = 0; q < 200; ++q) {
                // Queries near the photons and off them, some exactly on one of them.
                const Vec3 p = q % 10 == 0   ? map[static_cast<size_t>(q) % map.size()].p
                               : layout == 2 ? Vec3(0.5f) + 0.02f * Vec3(u(rng), u(rng), u(rng))
                                             : Vec3(u(rng), u(rng), u(rng));
                const int k = std::array{1, 5, 50}[q % 3];
                const float max_distance2 = std::array{kInfinity, 0.01f, 1e-4f}[(q / 3) % 3];
                Found found;
                map.nearest(p, k, max_distance2, found);
                std::vector<uint32_t> indices;
                for (const auto& [d2, index] : found) {
                    EXPECT_FLOAT_EQ(d2, length_squared(map[index].p - p));
                    indices.push_back(index);
                }
                std::sort(indices.begin(), indices.end());
                ASSERT_EQ(indices, brute_force(map, p, k, max_distance2))
                    << "layout " << layout << ", " << n << " photons, query " << q << ", k " << k
                    << ", max d^2 " << max_distance2;
                // front() is the farthest photon kept (the radius of the estimate).
                if (!found.empty()) {
                    for (const auto& f : found) EXPECT_LE(f.first, found.front().first);
                }
                ++compared;
                full += static_cast<int>(found.size()) == k;
                capped += !found.empty() && static_cast<int>(found.size()) < k;
            }
        }
    }
    // Both regimes were exercised: k found, and fewer than k within the cap.
    EXPECT_GT(full, compared / 4);
    EXPECT_GT(capped, compared / 20);
}

// Photons of equal power spread uniformly over a unit square with total power Phi give the
// irradiance E = Phi / A, so a Lambertian surface of albedo rho reflects L = rho E / pi in
// every direction. The k-NN estimate with the cone filter has expectation
// 1 + 0.23 / (k - 1) times that for a Poisson process (the k-th photon sits on the rim of the
// disc, with the filter's weight there); its relative standard deviation is about 1/sqrt(k).
TEST(PhotonMap, UniformlyLitPlaneGivesTheIrradiance) {
    constexpr int kPhotons = 200000, kNeighbours = 64, kGrid = 20;
    constexpr float kPower = 3.0f, kAlbedo = 0.6f;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Photon> photons;
    for (int i = 0; i < kPhotons; ++i) {
        // Arrivals from above, from random directions: the estimate must not care.
        const Vec3 wi = glm::normalize(Vec3(u(rng) - 0.5f, 0.2f + u(rng), u(rng) - 0.5f));
        photons.push_back({Vec3(u(rng), 0.0f, u(rng)), wi, Spectrum(kPower / kPhotons)});
    }
    // A few photons that arrived from below must be ignored.
    for (int i = 0; i < kPhotons / 10; ++i)
        photons.push_back({Vec3(u(rng), 0.0f, u(rng)), Vec3(0, -1, 0), Spectrum(1.0f)});
    const PhotonMap map(std::move(photons));
    const LambertianBsdf bsdf{Spectrum(kAlbedo)};
    const double expected = kAlbedo * kPower / kPi * (1.0 + 0.2308 / (kNeighbours - 1));

    // Query points on a grid far enough apart (the disc radius is about 0.01) that the
    // estimates are independent, away from the square's edges.
    double sum = 0.0, sum2 = 0.0;
    int m = 0;
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            SurfaceInteraction si;
            si.p = Vec3((i + 0.5f) / kGrid, 0.0f, (j + 0.5f) / kGrid);
            si.ng = Vec3(0, 1, 0);
            si.shading = Frame::from_normal(si.ng);
            si.wo = glm::normalize(Vec3(0.3f, 1.0f, -0.2f));
            const double L = radiance_estimate(map, si, bsdf, kNeighbours, 0.25f).g;
            sum += L;
            sum2 += L * L;
            ++m;
        }
    }
    const double mean = sum / m;
    const double sd = std::sqrt(std::max(0.0, sum2 / m - mean * mean));
    EXPECT_NEAR(sd / mean, 1.0 / std::sqrt(kNeighbours), 0.5 / std::sqrt(kNeighbours));
    EXPECT_NEAR(mean, expected, 4.0 * sd / std::sqrt(m)) << "relative " << mean / expected;
}

// The work of a query (photons examined, a count, not a time) at a fixed k stays about the
// same when the map holds 16 times more photons, on surfaces and between them, with the
// maximum radius of a scene's default (1/20 of the diagonal).
TEST(PhotonMap, LookupWorkDoesNotGrowWithThePhotonCount) {
    constexpr int kNeighbours = 50;
    const float max_distance2 = 3.0f / 400.0f;
    auto mean_examined = [&](int n, bool between) {
        std::mt19937 rng(9);
        const PhotonMap map(random_photons(n, 1, rng));
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        Found found;
        double examined = 0.0;
        constexpr int kQueries = 2000;
        for (int q = 0; q < kQueries; ++q) {
            // On the two planes, or in the plane z = 0.5 above the floor (far from the wall).
            const Vec3 p = between
                               ? Vec3(u(rng), 0.5f * u(rng), 0.5f)
                               : (q % 2 ? Vec3(u(rng), 0.0f, u(rng)) : Vec3(u(rng), u(rng), 0.0f));
            examined += static_cast<double>(map.nearest(p, kNeighbours, max_distance2, found));
        }
        return examined / kQueries;
    };
    for (const bool between : {false, true}) {
        const double few = mean_examined(10000, between), many = mean_examined(160000, between);
        EXPECT_LT(many, 2.0 * few + 10.0 * kNeighbours)
            << (between ? "between the planes" : "on the planes") << ": " << few << " vs " << many;
        EXPECT_LT(many, 20.0 * kNeighbours);
    }
}
