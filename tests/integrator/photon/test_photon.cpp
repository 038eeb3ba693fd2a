// Photon mapping: flux bookkeeping, the caustic of a glass sphere, agreement with the path
// tracer, determinism.
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/photon.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <array>
#include <cmath>

using namespace glint;
using glint::test::mean_channel;
using glint::test::render_lua;

namespace {
// Sample counts for SppmAgreesWithPathTracingOnTheCornellBox, chosen for about 5 s.
constexpr int kPathSpp = 512;
constexpr int kSppmPasses = 128;
constexpr int kSppmPhotons = 10000;
}  // namespace

namespace {

using test::BuiltScene;

BuiltScene build(const std::string& code) {
    return test::build_lua(code, "photon-test.lua");
}

double total_power(const PhotonMap& map) {
    double sum = 0.0;
    for (size_t i = 0; i < map.size(); ++i) sum += to_rgb(map[i].power).g;
    return sum;
}

}  // namespace

// In a closed box of albedo rho around a point light of power Phi, the photons stored at
// every bounce carry Phi rho^k on average, so the global map holds Phi / (1 - rho).
TEST(PhotonMapping, StoredFluxFollowsTheGeometricSeries) {
    for (const double rho : {0.3, 0.7}) {
        BuiltScene b = build(fmt::format(R"(
            glint.render{{ integrator = 'photon', photons = 200000, caustic_photons = 0, seed = 3 }}
            glint.point_light{{ position = {{0.2, 0.3, -0.1}}, intensity = 2 }}
            glint.box{{ min = {{-1, -1, -1}}, max = {{1, 1, 1}}, material = glint.diffuse{{ reflectance = {} }} }}
        )",
                                         rho));
        PhotonIntegrator integrator(b.settings, PhotonSettings::read(b.settings.params));
        integrator.build_maps(*b.scene);
        const double emitted = 4.0 * M_PI * 2.0;
        EXPECT_NEAR(total_power(integrator.global_map()), emitted / (1.0 - rho),
                    0.01 * emitted / (1.0 - rho))
            << "rho = " << rho;
        EXPECT_EQ(integrator.caustic_map().size(), 0u);
    }
}

// Stochastic progressive photon mapping and path tracing converge to the same image of the
// Cornell box with a glass and a mirror sphere (examples/cornell-spheres.lua), caustics
// included. Each integrator renders twice with its own seeds (four independent images); the
// two renders give each one's standard error, and the means of the whole image and of each
// quarter of it must agree within four standard errors of their difference. The whole
// image's bound is under 1.5 % of its mean, so a 3 % bias fails it, which the test checks
// on scaled copies. (SPPM's shrinking radius blurs the image slightly; the regions are large
// enough for that to cancel.)
TEST(PhotonMappingSlow, SppmAgreesWithPathTracingOnTheCornellBox) {
    const int res = 32;
    auto render = [&](const char* integrator, int spp, int seed) {
        return render_lua(glint::test::example_with_settings(
            "cornell-spheres.lua",
            fmt::format("width = {0}, height = {0}, spp = {1}, seed = {2}, integrator = '{3}', "
                        "photons = {4}",
                        res, spp, seed, integrator, kSppmPhotons)));
    };
    const Image path_a = render("path", kPathSpp, 1), path_b = render("path", kPathSpp, 2);
    const Image sppm_a = render("sppm", kSppmPasses, 3), sppm_b = render("sppm", kSppmPasses, 4);
    struct Region {
        int x0, y0, x1, y1;
    };
    const int h = res / 2;
    const Region regions[] = {
        {0, 0, res, res}, {0, 0, h, h}, {h, 0, res, h}, {0, h, h, res}, {h, h, res, res}};
    for (const Region& r : regions) {
        for (int c = 0; c < 3; ++c) {
            auto mean2 = [&](const Image& a, const Image& b) {
                return 0.5 * (mean_channel(a, c, r.x0, r.y0, r.x1, r.y1) +
                              mean_channel(b, c, r.x0, r.y0, r.x1, r.y1));
            };
            const double path = mean2(path_a, path_b), sppm = mean2(sppm_a, sppm_b);
            // Standard errors of one render, halved in variance by averaging two.
            const double path_error =
                glint::test::standard_error_of_mean(path_a, path_b, c, r.x0, r.y0, r.x1, r.y1) /
                std::sqrt(2.0);
            const double sppm_error =
                glint::test::standard_error_of_mean(sppm_a, sppm_b, c, r.x0, r.y0, r.x1, r.y1) /
                std::sqrt(2.0);
            const double bound = 4.0 * std::hypot(path_error, sppm_error);
            const std::string where = fmt::format(
                "region ({}, {})-({}, {}) channel {}: sppm {:.5f}, path {:.5f}, bound {:.5f}", r.x0,
                r.y0, r.x1, r.y1, c, sppm, path, bound);
            fmt::print("{} ({:.2f} %; path {:.5f}, sppm {:.5f})\n", where, 100.0 * bound / path,
                       path_error, sppm_error);
            EXPECT_NEAR(sppm, path, bound) << where;
            if (r.x1 - r.x0 == res) {
                EXPECT_LT(bound, 0.015 * path) << where;
                EXPECT_GT(std::abs(1.03 * sppm - path), bound) << where << ": misses a 3 % bias";
                EXPECT_GT(std::abs(0.97 * sppm - path), bound) << where << ": misses a 3 % bias";
            }
        }
    }
}

namespace {

// Irradiance per radial bin on the plane y = plane_y below a glass circle of radius 1 at the
// origin, lit by parallel light of irradiance 1 travelling along -y: the 2D meridional
// trace of every Fresnel branch (exact Snell and Fresnel), weighted by the 3D ring area.
std::vector<double> reference_caustic_profile(double eta, double plane_y, double bin_width,
                                              int bins) {
    std::vector<double> energy(bins, 0.0);
    auto fresnel = [](double cos_i, double n1, double n2) {
        const double sin_t = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i));
        if (sin_t >= 1.0) return 1.0;
        const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
        const double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
        const double rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
        return 0.5 * (rs * rs + rp * rp);
    };
    struct Branch {
        glm::dvec2 o, d;
        double weight;
        bool inside;
        int depth;
    };
    const int samples = 200000;
    for (int s = 0; s < samples; ++s) {
        // Heights uniform in h^2: equal 3D ring areas per sample.
        const double h = std::sqrt((s + 0.5) / samples);
        const double ring_area = M_PI / samples;
        std::vector<Branch> stack = {{glm::dvec2(h, 3.0), glm::dvec2(0.0, -1.0), 1.0, false, 0}};
        while (!stack.empty()) {
            Branch b = stack.back();
            stack.pop_back();
            // Next intersection with the unit circle, after the start.
            const double bq = glm::dot(b.o, b.d), c = glm::dot(b.o, b.o) - 1.0;
            const double disc = bq * bq - c;
            double t = -1.0;
            if (disc > 0.0) {
                const double t0 = -bq - std::sqrt(disc), t1 = -bq + std::sqrt(disc);
                t = t0 > 1e-9 ? t0 : (t1 > 1e-9 ? t1 : -1.0);
            }
            if (t < 0.0) {
                // Leaves the sphere for good: does it land on the plane?
                if (b.depth > 0 && b.d.y < 0.0) {
                    const double x = b.o.x + (plane_y - b.o.y) / b.d.y * b.d.x;
                    const int bin = static_cast<int>(std::abs(x) / bin_width);
                    if (bin < bins) energy[bin] += b.weight * ring_area;
                }
                continue;
            }
            if (b.weight < 1e-6 || b.depth > 12) continue;
            const glm::dvec2 p = b.o + t * b.d;
            glm::dvec2 n = p;  // outward
            const double n1 = b.inside ? eta : 1.0, n2 = b.inside ? 1.0 : eta;
            if (b.inside) n = -n;  // facing the incoming ray's side
            const double cos_i = -glm::dot(b.d, n);
            const double R = fresnel(cos_i, n1, n2);
            const glm::dvec2 reflected = b.d + 2.0 * cos_i * n;
            stack.push_back({p, reflected, b.weight * R, b.inside, b.depth + 1});
            if (R < 1.0) {
                const double ratio = n1 / n2;
                const double cos_t = std::sqrt(1.0 - ratio * ratio * (1.0 - cos_i * cos_i));
                const glm::dvec2 refracted = ratio * b.d + (ratio * cos_i - cos_t) * n;
                stack.push_back({p, refracted, b.weight * (1.0 - R), !b.inside, b.depth + 1});
            }
        }
    }
    for (int i = 0; i < bins; ++i) {
        const double r0 = i * bin_width, r1 = (i + 1) * bin_width;
        energy[i] /= M_PI * (r1 * r1 - r0 * r0);
    }
    return energy;
}

}  // namespace

// A glass sphere (n = 1.5, radius R) under parallel light focuses paraxial rays 1.5 R from
// its centre. On a receiver there, the caustic photons' radial irradiance profile matches
// an independent 2D trace of the same rays.
TEST(PhotonMapping, GlassSphereCausticMatchesRayTracedProfile) {
    BuiltScene b = build(R"(
        glint.render{ integrator = 'photon', photons = 1, caustic_photons = 600000, seed = 4 }
        glint.directional_light{ direction = {0, -1, 0}, irradiance = 1 }
        glint.sphere{ center = {0, 0, 0}, radius = 1, material = glint.dielectric{ ior = 1.5 } }
        glint.quad{ vertices = { {-1.6, -1.5, 1.6}, {1.6, -1.5, 1.6}, {1.6, -1.5, -1.6}, {-1.6, -1.5, -1.6} },
                    material = glint.diffuse{ reflectance = 0.5 } }
    )");
    PhotonIntegrator integrator(b.settings, PhotonSettings::read(b.settings.params));
    integrator.build_maps(*b.scene);
    const PhotonMap& caustics = integrator.caustic_map();
    ASSERT_GT(caustics.size(), 10000u);

    const double bin_width = 0.05;
    const int bins = 24;
    std::vector<double> measured(bins, 0.0);
    for (size_t i = 0; i < caustics.size(); ++i) {
        const Photon& photon = caustics[i];
        if (std::abs(photon.p.y + 1.5f) > 1e-3f) continue;  // only the receiver
        const int bin = static_cast<int>(std::hypot(photon.p.x, photon.p.z) / bin_width);
        if (bin < bins) measured[bin] += to_rgb(photon.power).g;
    }
    for (int i = 0; i < bins; ++i) {
        measured[i] /= M_PI * (sqr((i + 1) * bin_width) - sqr(i * bin_width));
    }
    const std::vector<double> expected = reference_caustic_profile(1.5, -1.5, bin_width, bins);

    double difference = 0.0, total = 0.0;
    for (int i = 0; i < bins; ++i) {
        fmt::print("r {:.3f}: photons {:.4f}, traced {:.4f}\n", (i + 0.5) * bin_width, measured[i],
                   expected[i]);
        difference += std::abs(measured[i] - expected[i]) * (2 * i + 1);  // weighted by ring area
        total += expected[i] * (2 * i + 1);
    }
    EXPECT_LT(difference / total, 0.05);
    // The focus: the centre is the brightest point of both profiles.
    EXPECT_EQ(std::max_element(measured.begin(), measured.end()) - measured.begin(), 0);
    EXPECT_EQ(std::max_element(expected.begin(), expected.end()) - expected.begin(), 0);
}

// Projection maps aim an area light's caustic photons at the glass: several times more of
// them are stored, and the caustic they draw carries the same power, in total and in its
// bright centre, as without (both are unbiased estimates of the same caustic flux).
TEST(PhotonMapping, AreaLightProjectionMapKeepsTheCausticsPower) {
    auto caustic_map = [](bool projection_maps) {
        BuiltScene b = build(fmt::format(R"(
            glint.render{{ integrator = 'photon', photons = 1, caustic_photons = 200000, seed = 9,
                           projection_maps = {} }}
            glint.quad{{ vertices = {{ {{-0.25, 4, -0.25}}, {{0.25, 4, -0.25}}, {{0.25, 4, 0.25}}, {{-0.25, 4, 0.25}} }},
                        material = glint.emissive{{ radiance = 50 }} }}
            glint.sphere{{ center = {{0, 1, 0}}, radius = 1, material = glint.dielectric{{ ior = 1.5 }} }}
            glint.quad{{ vertices = {{ {{-8, 0, 8}}, {{8, 0, 8}}, {{8, 0, -8}}, {{-8, 0, -8}} }},
                        material = glint.diffuse{{ reflectance = 0.5 }} }}
        )",
                                         projection_maps ? "true" : "false"));
        PhotonIntegrator integrator(b.settings, PhotonSettings::read(b.settings.params));
        integrator.build_maps(*b.scene);
        const PhotonMap& map = integrator.caustic_map();
        double total = 0.0, centre = 0.0;
        for (size_t i = 0; i < map.size(); ++i) {
            if (std::abs(map[i].p.y) > 1e-3f) continue;  // on the floor only
            total += to_rgb(map[i].power).g;
            if (std::hypot(map[i].p.x, map[i].p.z) < 0.3f) centre += to_rgb(map[i].power).g;
        }
        return std::array<double, 3>{static_cast<double>(map.size()), total, centre};
    };
    const auto aimed = caustic_map(true), everywhere = caustic_map(false);
    fmt::print("stored {} vs {}; floor power {:.4f} vs {:.4f}; centre {:.4f} vs {:.4f}\n", aimed[0],
               everywhere[0], aimed[1], everywhere[1], aimed[2], everywhere[2]);
    EXPECT_GT(aimed[0], 3.0 * everywhere[0]);
    EXPECT_NEAR(aimed[1], everywhere[1], 0.03 * everywhere[1]);
    EXPECT_NEAR(aimed[2], everywhere[2], 0.05 * everywhere[2]);
}
