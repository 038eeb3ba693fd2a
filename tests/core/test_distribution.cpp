#include <glint/core/distribution.h>
#include <glint/core/error.h>
#include <glint/core/rng.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace glint {
namespace {

TEST(Distribution1D, IntegralAndPmf) {
    const Distribution1D d({1.0f, 3.0f, 0.0f, 4.0f});
    EXPECT_EQ(d.size(), 4u);
    EXPECT_FLOAT_EQ(d.integral(), 2.0f);  // mean bin height over [0, 1)
    EXPECT_FLOAT_EQ(d.pmf(0), 0.125f);
    EXPECT_FLOAT_EQ(d.pmf(1), 0.375f);
    EXPECT_FLOAT_EQ(d.pmf(2), 0.0f);
    EXPECT_FLOAT_EQ(d.pmf(3), 0.5f);
    EXPECT_FLOAT_EQ(d.pmf(4), 0.0f);
    EXPECT_FLOAT_EQ(d.pdf(0.3f), 1.5f);  // bin 1: 3 / 2
    EXPECT_FLOAT_EQ(d.pdf(0.6f), 0.0f);
    EXPECT_FLOAT_EQ(d.pdf(1.0f), 0.0f);
}

TEST(Distribution1D, ContinuousInvertsTheCdf) {
    const Distribution1D d({1.0f, 3.0f, 0.0f, 4.0f});
    // cdf edges: 0, 1/8, 1/2, 1/2, 1; u = 0.3125 lies halfway through bin 1.
    const auto s = d.sample_continuous(0.3125f);
    EXPECT_EQ(s.index, 1u);
    EXPECT_FLOAT_EQ(s.x, 0.25f + 0.5f * 0.25f);
    EXPECT_FLOAT_EQ(s.pdf, 1.5f);
    // Exactly on the edge of the empty bin: the sample must skip it.
    const auto edge = d.sample_continuous(0.5f);
    EXPECT_EQ(edge.index, 3u);
    EXPECT_FLOAT_EQ(edge.x, 0.75f);
    // u at or beyond 1, and NaN, stay inside [0, 1).
    EXPECT_LT(d.sample_continuous(1.0f).x, 1.0f);
    EXPECT_EQ(d.sample_continuous(1.0f).index, 3u);
    EXPECT_EQ(d.sample_continuous(std::nanf("")).index, 0u);
}

TEST(Distribution1D, DiscreteFrequenciesMatchPmf) {
    const std::vector<float> values = {0.5f, 0.0f, 2.0f, 1.0f, 0.0f, 4.5f};
    const Distribution1D d(values);
    std::vector<double> counts(values.size(), 0.0);
    Rng rng(7);
    constexpr int kSamples = 200000;
    for (int i = 0; i < kSamples; ++i) {
        const auto s = d.sample_discrete(rng.next_float());
        ASSERT_LT(s.index, values.size());
        EXPECT_GT(s.pmf, 0.0f);
        EXPECT_GE(s.u_remapped, 0.0f);
        EXPECT_LT(s.u_remapped, 1.0f);
        counts[s.index] += 1.0;
    }
    // Chi-square over the non-empty bins: 3 degrees of freedom; 16.3 is the 0.1 % tail.
    double chi2 = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double expected = kSamples * d.pmf(i);
        if (expected == 0.0) {
            EXPECT_EQ(counts[i], 0.0) << "empty bin " << i << " was sampled";
            continue;
        }
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    }
    EXPECT_LT(chi2, 16.3);
}

TEST(Distribution1D, RemappedUIsUniform) {
    // Reusing u after a discrete choice is only sound if it is uniform again.
    const Distribution1D d({1.0f, 2.0f, 3.0f});
    Rng rng(11);
    constexpr int kBins = 10;
    constexpr int kSamples = 100000;
    std::vector<double> hist(kBins, 0.0);
    for (int i = 0; i < kSamples; ++i) {
        hist[static_cast<int>(d.sample_discrete(rng.next_float()).u_remapped * kBins)] += 1.0;
    }
    double chi2 = 0.0;
    const double expected = static_cast<double>(kSamples) / kBins;
    for (double h : hist) chi2 += (h - expected) * (h - expected) / expected;
    EXPECT_LT(chi2, 27.9);  // 9 dof, 0.1 % tail
}

TEST(Distribution1D, ContinuousHistogramMatchesPdf) {
    const Distribution1D d({0.2f, 1.0f, 0.0f, 3.0f, 0.8f});
    Rng rng(3);
    constexpr int kBins = 20;  // 4 histogram bins per distribution bin
    constexpr int kSamples = 200000;
    std::vector<double> hist(kBins, 0.0);
    for (int i = 0; i < kSamples; ++i) {
        const auto s = d.sample_continuous(rng.next_float());
        ASSERT_GE(s.x, 0.0f);
        ASSERT_LT(s.x, 1.0f);
        EXPECT_FLOAT_EQ(s.pdf, d.pdf(s.x));
        hist[static_cast<int>(s.x * kBins)] += 1.0;
    }
    double chi2 = 0.0;
    int dof = -1;
    for (int b = 0; b < kBins; ++b) {
        const double expected = kSamples * d.pdf((b + 0.5f) / kBins) / kBins;
        if (expected == 0.0) {
            EXPECT_EQ(hist[b], 0.0);
            continue;
        }
        chi2 += (hist[b] - expected) * (hist[b] - expected) / expected;
        ++dof;
    }
    EXPECT_EQ(dof, 15);
    EXPECT_LT(chi2, 37.7);  // 15 dof, 0.1 % tail
}

TEST(Distribution1D, AllZeroFallsBackToUniform) {
    const Distribution1D d({0.0f, 0.0f});
    EXPECT_EQ(d.integral(), 0.0f);
    EXPECT_FLOAT_EQ(d.pmf(1), 0.5f);
    const auto s = d.sample_continuous(0.75f);
    EXPECT_EQ(s.index, 1u);
    EXPECT_FLOAT_EQ(s.x, 0.75f);
    EXPECT_FLOAT_EQ(s.pdf, 1.0f);
}

TEST(Distribution1D, RejectsBadInput) {
    EXPECT_THROW(Distribution1D({}), Error);
    EXPECT_THROW(Distribution1D({1.0f, -1.0f}), Error);
    EXPECT_THROW(Distribution1D({1.0f, std::nanf("")}), Error);
    EXPECT_THROW(Distribution1D({std::numeric_limits<float>::infinity()}), Error);
}

TEST(Distribution1D, Deterministic) {
    const Distribution1D d({1.0f, 5.0f, 2.0f});
    const auto a = d.sample_continuous(0.4321f);
    const auto b = d.sample_continuous(0.4321f);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.index, b.index);
}

// A 4 x 3 grid (width x height) with an empty cell, an empty row and uneven rows.
const std::vector<float> kGrid = {
    1.0f, 2.0f, 0.0f, 1.0f,  // row 0: integral 1
    0.0f, 0.0f, 0.0f, 0.0f,  // row 1: empty
    4.0f, 1.0f, 2.0f, 5.0f,  // row 2: integral 3
};

TEST(Distribution2D, PdfIsValueOverIntegral) {
    const Distribution2D d(kGrid, 4, 3);
    EXPECT_EQ(d.width(), 4u);
    EXPECT_EQ(d.height(), 3u);
    EXPECT_FLOAT_EQ(d.integral(), 16.0f / 12.0f);
    double total = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
        for (std::size_t i = 0; i < 4; ++i) {
            const Vec2 centre((i + 0.5f) / 4.0f, (j + 0.5f) / 3.0f);
            EXPECT_FLOAT_EQ(d.pdf(centre), kGrid[j * 4 + i] / d.integral()) << i << ", " << j;
            total += d.pdf(centre) / 12.0;
        }
    }
    EXPECT_NEAR(total, 1.0, 1e-6);
    EXPECT_EQ(d.pdf(Vec2(0.5f, 1.0f)), 0.0f);
    EXPECT_EQ(d.pdf(Vec2(-0.1f, 0.5f)), 0.0f);
}

TEST(Distribution2D, SampleInvertsBothCdfs) {
    const Distribution2D d(kGrid, 4, 3);
    // Row cdf edges: 0, 1/4, 1/4, 1; u.y = 5/8 lies halfway through row 2, which covers
    // y in [2/3, 1). Row 2's cdf edges: 0, 1/3, 5/12, 7/12, 1; u.x = 0.5 is halfway
    // through cell 2, which covers x in [1/2, 3/4).
    const auto s = d.sample_continuous(Vec2(0.5f, 0.625f));
    EXPECT_FLOAT_EQ(s.point.x, 0.625f);
    EXPECT_FLOAT_EQ(s.point.y, 5.0f / 6.0f);
    EXPECT_FLOAT_EQ(s.pdf, 2.0f / d.integral());
    // The empty row and the empty cell are never reached, even from their cdf edges.
    const auto edge = d.sample_continuous(Vec2(0.0f, 0.25f));
    EXPECT_GE(edge.point.y, 2.0f / 3.0f);
    EXPECT_LT(d.sample_continuous(Vec2(1.0f, 1.0f)).point.x, 1.0f);
    EXPECT_LT(d.sample_continuous(Vec2(1.0f, 1.0f)).point.y, 1.0f);
}

TEST(Distribution2D, HistogramMatchesPdf) {
    const Distribution2D d(kGrid, 4, 3);
    constexpr int kSub = 2;  // histogram bins per cell along each axis
    constexpr int kBinsX = 4 * kSub, kBinsY = 3 * kSub;
    constexpr int kSamples = 200000;
    std::vector<double> hist(kBinsX * kBinsY, 0.0);
    Rng rng(5);
    for (int n = 0; n < kSamples; ++n) {
        const auto s = d.sample_continuous(Vec2(rng.next_float(), rng.next_float()));
        ASSERT_GE(s.point.x, 0.0f);
        ASSERT_LT(s.point.x, 1.0f);
        ASSERT_GE(s.point.y, 0.0f);
        ASSERT_LT(s.point.y, 1.0f);
        EXPECT_FLOAT_EQ(s.pdf, d.pdf(s.point));
        hist[static_cast<int>(s.point.y * kBinsY) * kBinsX +
             static_cast<int>(s.point.x * kBinsX)] += 1.0;
    }
    double chi2 = 0.0;
    int dof = -1;
    for (int by = 0; by < kBinsY; ++by) {
        for (int bx = 0; bx < kBinsX; ++bx) {
            const double p = d.pdf(Vec2((bx + 0.5f) / kBinsX, (by + 0.5f) / kBinsY));
            const double expected = kSamples * p / (kBinsX * kBinsY);
            const double observed = hist[by * kBinsX + bx];
            if (expected == 0.0) {
                EXPECT_EQ(observed, 0.0) << "empty bin " << bx << ", " << by;
                continue;
            }
            chi2 += (observed - expected) * (observed - expected) / expected;
            ++dof;
        }
    }
    EXPECT_EQ(dof, 27);     // 7 non-empty cells of 4 bins each, less one
    EXPECT_LT(chi2, 55.5);  // 27 dof, 0.1 % tail
}

TEST(Distribution2D, AllZeroFallsBackToUniform) {
    const Distribution2D d(std::vector<float>(6, 0.0f), 3, 2);
    EXPECT_EQ(d.integral(), 0.0f);
    const auto s = d.sample_continuous(Vec2(0.25f, 0.75f));
    EXPECT_FLOAT_EQ(s.point.x, 0.25f);
    EXPECT_FLOAT_EQ(s.point.y, 0.75f);
    EXPECT_FLOAT_EQ(s.pdf, 1.0f);
    EXPECT_FLOAT_EQ(d.pdf(Vec2(0.9f, 0.1f)), 1.0f);
}

TEST(Distribution2D, RejectsBadInput) {
    EXPECT_THROW(Distribution2D({1.0f, 2.0f, 3.0f}, 2, 2), Error);
    EXPECT_THROW(Distribution2D({}, 0, 0), Error);
    EXPECT_THROW(Distribution2D({1.0f, -1.0f}, 2, 1), Error);
}

}  // namespace
}  // namespace glint
