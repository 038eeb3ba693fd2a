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

// A rectangle in (z = cos theta, phi).
struct Cell {
    double z0, z1, phi0, phi1;
};

struct CellEstimate {
    double integral = 0.0;
    double bound = 0.0;  // largest value times the area
    bool jump_z = false, jump_phi = false;
};

// Midpoint rule on an 8x8 grid, and whether the density looks continuous there. An open
// rule on purpose: densities often jump exactly on bin edges (a hemisphere at z = 0, a
// cone at its angle), and a closed rule such as Simpson's, which evaluates on the edges,
// counts the jump with the wrong weight. The edges are evaluated too, but only to look for
// jumps: one between the edge and the first row of midpoints is missed otherwise.
CellEstimate midpoint_rule(const DirectionPdf& pdf, const Cell& c) {
    constexpr int kN = 8;
    const double hz = (c.z1 - c.z0) / kN, hphi = (c.phi1 - c.phi0) / kN;
    // Index 0 and kN + 1 are the edges, 1..kN the midpoints.
    auto coordinate = [](double lo, double h, int i) {
        return i == 0 ? lo : (i == kN + 1 ? lo + kN * h : lo + (i - 0.5) * h);
    };
    double values[kN + 2][kN + 2];
    double sum = 0.0, largest = 0.0;
    for (int a = 0; a < kN + 2; ++a) {
        const double z = coordinate(c.z0, hz, a);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        for (int b = 0; b < kN + 2; ++b) {
            const double phi = coordinate(c.phi0, hphi, b);
            const Vec3 w(static_cast<float>(r * std::cos(phi)),
                         static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
            values[a][b] = pdf(w);
            largest = std::max(largest, std::abs(values[a][b]));
            if (a > 0 && a <= kN && b > 0 && b <= kN) sum += values[a][b];
        }
    }
    // A jump between neighbouring points much larger than a smooth density's variation
    // over one grid step marks an edge inside the cell.
    double jump_z = 0.0, jump_phi = 0.0;
    for (int a = 0; a < kN + 2; ++a) {
        for (int b = 0; b < kN + 2; ++b) {
            if (a + 1 < kN + 2)
                jump_z = std::max(jump_z, std::abs(values[a + 1][b] - values[a][b]));
            if (b + 1 < kN + 2)
                jump_phi = std::max(jump_phi, std::abs(values[a][b + 1] - values[a][b]));
        }
    }
    const double area = (c.z1 - c.z0) * (c.phi1 - c.phi0);
    return {sum * hz * hphi, largest * area, jump_z > 0.2 * largest, jump_phi > 0.2 * largest};
}

// Adaptive integration: cells holding a jump of the density (the edge of a light or a cone
// cutting through a bin) are split across the jump, so such edges cost accuracy only in
// ever smaller cells. Splitting along one axis only resolves edges of constant z or phi,
// whose errors would otherwise add up with the same sign in every bin along the edge,
// finely and cheaply; slanted edges, whose errors are of both signs, stop at a coarser
// level. Cells too light to matter (`tolerance`, a probability) are not split. Down to
// `forced_depth` every cell is split, to find features smaller than the grid.
double integrate_cell(const DirectionPdf& pdf, const Cell& c, double tolerance, int depth,
                      int forced_depth) {
    constexpr int kMaxDepth = 12;  // halvings of the bin, counting each axis
    const CellEstimate e = midpoint_rule(pdf, c);
    const bool forced = depth < forced_depth;
    const int splits = forced ? 2 : (e.jump_z ? 1 : 0) + (e.jump_phi ? 1 : 0);
    if (!forced && (splits == 0 || depth + splits > kMaxDepth || e.bound <= tolerance)) {
        return e.integral;
    }
    const double zm = forced || e.jump_z ? 0.5 * (c.z0 + c.z1) : c.z1;
    const double pm = forced || e.jump_phi ? 0.5 * (c.phi0 + c.phi1) : c.phi1;
    const Cell parts[4] = {{c.z0, zm, c.phi0, pm},
                           {zm, c.z1, c.phi0, pm},
                           {c.z0, zm, pm, c.phi1},
                           {zm, c.z1, pm, c.phi1}};
    double sum = 0.0;
    for (const Cell& part : parts) {
        if (part.z1 > part.z0 && part.phi1 > part.phi0) {
            sum += integrate_cell(pdf, part, std::ldexp(tolerance, -splits), depth + splits,
                                  forced_depth);
        }
    }
    return sum;
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
        const int zi =
            std::min(cos_theta_bins - 1, static_cast<int>((z + 1.0) * 0.5 * cos_theta_bins));
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
    // the pdf over its (z, phi) rectangle.
    std::vector<double> expected(bins, 0.0);
    double total_pdf = 0.0;
    const double dz = 2.0 / cos_theta_bins, dphi = 2.0 * M_PI / phi_bins;
    const double tolerance = 0.01 / sample_count;  // a hundredth of a sample per bin
    for (int zi = 0; zi < cos_theta_bins; ++zi) {
        for (int pi = 0; pi < phi_bins; ++pi) {
            const Cell bin{-1.0 + zi * dz, -1.0 + (zi + 1) * dz, pi * dphi, (pi + 1) * dphi};
            double integral = integrate_cell(pdf, bin, tolerance, 0, 0);
            // Samples where the grid saw no density: look again, finely, for a sliver of
            // the pdf's support (a light seen edge-on) between the grid points.
            if (integral == 0.0 && observed[zi * phi_bins + pi] > 0.0) {
                integral = integrate_cell(pdf, bin, tolerance, 0, 8);
            }
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
                return {
                    false, 0.0, total_pdf, double(successes) / sample_count,
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
    result.details = fmt::format(
        "chi2 = {:.2f}, dof = {}, p = {:.4g}, integral of pdf = {:.5f}, "
        "sample fraction = {:.5f}",
        chi2, dof, result.p_value, total_pdf, result.sample_fraction);
    return result;
}

}  // namespace glint::test
