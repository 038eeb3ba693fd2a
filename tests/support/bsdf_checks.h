#pragma once
// Checks shared by the BSDF tests (test_microfacet.cpp, test_principled.cpp): chi-square of
// sample() against pdf() in a magnified view of a lobe, with each sample's f, pdf, flags and
// eta compared with eval() and pdf(); directional albedo by the BSDF's own sampling and by
// quadrature of eval().
#include <glint/core/rng.h>
#include <glint/material/bsdf.h>
#include <glint/material/fresnel.h>
#include <glint/math/frame.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/chi_square.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint::test {

inline std::string describe(const Vec3& wo) {
    return fmt::format("wo = ({:.3f}, {:.3f}, {:.3f})", wo.x, wo.y, wo.z);
}

inline bool close(float a, float b, float relative) {
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + 1e-30f;
}

// A magnified view of the sphere for chi-square tests of sharp lobes. The test's bins are
// equal areas in (cos theta, phi), about 0.1 rad wide at the equator and much coarser in
// angle at the poles, so a lobe of width alpha = 0.0025 falls into one bin and its pdf
// cannot be integrated over that bin accurately. The view maps w to
//   v = R normalize(M F(w)),   F: the frame around the lobe's centre,
//   M = diag(1/s, 1/s, 1): magnifies a cone of half-angle ~s around the centre to ~1 rad,
//   R: turns the centre from the pole to the equator (+x), where the bins are finest;
// densities transform with the Jacobian of the inverse map, d(w)/d(v) = s^2 / |M^-1 u|^3
// with u = R^-1 v (the Jacobian of a linear map of directions, |det| / |A u|^3).
class Zoom {
public:
    Zoom(const Vec3& centre, float scale)
        : m_frame(Frame::from_normal(glm::normalize(centre))), m_scale(scale) {}

    Vec3 to_view(const Vec3& w) const {
        const Vec3 l = m_frame.to_local(w);
        const Vec3 u = glm::normalize(Vec3(l.x / m_scale, l.y / m_scale, l.z));
        return Vec3(u.z, u.x, u.y);
    }
    // The direction seen at v, and d(w)/d(v).
    Vec3 from_view(const Vec3& v, double& jacobian) const {
        const Vec3 m(m_scale * v.y, m_scale * v.z, v.x);
        const double length = glm::length(m);
        jacobian = double(m_scale) * m_scale / (length * length * length);
        return m_frame.to_world(m / static_cast<float>(length));
    }

private:
    Frame m_frame;
    float m_scale;
};

// How much to magnify a lobe of GGX width alpha: about 1 rad in the view.
inline float zoom_scale(float alpha) {
    return std::clamp(2.0f * alpha, 0.02f, 1.0f);
}

enum class Lobe { kAll, kReflection, kTransmission };

struct SamplingCheck {
    test::ChiSquareResult chi_square;
    int inconsistent = 0;
    std::string first_inconsistency;
};

// Chi-square of sample() against pdf() in a zoomed view, restricted to one side of the
// surface when `lobe` says so (then the other side's samples count as failures and its
// density as zero, which keeps the test exact for what remains). Each sample's f, pdf,
// flags and eta are compared with eval(), pdf() and the side it landed on.
inline SamplingCheck check_sampling(const Bsdf& bsdf, const Vec3& wo, const Zoom& zoom, Lobe lobe,
                                    float eta_inside, double significance, int samples = 100000) {
    SamplingCheck check;
    auto wanted = [&](const Vec3& wi) {
        if (lobe == Lobe::kAll) return true;
        return (lobe == Lobe::kReflection) == same_hemisphere(wo, wi);
    };
    auto report = [&](const std::string& what) {
        if (check.inconsistent++ == 0) check.first_inconsistency = what;
    };
    auto sample = [&](const Vec2& u, float u_lobe) -> std::optional<Vec3> {
        const auto s = bsdf.sample(wo, u, u_lobe);
        if (!s) return std::nullopt;
        const Spectrum f = bsdf.eval(wo, s->wi);
        const float pdf = bsdf.pdf(wo, s->wi);
        const bool transmitted = !same_hemisphere(wo, s->wi);
        const float eta = transmitted ? (wo.z > 0.0f ? eta_inside : 1.0f / eta_inside) : 1.0f;
        if (!close(s->pdf, pdf, 2e-4f)) {
            report(fmt::format("pdf {} against pdf() {}", s->pdf, pdf));
        } else if (!close(to_rgb(s->f).r, to_rgb(f).r, 2e-4f) ||
                   !close(to_rgb(s->f).b, to_rgb(f).b, 2e-4f)) {
            report(fmt::format("f {} against eval() {}", to_rgb(s->f).r, to_rgb(f).r));
        } else if (s->is_transmission() != transmitted || !close(s->eta, eta, 1e-6f)) {
            report(fmt::format("flags {} eta {} for wi.z {}", s->flags, s->eta, s->wi.z));
        } else if (std::abs(glm::length(s->wi) - 1.0f) > 1e-4f || s->is_delta()) {
            report("not a unit direction, or a delta lobe");
        }
        if (!wanted(s->wi)) return std::nullopt;
        return zoom.to_view(s->wi);
    };
    auto pdf = [&](const Vec3& v) {
        double jacobian = 0.0;
        const Vec3 wi = zoom.from_view(v, jacobian);
        return wanted(wi) ? bsdf.pdf(wo, wi) * jacobian : 0.0;
    };
    check.chi_square = test::chi_square_directions(sample, pdf, samples, 7, 20, 40, significance);
    return check;
}

inline void expect_sampling_ok(const SamplingCheck& check, const std::string& label) {
    const test::ChiSquareResult& r = check.chi_square;
    EXPECT_TRUE(r.passed) << label << ": " << r.details;
    // The pdf integrates to the fraction of samples produced (those that do not leave
    // through the wrong side), never to more than 1.
    EXPECT_NEAR(r.integrated_pdf, r.sample_fraction, 5e-3) << label << ": " << r.details;
    EXPECT_LE(r.integrated_pdf, 1.0 + 5e-3) << label;
    EXPECT_EQ(check.inconsistent, 0) << label << ": " << check.first_inconsistency;
}

inline Vec3 mirror_direction(const Vec3& wo) {
    return Vec3(-wo.x, -wo.y, wo.z);
}

// The smooth refraction of wo, the centre of the transmission lobe.
inline Vec3 refracted_direction(const Vec3& wo, float eta_inside) {
    const bool outside = wo.z > 0.0f;
    Vec3 wt;
    const bool ok = refract(wo, Vec3(0.0f, 0.0f, outside ? 1.0f : -1.0f),
                            outside ? eta_inside : 1.0f / eta_inside, wt);
    return ok ? wt : -wo;
}

// Mean and standard error of the directional albedo, estimated with the BSDF's own
// sampling (absorbed samples count as 0); transmitted weights are multiplied by eta^2 to
// turn radiance back into energy.
struct Albedo {
    double mean = 0.0;
    double error = 0.0;
};

inline Albedo sampled_albedo(const Bsdf& bsdf, const Vec3& wo, int samples, uint64_t seed,
                             int channel = 0) {
    Rng rng(seed);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < samples; ++i) {
        const auto s = bsdf.sample(wo, Vec2(rng.next_float(), rng.next_float()), rng.next_float());
        double w = 0.0;
        if (s && s->pdf > 0.0f) {
            w = to_rgb(s->f)[channel] * abs_cos_theta(s->wi) / s->pdf;
            if (s->is_transmission()) w *= double(s->eta) * s->eta;
        }
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / samples;
    return {mean, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples)};
}

// The same albedo by a midpoint rule over the sphere in (theta, phi), which does not depend
// on sample() (only for lobes that are not too sharp). Steps in theta rather than cos theta
// resolve lobes around the poles, such as refraction at normal incidence.
inline double quadrature_albedo(const Bsdf& bsdf, const Vec3& wo, float eta_inside = 1.0f) {
    const int ntheta = 720, nphi = 360;
    const double dtheta = M_PI / ntheta, dphi = 2.0 * M_PI / nphi;
    double sum = 0.0;
    for (int i = 0; i < ntheta; ++i) {
        const double theta = (i + 0.5) * dtheta;
        const double z = std::cos(theta), r = std::sin(theta);
        for (int j = 0; j < nphi; ++j) {
            const double phi = (j + 0.5) * dphi;
            const Vec3 wi(static_cast<float>(r * std::cos(phi)),
                          static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
            double energy = to_rgb(bsdf.eval(wo, wi)).r * std::abs(z) * r;
            if (!same_hemisphere(wo, wi)) {
                const double eta = wo.z > 0.0f ? eta_inside : 1.0 / eta_inside;
                energy *= eta * eta;
            }
            sum += energy;
        }
    }
    return sum * dtheta * dphi;
}

}  // namespace glint::test
