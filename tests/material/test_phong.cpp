// The modified Phong BSDF: sampling against pdf, energy conservation, reciprocity.
#include <glint/core/rng.h>
#include <glint/material/phong.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>

#include <cmath>
#include <vector>

using namespace glint;

namespace {

Vec3 at_angle(float degrees, float phi = 0.3f, bool below = false) {
    const float theta = glm::radians(degrees);
    const Vec3 w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    return below ? Vec3(w.x, w.y, -w.z) : w;
}

// Directional albedo: integral of f |cos wi| over the sphere, midpoint rule in (z, phi).
double albedo(const Bsdf& bsdf, const Vec3& wo) {
    const int nz = 400, nphi = 400;
    double sum = 0.0;
    for (int i = 0; i < nz; ++i) {
        const double z = -1.0 + (i + 0.5) * 2.0 / nz;
        const double r = std::sqrt(1.0 - z * z);
        for (int j = 0; j < nphi; ++j) {
            const double phi = (j + 0.5) * 2.0 * M_PI / nphi;
            const Vec3 wi(static_cast<float>(r * std::cos(phi)),
                          static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
            sum += to_rgb(bsdf.eval(wo, wi)).r * std::abs(z);
        }
    }
    return sum * (2.0 / nz) * (2.0 * M_PI / nphi);
}

}  // namespace

TEST(PhongBsdf, SamplingMatchesPdf) {
    struct Case {
        float diffuse, specular, exponent;
    };
    const Case cases[] = {{0.5f, 0.4f, 20.0f}, {0.0f, 0.9f, 200.0f}, {0.8f, 0.1f, 1.0f}};
    const std::vector<Vec3> outgoing = {at_angle(0.0f), at_angle(45.0f), at_angle(80.0f),
                                        at_angle(30.0f, 2.0f, true)};
    for (const Case& c : cases) {
        const PhongBsdf bsdf(Spectrum(c.diffuse), Spectrum(c.specular), c.exponent);
        for (const Vec3& wo : outgoing) {
            int inconsistent = 0;
            auto sample = [&](const Vec2& u, float u_lobe) -> std::optional<Vec3> {
                const auto s = bsdf.sample(wo, u, u_lobe);
                if (!s) return std::nullopt;
                if (std::abs(s->pdf - bsdf.pdf(wo, s->wi)) > 1e-4f * s->pdf ||
                    !same_hemisphere(wo, s->wi)) {
                    ++inconsistent;
                }
                return s->wi;
            };
            auto pdf = [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); };
            const auto result =
                test::chi_square_directions(sample, pdf, 200000, 5, 20, 40, 0.01 / 12);
            EXPECT_TRUE(result.passed)
                << "exponent " << c.exponent << ", wo.z " << wo.z << ": " << result.details;
            // Lobe samples that dip below the surface are dropped: the pdf integrates to
            // exactly the fraction of samples that survive.
            EXPECT_NEAR(result.integrated_pdf, result.sample_fraction, 5e-3) << result.details;
            EXPECT_EQ(inconsistent, 0);
        }
    }
}

// kd + ks <= 1 never reflects more than it receives, at any angle; at normal incidence
// the whole lobe is above the surface and the albedo is exactly kd + ks.
TEST(PhongBsdf, ConservesEnergy) {
    const PhongBsdf bsdf(Spectrum(0.6f), Spectrum(0.4f), 30.0f);
    EXPECT_NEAR(albedo(bsdf, at_angle(0.0f)), 1.0, 0.01);
    for (float degrees : {20.0f, 50.0f, 75.0f, 89.0f}) {
        EXPECT_LE(albedo(bsdf, at_angle(degrees)), 1.0 + 1e-3) << degrees << " degrees";
    }
    const PhongBsdf sharp(Spectrum(0.0f), Spectrum(1.0f), 1000.0f);
    EXPECT_LE(albedo(sharp, at_angle(60.0f)), 1.0 + 1e-2);
}

TEST(PhongBsdf, ReciprocalAndOneSidedPerHemisphere) {
    const PhongBsdf bsdf(Spectrum(0.3f), Spectrum(0.5f), 15.0f);
    Rng rng(3);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 a = at_angle(rng.next_float() * 89.0f, rng.next_float() * 6.28f);
        const Vec3 b = at_angle(rng.next_float() * 89.0f, rng.next_float() * 6.28f);
        EXPECT_NEAR(to_rgb(bsdf.eval(a, b)).r, to_rgb(bsdf.eval(b, a)).r,
                    1e-4f * (1.0f + to_rgb(bsdf.eval(a, b)).r));
        EXPECT_EQ(to_rgb(bsdf.eval(a, Vec3(b.x, b.y, -b.z))).r, 0.0f);
    }
}
