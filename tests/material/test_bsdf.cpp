// The BSDF contract (material/bsdf.h) for the diffuse, mirror and smooth glass lobes:
// sampling against pdf (chi-square), eval/pdf/sample consistency, energy, reciprocity, and
// the Fresnel and Snell laws against closed forms written independently of fresnel.h.
#include <glint/core/rng.h>
#include <glint/material/fresnel.h>
#include <glint/material/lambertian.h>
#include <glint/material/smooth_dielectric.h>
#include <glint/material/specular_reflection.h>
#include <glint/math/warp.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>
#include <support/test_util.h>

#include <cmath>
#include <string>
#include <vector>

using namespace glint;
using glint::test::direction;

namespace {

float sin_theta(const Vec3& w) {
    return std::sqrt(std::max(0.0f, w.x * w.x + w.y * w.y));
}

// Exact unpolarised Fresnel reflectance in Fresnel's angle form, in double precision:
// r_s = -sin(i - t) / sin(i + t), r_p = tan(i - t) / tan(i + t), with Snell's law for t.
// `cos_i` > 0: light arrives from outside (index 1) onto the inside (index eta).
double fresnel_reference(double cos_i, double eta) {
    double n1 = 1.0, n2 = eta;
    if (cos_i < 0.0) {
        std::swap(n1, n2);
        cos_i = -cos_i;
    }
    const double theta_i = std::acos(std::min(1.0, cos_i));
    const double sin_t = n1 / n2 * std::sin(theta_i);
    if (sin_t >= 1.0) return 1.0;
    if (theta_i == 0.0) return std::pow((n2 - n1) / (n2 + n1), 2.0);
    const double theta_t = std::asin(sin_t);
    const double rs = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
    const double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Path weight f |cos wi| / pdf of a sample, first channel.
float weight(const BsdfSample& s) {
    return to_rgb(s.f).r * abs_cos_theta(s.wi) / s.pdf;
}

}  // namespace

TEST(LambertianBsdf, SamplingMatchesPdf) {
    const LambertianBsdf bsdf(uplift(Rgb(0.7f, 0.5f, 0.3f), RgbRole::unbounded));
    const std::vector<Vec3> outgoing = {direction(0.0f), direction(35.0f), direction(84.0f),
                                        direction(20.0f, 2.0f, true), direction(70.0f, 4.0f, true)};
    for (const Vec3& wo : outgoing) {
        int inconsistent = 0;
        auto sample = [&](const Vec2& u, float u_lobe) -> std::optional<Vec3> {
            const auto s = bsdf.sample(wo, u, u_lobe);
            if (!s) return std::nullopt;
            // The sample's own f and pdf are what eval() and pdf() say for its direction,
            // and it reflects on the viewer's side (two-sided).
            const float pdf = bsdf.pdf(wo, s->wi);
            const Spectrum f = bsdf.eval(wo, s->wi);
            if (std::abs(s->pdf - pdf) > 1e-5f * pdf || !(s->f == f) ||
                !same_hemisphere(wo, s->wi) || s->flags != (kBsdfReflection | kBsdfDiffuse)) {
                ++inconsistent;
            }
            return s->wi;
        };
        auto pdf = [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); };
        const auto result =
            test::chi_square_directions(sample, pdf, 200000, 21, 20, 40, 0.01 / outgoing.size());
        EXPECT_TRUE(result.passed) << "wo.z = " << wo.z << ": " << result.details;
        EXPECT_NEAR(result.integrated_pdf, 1.0, 1e-3);
        EXPECT_EQ(result.sample_fraction, 1.0);
        EXPECT_EQ(inconsistent, 0) << "wo.z = " << wo.z;
    }
}

// The directional albedo, integral of f |cos wi| over the sphere by stratified Monte
// Carlo in (cos theta, phi), equals the reflectance; the sampling estimator agrees.
TEST(LambertianBsdf, AlbedoEqualsReflectance) {
    const Spectrum reflectance = uplift(Rgb(0.9f, 0.5f, 0.1f), RgbRole::unbounded);
    const LambertianBsdf bsdf(reflectance);
    Rng rng(4);
    for (const Vec3& wo : {direction(10.0f), direction(60.0f), direction(45.0f, 1.0f, true)}) {
        constexpr int kStrata = 400;
        double albedo[3] = {0, 0, 0};
        for (int i = 0; i < kStrata; ++i) {
            for (int j = 0; j < kStrata; ++j) {
                const Vec2 u((i + rng.next_float()) / kStrata, (j + rng.next_float()) / kStrata);
                const Vec3 wi = warp::square_to_uniform_sphere(u);
                const Spectrum f = bsdf.eval(wo, wi);
                for (int c = 0; c < 3; ++c) {
                    albedo[c] += to_rgb(f)[c] * abs_cos_theta(wi) / warp::uniform_sphere_pdf();
                }
            }
        }
        double sampled = 0.0;
        constexpr int kSamples = 10000;
        for (int i = 0; i < kSamples; ++i) {
            const auto s =
                bsdf.sample(wo, Vec2(rng.next_float(), rng.next_float()), rng.next_float());
            ASSERT_TRUE(s.has_value());
            sampled += weight(*s);
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(albedo[c] / (kStrata * kStrata), to_rgb(reflectance)[c],
                        0.01 * to_rgb(reflectance)[c])
                << "channel " << c << ", wo.z = " << wo.z;
        }
        EXPECT_NEAR(sampled / kSamples, to_rgb(reflectance).r, 1e-4);
    }
}

TEST(LambertianBsdf, ReciprocalAndZeroAcrossTheSurface) {
    const LambertianBsdf bsdf(Spectrum(0.6f));
    Rng rng(5);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 a = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 b = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        EXPECT_TRUE(bsdf.eval(a, b) == bsdf.eval(b, a));
        if (!same_hemisphere(a, b)) {
            EXPECT_TRUE(bsdf.eval(a, b).is_black());
            EXPECT_EQ(bsdf.pdf(a, b), 0.0f);
        } else {
            EXPECT_NEAR(to_rgb(bsdf.eval(a, b)).r, 0.6f / kPi, 1e-6f);
        }
    }
    // A grazing viewer exactly in the surface gets nothing rather than a NaN.
    EXPECT_FALSE(bsdf.sample(Vec3(1, 0, 0), Vec2(0.3f, 0.6f), 0.5f).has_value());
}

// Light sampling takes f and pdf from one eval_pdf() call: it must give exactly what eval()
// and pdf() give, on both sides of the surface.
TEST(LambertianBsdf, EvalPdfGivesEvalAndPdfBitForBit) {
    const LambertianBsdf bsdf(uplift(Rgb(0.2f, 0.5f, 0.9f), RgbRole::unbounded));
    Rng rng(17);
    int across = 0;
    for (int i = 0; i < 10000; ++i) {
        const Vec3 wo = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 wi = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        float pdf = -1.0f;
        const Spectrum f = bsdf.eval_pdf(wo, wi, pdf);
        const Spectrum expected = bsdf.eval(wo, wi);
        ASSERT_EQ(pdf, bsdf.pdf(wo, wi));
        ASSERT_EQ(to_rgb(f).r, to_rgb(expected).r);
        ASSERT_EQ(to_rgb(f).g, to_rgb(expected).g);
        ASSERT_EQ(to_rgb(f).b, to_rgb(expected).b);
        across += !same_hemisphere(wo, wi);
    }
    EXPECT_GT(across, 1000);  // both branches were taken
}

TEST(SpecularReflectionBsdf, MirrorDirectionWithTintWeight) {
    const Spectrum tint = uplift(Rgb(0.9f, 0.6f, 0.25f), RgbRole::unbounded);
    const SpecularReflectionBsdf bsdf(tint);
    for (const Vec3& wo :
         {direction(0.0f), direction(45.0f), direction(89.0f), direction(30.0f, 2.0f, true)}) {
        const auto s = bsdf.sample(wo, Vec2(0.2f, 0.9f), 0.4f);
        ASSERT_TRUE(s.has_value());
        EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
        EXPECT_TRUE(s->is_delta());
        EXPECT_FALSE(s->is_transmission());
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(to_rgb(s->f)[c] * abs_cos_theta(s->wi) / s->pdf, to_rgb(tint)[c],
                        1e-5f * to_rgb(tint)[c]);
        }
        // Delta lobes have no density and no value for any given pair of directions.
        EXPECT_TRUE(bsdf.eval(wo, s->wi).is_black());
        EXPECT_EQ(bsdf.pdf(wo, s->wi), 0.0f);
    }
    EXPECT_TRUE(bsdf.is_delta());
}

TEST(SmoothDielectricBsdf, FresnelAtNormalIncidence) {
    for (float eta : {1.33f, 1.5f, 2.4f, 1.0f / 1.5f}) {
        const float expected = sqr((eta - 1.0f) / (eta + 1.0f));
        EXPECT_NEAR(fresnel_dielectric(1.0f, eta), expected, 1e-6f) << eta;
        EXPECT_NEAR(fresnel_dielectric(-1.0f, eta), expected, 1e-6f) << eta;
    }
    EXPECT_NEAR(fresnel_dielectric(0.7f, 1.0f), 0.0f, 1e-7f);  // index matched: no interface
}

TEST(SmoothDielectricBsdf, FresnelMatchesAngleForm) {
    for (float eta : {1.33f, 1.5f, 2.4f}) {
        for (int i = 1; i < 1000; ++i) {
            // The reference takes the same float input, and the tolerance allows for float
            // rounding next to the critical angle, where R has an infinite slope. (Schlick's
            // approximation is off by around 1e-2.)
            const float cos_i = i / 1000.0f;
            for (float signed_cos : {cos_i, -cos_i}) {
                EXPECT_NEAR(fresnel_dielectric(signed_cos, eta), fresnel_reference(signed_cos, eta),
                            1e-5)
                    << "eta " << eta << ", cos " << signed_cos;
            }
        }
        // Light crossing the interface in either direction sees the same reflectance.
        for (double degrees : {10.0, 40.0, 70.0, 80.0}) {
            const double sin_t = std::sin(glm::radians(degrees)) / eta;
            const float cos_o = static_cast<float>(std::cos(glm::radians(degrees)));
            const float cos_t = static_cast<float>(std::sqrt(1.0 - sin_t * sin_t));
            EXPECT_NEAR(fresnel_dielectric(cos_o, eta), fresnel_dielectric(-cos_t, eta), 1e-5f)
                << degrees;
        }
        EXPECT_NEAR(fresnel_dielectric(1e-7f, eta), 1.0f, 1e-5f);  // grazing
    }
}

// Reflection is chosen with probability F and transmission 1 - F; transmitted directions obey
// Snell's law; each sample's weight is 1 for reflection and 1/eta^2 for transmission, so the
// mean weight is R + T / eta^2.
TEST(SmoothDielectricBsdf, LobeChoiceSnellAndEnergy) {
    const float eta = 1.5f;
    const SmoothDielectricBsdf bsdf(eta);
    const float critical = glm::degrees(std::asin(1.0f / eta));  // about 41.8 degrees
    struct Case {
        float degrees;
        bool inside;
    };
    const Case cases[] = {{0, false}, {30, false}, {60, false}, {85, false},
                          {0, true},  {20, true},  {35, true},  {critical - 1.0f, true}};
    Rng rng(9);
    constexpr int kSamples = 100000;
    for (const Case& c : cases) {
        const Vec3 wo = direction(c.degrees, 1.3f, c.inside);
        const double reflectance = fresnel_reference(cos_theta(wo), eta);
        const float eta_rel = c.inside ? 1.0f / eta : eta;  // n(wi side) / n(wo side) on refraction
        int reflected = 0, bad = 0;
        double weight_sum = 0.0;
        for (int i = 0; i < kSamples; ++i) {
            const auto s =
                bsdf.sample(wo, Vec2(rng.next_float(), rng.next_float()), rng.next_float());
            ASSERT_TRUE(s.has_value());
            weight_sum += weight(*s);
            if (!s->is_transmission()) {
                ++reflected;
                if (std::abs(s->pdf - reflectance) > 1e-5 || std::abs(weight(*s) - 1.0f) > 1e-5f ||
                    s->wi != Vec3(-wo.x, -wo.y, wo.z) || s->eta != 1.0f) {
                    ++bad;
                }
                continue;
            }
            // Snell: n_o sin(theta_o) = n_i sin(theta_i), on the other side, azimuth turned by pi.
            const float n_o = c.inside ? eta : 1.0f, n_i = c.inside ? 1.0f : eta;
            const bool snell = std::abs(n_o * sin_theta(wo) - n_i * sin_theta(s->wi)) < 2e-6f;
            const bool opposite = s->wi.z * wo.z < 0.0f;
            const bool azimuth = glm::dot(Vec2(s->wi), Vec2(wo)) <= 1e-6f * sin_theta(wo);
            const bool unit = std::abs(glm::length(s->wi) - 1.0f) < 1e-5f;
            const bool flags = s->is_delta() && std::abs(s->eta - eta_rel) < 1e-6f;
            const bool weighted = std::abs(s->pdf - (1.0 - reflectance)) < 1e-5 &&
                                  std::abs(weight(*s) - 1.0f / (eta_rel * eta_rel)) < 1e-5f;
            if (!(snell && opposite && azimuth && unit && flags && weighted)) ++bad;
        }
        EXPECT_EQ(bad, 0) << c.degrees << (c.inside ? " inside" : " outside");
        const double sigma = std::sqrt(kSamples * reflectance * (1.0 - reflectance));
        EXPECT_NEAR(reflected, kSamples * reflectance, 4.0 * sigma + 1.0)
            << c.degrees << (c.inside ? " inside" : " outside");
        const double expected_weight = reflectance + (1.0 - reflectance) / (eta_rel * eta_rel);
        const double weight_sigma = std::abs(1.0 - 1.0 / (eta_rel * eta_rel)) * sigma / kSamples;
        EXPECT_NEAR(weight_sum / kSamples, expected_weight, 4.0 * weight_sigma + 1e-6)
            << c.degrees << (c.inside ? " inside" : " outside");
    }
}

TEST(SmoothDielectricBsdf, TotalInternalReflection) {
    const float eta = 1.5f;
    const SmoothDielectricBsdf bsdf(eta);
    const float one_minus = std::nextafter(1.0f, 0.0f);
    for (float degrees : {42.5f, 50.0f, 70.0f, 89.5f}) {
        const Vec3 wo = direction(degrees, 0.4f, true);
        for (float u_lobe : {0.0f, 0.5f, 0.99f, one_minus}) {
            const auto s = bsdf.sample(wo, Vec2(0.5f), u_lobe);
            ASSERT_TRUE(s.has_value()) << degrees;
            EXPECT_FALSE(s->is_transmission()) << degrees;
            EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
            EXPECT_NEAR(s->pdf, 1.0f, 1e-6f);
            EXPECT_NEAR(weight(*s), 1.0f, 1e-5f);
        }
    }
}

// Generalised reciprocity (Veach 1997, sec. 5.2): as distributions eval(wo, wi) / n_o^2 =
// eval(wi, wo) / n_i^2, with n_o the index on wo's side. The delta about the refracted
// direction carries the Jacobian d(omega_i)/d(omega_o) = n_o^2 cos_o / (n_i^2 cos_i), so in
// terms of the sampled coefficients c(wo -> wi) = f |cos wi| it reads
// c(wo -> wi) n_i^4 = c(wi -> wo) n_o^4. Transmission back from wi also returns to wo.
TEST(SmoothDielectricBsdf, GeneralisedReciprocityOfTransmission) {
    const float eta = 1.5f;
    const SmoothDielectricBsdf bsdf(eta);
    const float transmit = std::nextafter(1.0f, 0.0f);  // u_lobe above any reflectance < 1
    for (float degrees : {0.0f, 25.0f, 50.0f, 75.0f, 88.0f}) {
        for (bool inside : {false, true}) {
            const Vec3 wo = direction(inside ? degrees * 0.45f : degrees, 2.2f, inside);
            const auto forward = bsdf.sample(wo, Vec2(0.5f), transmit);
            ASSERT_TRUE(forward.has_value() && forward->is_transmission()) << degrees;
            const Vec3 wi = forward->wi;
            const auto backward = bsdf.sample(wi, Vec2(0.5f), transmit);
            ASSERT_TRUE(backward.has_value() && backward->is_transmission()) << degrees;
            EXPECT_NEAR(backward->wi.x, wo.x, 1e-5f);
            EXPECT_NEAR(backward->wi.y, wo.y, 1e-5f);
            EXPECT_NEAR(backward->wi.z, wo.z, 1e-5f);
            const float n_o = inside ? eta : 1.0f, n_i = inside ? 1.0f : eta;
            const double c_forward = to_rgb(forward->f).r * abs_cos_theta(wi);
            const double c_backward = to_rgb(backward->f).r * abs_cos_theta(wo);
            EXPECT_NEAR(c_forward * std::pow(n_i, 4.0) / (c_backward * std::pow(n_o, 4.0)), 1.0,
                        1e-4)
                << degrees << (inside ? " inside" : " outside");
        }
    }
}
