// Weighted reservoir sampling on synthetic candidates: the sums it keeps, what a merge
// keeps, that it selects in proportion to weight (chi-square), and that the contribution
// weights of RIS and of reuse give unbiased estimates (and the 1/M weights the documented
// bias when a merged reservoir could not have produced the sample).
#include <glint/core/rng.h>
#include <glint/integrator/realtime/reservoir.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace glint;

namespace {

using IndexReservoir = Reservoir<int>;

// Chi-square statistic of observed counts against expected probabilities.
double chi_square(const std::vector<double>& counts, const std::vector<double>& probabilities,
                  double trials) {
    double chi2 = 0.0;
    for (size_t i = 0; i < counts.size(); ++i) {
        const double expected = probabilities[i] * trials;
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    }
    return chi2;
}

// The chi-square quantile for p = 0.001 at 4 degrees of freedom.
constexpr double kChi2Dof4 = 18.47;

}  // namespace

TEST(Reservoir, KeepsTheWeightSumAndTheCount) {
    IndexReservoir r;
    const std::array<float, 5> weights = {0.5f, 0.0f, 2.0f, 1.25f, 0.25f};
    Rng rng(1);
    for (int i = 0; i < 5; ++i) {
        r.update(i, weights[i], 1.0f + static_cast<float>(i), rng.next_float());
        r.count += 1.0f;
    }
    EXPECT_FLOAT_EQ(r.weight_sum, 4.0f);
    EXPECT_EQ(r.count, 5.0f);
    EXPECT_NE(r.sample, 1);  // weight zero is never chosen
    EXPECT_FLOAT_EQ(r.target, 1.0f + static_cast<float>(r.sample));
    r.finish_uniform();
    EXPECT_FLOAT_EQ(r.W, 4.0f / (5.0f * r.target));

    // Merging: the count adds up, and the other reservoir enters with weight
    // target_here * W * M.
    IndexReservoir other;
    other.update(7, 3.0f, 2.0f, 0.0f);
    other.count = 4.0f;
    other.finish_uniform();  // W = 3 / (4 * 2)
    IndexReservoir merged;
    merged.merge(r, r.target, 0.5f);
    merged.merge(other, 1.5f, 0.5f);
    EXPECT_EQ(merged.count, 9.0f);
    EXPECT_FLOAT_EQ(merged.weight_sum, 4.0f + 1.5f * (3.0f / 8.0f) * 4.0f);
    // A reservoir without a sample still counts its candidates.
    IndexReservoir empty;
    empty.count = 3.0f;
    merged.merge(empty, 1.0f, 0.0f);
    EXPECT_EQ(merged.count, 12.0f);
}

// Streaming selects candidate i with probability w_i / sum(w), and so does streaming the
// candidates into two reservoirs and merging them (with the target as the weights' target).
TEST(Reservoir, SelectsInProportionToWeight) {
    const std::vector<float> weights = {0.3f, 1.0f, 2.2f, 0.5f, 1.5f};
    std::vector<double> probabilities;
    double total = 0.0;
    for (float w : weights) total += w;
    for (float w : weights) probabilities.push_back(w / total);
    const int trials = 100000;
    std::vector<double> streamed(5, 0.0), merged(5, 0.0);
    Rng rng(42);
    for (int t = 0; t < trials; ++t) {
        IndexReservoir r;
        for (int i = 0; i < 5; ++i) r.update(i, weights[i], weights[i], rng.next_float());
        streamed[r.sample] += 1.0;

        // Candidates 0-2 in one, 3-4 in the other; target = weight (source density 1).
        IndexReservoir a, b;
        for (int i = 0; i < 3; ++i) {
            a.update(i, weights[i], weights[i], rng.next_float());
            a.count += 1.0f;
        }
        for (int i = 3; i < 5; ++i) {
            b.update(i, weights[i], weights[i], rng.next_float());
            b.count += 1.0f;
        }
        a.finish_uniform();
        b.finish_uniform();
        IndexReservoir m;
        m.merge(a, a.target, rng.next_float());
        m.merge(b, b.target, rng.next_float());
        merged[m.sample] += 1.0;
    }
    const double chi2_streamed = chi_square(streamed, probabilities, trials);
    const double chi2_merged = chi_square(merged, probabilities, trials);
    std::printf("chi-square (4 dof): streamed %.2f, merged %.2f\n", chi2_streamed, chi2_merged);
    EXPECT_LT(chi2_streamed, kChi2Dof4);
    EXPECT_LT(chi2_merged, kChi2Dof4);
    // A wrong rule (keeping the latest candidate with probability 1/2) fails the same test.
    std::vector<double> wrong(5, 0.0);
    for (int t = 0; t < trials; ++t) {
        int kept = 0;
        for (int i = 1; i < 5; ++i)
            if (rng.next_float() < 0.5f) kept = i;
        wrong[kept] += 1.0;
    }
    EXPECT_GT(chi_square(wrong, probabilities, trials), kChi2Dof4);
}

// A discrete model of ReSTIR on 8 light points: two pixels A and B with different targets
// (B sees only points 0-4: the others are "below its horizon"), each with RIS from a
// uniform source. Pixel A's integral of its target, sum_y pA(y), is estimated by f(y) W with
// (1) RIS alone, (2) A's reservoir merged with B's under the balance-heuristic weights
// (unbiased), and (3) under 1/M weights, which count B's candidates also where B could not
// have produced y: too small, by the documented bias.
TEST(Reservoir, ResamplingWeightsAreUnbiasedAndUniformWeightsAreNot) {
    const std::array<float, 8> target_a = {1.0f, 0.5f, 2.0f, 0.2f, 1.5f, 3.0f, 0.7f, 1.1f};
    const std::array<float, 8> target_b = {0.8f, 1.0f, 1.5f, 0.4f, 2.0f, 0.0f, 0.0f, 0.0f};
    double exact = 0.0;
    for (float t : target_a) exact += t;
    const int candidates = 3, trials = 200000;
    Rng rng(7);
    auto ris = [&](const std::array<float, 8>& target) {
        IndexReservoir r;
        for (int c = 0; c < candidates; ++c) {
            const int y = std::min(7, static_cast<int>(rng.next_float() * 8.0f));
            r.update(y, target[y] * 8.0f, target[y], rng.next_float());  // source pdf 1/8
            r.count += 1.0f;
        }
        r.finish_uniform();
        return r;
    };
    double sum_ris = 0.0, sum_mis = 0.0, sum_uniform = 0.0;
    double sq_ris = 0.0, sq_mis = 0.0, sq_uniform = 0.0;
    for (int t = 0; t < trials; ++t) {
        const IndexReservoir a = ris(target_a), b = ris(target_b);
        const double e_ris = a.has_sample() ? target_a[a.sample] * a.W : 0.0;
        sum_ris += e_ris;
        sq_ris += e_ris * e_ris;

        IndexReservoir m;
        int chosen = -1;
        const float u0 = rng.next_float(), u1 = rng.next_float();
        if (m.merge(a, a.target, u0)) chosen = 0;
        if (m.merge(b, b.has_sample() ? target_a[b.sample] : 0.0f, u1)) chosen = 1;
        double e_mis = 0.0, e_uniform = 0.0;
        if (chosen >= 0) {
            const int y = m.sample;
            IndexReservoir weighted = m, uniform = m;
            const float own[2] = {target_a[y], target_b[y]};
            weighted.finish_weighted(own[chosen] / (a.count * own[0] + b.count * own[1]));
            uniform.finish_uniform();
            e_mis = target_a[y] * weighted.W;
            e_uniform = target_a[y] * uniform.W;
        }
        sum_mis += e_mis;
        sq_mis += e_mis * e_mis;
        sum_uniform += e_uniform;
        sq_uniform += e_uniform * e_uniform;
    }
    auto mean = [&](double s) { return s / trials; };
    auto error = [&](double s, double sq) {
        const double m = s / trials;
        return std::sqrt((sq / trials - m * m) / trials);
    };
    std::printf("exact %.4f: RIS %.4f +- %.4f, balance heuristic %.4f +- %.4f, 1/M %.4f +- %.4f\n",
                exact, mean(sum_ris), error(sum_ris, sq_ris), mean(sum_mis), error(sum_mis, sq_mis),
                mean(sum_uniform), error(sum_uniform, sq_uniform));
    EXPECT_NEAR(mean(sum_ris), exact, 4.0 * error(sum_ris, sq_ris));
    EXPECT_NEAR(mean(sum_mis), exact, 4.0 * error(sum_mis, sq_mis));
    // B cannot produce points 5-7, which carry 4.8 / 10 of A's integral: the 1/M estimate
    // loses about half of that share.
    EXPECT_LT(mean(sum_uniform), exact - 10.0 * error(sum_uniform, sq_uniform));
}
