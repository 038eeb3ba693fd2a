#include <glint/core/rng.h>

#include <fmt/format.h>
#include <support/chi_square.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace glint::test {
namespace {

// Regularised lower incomplete gamma P(a, x) by its series, upper Q(a, x) by the continued
// fraction (Numerical Recipes' split), each where it converges fast.
double gamma_p_series(double a, double x) {
    double sum = 1.0 / a, term = sum;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double gamma_q_fraction(double a, double x) {
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chi_square_upper_tail(double statistic, int dof) {
    if (statistic <= 0.0) return 1.0;
    const double a = 0.5 * dof, x = 0.5 * statistic;
    return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

ChiSquareResult chi_square_directions(const DirectionSampler& sample, const DirectionPdf& pdf,
                                      int sample_count, uint64_t seed, int cos_theta_bins,
                                      int phi_bins, double significance) {
    const int bins = cos_theta_bins * phi_bins;
    auto bin_of = [&](const Vec3& w) {
        const double z = std::clamp(static_cast<double>(w.z), -1.0, 1.0);
        double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
        if (phi < 0.0) phi += 2.0 * M_PI;
        const int zi = std::min(cos_theta_bins - 1, static_cast<int>((z + 1.0) * 0.5 * cos_theta_bins));
        const int pi = std::min(phi_bins - 1, static_cast<int>(phi / (2.0 * M_PI) * phi_bins));
        return zi * phi_bins + pi;
    };

    std::vector<double> observed(bins, 0.0);
    Rng rng(seed);
    int successes = 0;
    for (int i = 0; i < sample_count; ++i) {
        const Vec2 u(rng.next_float(), rng.next_float());
        const float u_extra = rng.next_float();
        const std::optional<Vec3> w = sample(u, u_extra);
        if (!w) continue;
        ++successes;
        observed[bin_of(*w)] += 1.0;
    }

    // The map (z, phi) -> sphere preserves area, so a bin's probability is the integral of
    // the pdf over its (z, phi) rectangle; Simpson's rule on a fine grid inside each bin.
    constexpr int kSub = 8;
    std::vector<double> expected(bins, 0.0);
    double total_pdf = 0.0;
    const double dz = 2.0 / cos_theta_bins, dphi = 2.0 * M_PI / phi_bins;
    for (int zi = 0; zi < cos_theta_bins; ++zi) {
        for (int pi = 0; pi < phi_bins; ++pi) {
            double integral = 0.0;
            for (int a = 0; a <= 2 * kSub; ++a) {
                const double wa = (a == 0 || a == 2 * kSub) ? 1.0 : (a % 2 ? 4.0 : 2.0);
                const double z = -1.0 + zi * dz + a * dz / (2 * kSub);
                for (int b = 0; b <= 2 * kSub; ++b) {
                    const double wb = (b == 0 || b == 2 * kSub) ? 1.0 : (b % 2 ? 4.0 : 2.0);
                    const double phi = pi * dphi + b * dphi / (2 * kSub);
                    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    const Vec3 w(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                                 static_cast<float>(z));
                    integral += wa * wb * pdf(w);
                }
            }
            integral *= (dz / (6.0 * kSub)) * (dphi / (6.0 * kSub));
            expected[zi * phi_bins + pi] = integral * sample_count;
            total_pdf += integral;
        }
    }

    // Pool bins expected to hold fewer than 5 samples, as the test requires.
    std::vector<int> order(bins);
    for (int i = 0; i < bins; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
    double chi2 = 0.0, pooled_observed = 0.0, pooled_expected = 0.0;
    int dof = -1;
    std::string worst;
    for (int i : order) {
        if (expected[i] == 0.0) {
            if (observed[i] > 0.0) {
                return {false, 0.0, total_pdf, double(successes) / sample_count,
                        fmt::format("{} samples fell in bin {} where the pdf is zero", observed[i], i)};
            }
            continue;
        }
        if (expected[i] < 5.0) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        const double diff = observed[i] - expected[i];
        chi2 += diff * diff / expected[i];
        ++dof;
    }
    if (pooled_expected > 0.0) {
        const double diff = pooled_observed - pooled_expected;
        chi2 += diff * diff / pooled_expected;
        ++dof;
    }
    ChiSquareResult result;
    result.integrated_pdf = total_pdf;
    result.sample_fraction = double(successes) / sample_count;
    result.p_value = dof > 0 ? chi_square_upper_tail(chi2, dof) : 1.0;
    result.passed = result.p_value > significance;
    result.details = fmt::format("chi2 = {:.2f}, dof = {}, p = {:.4g}, integral of pdf = {:.5f}, "
                                 "sample fraction = {:.5f}",
                                 chi2, dof, result.p_value, total_pdf, result.sample_fraction);
    return result;
}

}  // namespace glint::test
