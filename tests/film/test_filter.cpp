#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/film/filter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace glint {
namespace {

constexpr int kSamples = 200000;

// Midpoint-rule integral of fn over [x0, x1] x [y0, y1].
double integrate(const std::function<double(double, double)>& fn, double x0, double x1, double y0,
                 double y1, int n) {
    const double dx = (x1 - x0) / n, dy = (y1 - y0) / n;
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) sum += fn(x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy);
    }
    return sum * dx * dy;
}

double filter_value(const Filter& f, double x, double y) {
    return f.eval(Vec2(static_cast<float>(x), static_cast<float>(y)));
}

// Signed, weighted histogram of the filter's samples on a bins x bins grid over its
// support, normalised per sample: each entry estimates the integral of f over the cell.
struct WeightedHistogram {
    std::vector<double> sum;
};

WeightedHistogram sample_histogram(const Filter& filter, int bins, uint64_t seed) {
    WeightedHistogram h{std::vector<double>(bins * bins, 0.0)};
    const Vec2 r = filter.radius();
    Rng rng(seed);
    for (int s = 0; s < kSamples; ++s) {
        const FilterSample fs = filter.sample(Vec2(rng.next_float(), rng.next_float()));
        EXPECT_LE(std::abs(fs.offset.x), r.x);
        EXPECT_LE(std::abs(fs.offset.y), r.y);
        const int bx = std::min(bins - 1, static_cast<int>((fs.offset.x + r.x) / (2 * r.x) * bins));
        const int by = std::min(bins - 1, static_cast<int>((fs.offset.y + r.y) / (2 * r.y) * bins));
        h.sum[by * bins + bx] += fs.weight;
    }
    return h;
}

// Every cell's estimate lies within 5 standard errors of the integral of f over it, and
// the estimates add up to the whole integral. Works for signed filters too.
void expect_histogram_matches(const Filter& filter, int bins) {
    const WeightedHistogram h = sample_histogram(filter, bins, 1234);
    const double weight_magnitude = std::abs(filter.sample(Vec2(0.5f)).weight);
    const Vec2 r = filter.radius();
    const double cw = 2.0 * r.x / bins, ch = 2.0 * r.y / bins;
    double l1 = 0.0, total_abs = 0.0;
    for (int by = 0; by < bins; ++by) {
        for (int bx = 0; bx < bins; ++bx) {
            const double x0 = -r.x + bx * cw, y0 = -r.y + by * ch;
            const double expected =
                integrate([&](double x, double y) { return filter_value(filter, x, y); }, x0,
                          x0 + cw, y0, y0 + ch, 32);
            const int i = by * bins + bx;
            const double mean = h.sum[i] / kSamples;
            // Every weight has magnitude W, so one sample's contribution to the cell has
            // variance W |expected| - expected^2: the test's own noise, known in advance.
            const double var = weight_magnitude * std::abs(expected) - expected * expected;
            const double stderr_ = std::sqrt(std::max(var, 0.0) / kSamples);
            EXPECT_NEAR(mean, expected, 5.0 * stderr_ + 1e-7) << "cell " << bx << ", " << by;
            l1 += std::abs(mean - expected);
            total_abs += std::abs(expected);
        }
    }
    EXPECT_LT(l1 / total_abs, 0.02);
}

TEST(BoxFilter, UniformInsideRadiusWithUnitWeight) {
    const auto box = make_box_filter(0.5f);
    EXPECT_EQ(box->radius(), Vec2(0.5f));
    EXPECT_EQ(box->eval(Vec2(0.2f, -0.4f)), 1.0f);
    EXPECT_EQ(box->eval(Vec2(0.6f, 0.0f)), 0.0f);
    constexpr int kBins = 8;
    std::vector<double> hist(kBins * kBins, 0.0);
    Rng rng(5);
    for (int s = 0; s < kSamples; ++s) {
        const FilterSample fs = box->sample(Vec2(rng.next_float(), rng.next_float()));
        ASSERT_EQ(fs.weight, 1.0f);
        ASSERT_GE(fs.offset.x, -0.5f);
        ASSERT_LT(fs.offset.x, 0.5f);
        ASSERT_GE(fs.offset.y, -0.5f);
        ASSERT_LT(fs.offset.y, 0.5f);
        hist[static_cast<int>((fs.offset.y + 0.5f) * kBins) * kBins +
             static_cast<int>((fs.offset.x + 0.5f) * kBins)] += 1.0;
    }
    double chi2 = 0.0;
    const double expected = static_cast<double>(kSamples) / (kBins * kBins);
    for (double c : hist) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 103.4);  // 63 dof, 0.1 % tail
    // Corners of the unit square map to the corners of the support.
    EXPECT_EQ(box->sample(Vec2(0.0f)).offset, Vec2(-0.5f));
    EXPECT_EQ(make_box_filter(1.0f)->sample(Vec2(0.75f, 0.25f)).offset, Vec2(0.5f, -0.5f));
}

TEST(GaussianFilter, ShapeAndZeroAtRadius) {
    const auto g = make_gaussian_filter(1.5f, 0.5f);
    const double floor = std::exp(-1.5 * 1.5 / (2 * 0.25));
    EXPECT_NEAR(g->eval(Vec2(0.0f)), (1.0 - floor) * (1.0 - floor), 1e-6);
    EXPECT_NEAR(g->eval(Vec2(0.5f, 0.0f)), (std::exp(-0.5) - floor) * (1.0 - floor), 1e-6);
    EXPECT_EQ(g->eval(Vec2(1.5f, 0.0f)), 0.0f);
    EXPECT_EQ(g->eval(Vec2(0.0f, 1.6f)), 0.0f);
}

TEST(GaussianFilter, SamplesFollowTheFilter) {
    const auto g = make_gaussian_filter(1.5f, 0.5f);
    // A positive filter: all weights are the same positive value.
    Rng rng(9);
    const float w0 = g->sample(Vec2(rng.next_float(), rng.next_float())).weight;
    EXPECT_GT(w0, 0.0f);
    for (int i = 0; i < 1000; ++i) {
        ASSERT_EQ(g->sample(Vec2(rng.next_float(), rng.next_float())).weight, w0);
    }
    // The weight is the filter's integral, so sum(w L) / N estimates the filtered value.
    const double integral = integrate([&](double x, double y) { return filter_value(*g, x, y); },
                                      -1.5, 1.5, -1.5, 1.5, 600);
    EXPECT_NEAR(w0, integral, 1e-3 * integral);
    expect_histogram_matches(*g, 12);
}

TEST(MitchellFilter, ShapeAndContinuity) {
    const auto m = make_mitchell_filter(2.0f, 1.0f / 3, 1.0f / 3);
    // Per axis, the cubic is (6 - 2B) / 6 at 0, B / 6 at 1 from both sides, 0 from 2 on.
    EXPECT_NEAR(m->eval(Vec2(0.0f)), sqr(16.0f / 18.0f), 1e-6);
    EXPECT_NEAR(m->eval(Vec2(1.0f - 1e-5f, 0.0f)), (1.0f / 18.0f) * (16.0f / 18.0f), 1e-5);
    EXPECT_NEAR(m->eval(Vec2(1.0f + 1e-5f, 0.0f)), (1.0f / 18.0f) * (16.0f / 18.0f), 1e-5);
    EXPECT_LT(m->eval(Vec2(1.5f, 0.0f)), 0.0f);  // negative lobe
    EXPECT_EQ(m->eval(Vec2(2.0f, 0.0f)), 0.0f);
    // A wider radius stretches the same shape.
    const auto wide = make_mitchell_filter(3.0f);
    EXPECT_NEAR(wide->eval(Vec2(1.5f, 0.0f)), m->eval(Vec2(1.0f, 0.0f)), 1e-6);
}

TEST(MitchellFilter, SignedHistogramMatchesFilter) {
    const auto m = make_mitchell_filter();
    int negative = 0;
    Rng rng(21);
    for (int i = 0; i < 10000; ++i) {
        negative += m->sample(Vec2(rng.next_float(), rng.next_float())).weight < 0.0f;
    }
    // The lobes hold a few percent of |f|; they must be sampled, with negative weight.
    EXPECT_GT(negative, 100);
    EXPECT_LT(negative, 2000);
    expect_histogram_matches(*m, 16);
}

TEST(MitchellFilter, WeightedEstimateOfTestFunction) {
    // E[w g(offset)] must equal the integral of f g: the property the film relies on.
    const auto m = make_mitchell_filter();
    const auto g = [](double x, double y) { return 1.0 + 0.5 * x + y * y + std::sin(x * y); };
    const double reference = integrate(
        [&](double x, double y) { return filter_value(*m, x, y) * g(x, y); }, -2, 2, -2, 2, 800);
    const double f_integral =
        integrate([&](double x, double y) { return filter_value(*m, x, y); }, -2, 2, -2, 2, 800);
    EXPECT_NEAR(f_integral, 1.0, 1e-3);  // the Mitchell cubic integrates to 1 per axis
    double sum = 0.0, sum_sq = 0.0, weight_sum = 0.0;
    Rng rng(77);
    for (int s = 0; s < kSamples; ++s) {
        const FilterSample fs = m->sample(Vec2(rng.next_float(), rng.next_float()));
        const double v = fs.weight * g(fs.offset.x, fs.offset.y);
        sum += v;
        sum_sq += v * v;
        weight_sum += fs.weight;
    }
    const double mean = sum / kSamples;
    const double stderr_ = std::sqrt((sum_sq / kSamples - mean * mean) / kSamples);
    EXPECT_NEAR(mean, reference, 5.0 * stderr_);
    EXPECT_NEAR(weight_sum / kSamples, f_integral, 0.01);
    // The ratio estimator the film computes: the filtered value of g at the centre.
    EXPECT_NEAR(sum / weight_sum, reference / f_integral, 0.02);
}

TEST(Filter, SamplingIsDeterministic) {
    for (const char* name : {"box", "gaussian", "mitchell"}) {
        const auto a = make_filter(name, 0.0f);
        const auto b = make_filter(name, 0.0f);
        const Vec2 u(0.123f, 0.987f);
        EXPECT_EQ(a->sample(u).offset, b->sample(u).offset) << name;
        EXPECT_EQ(a->sample(u).weight, b->sample(u).weight) << name;
    }
}

TEST(Filter, FactoryByName) {
    EXPECT_EQ(make_filter("box", 0.0f)->radius(), Vec2(0.5f));
    EXPECT_EQ(make_filter("gaussian", -1.0f)->radius(), Vec2(1.5f));
    EXPECT_EQ(make_filter("mitchell", 0.0f)->radius(), Vec2(2.0f));
    EXPECT_EQ(make_filter("mitchell", 1.5f)->radius(), Vec2(1.5f));
    EXPECT_THROW(make_filter("box", std::nanf("")), Error);
    EXPECT_THROW(make_gaussian_filter(1.0f, 0.0f), Error);
    try {
        make_filter("tent", 1.0f);
        FAIL() << "unknown filter accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("tent"), std::string::npos);
        EXPECT_NE(message.find("box"), std::string::npos);
        EXPECT_NE(message.find("gaussian"), std::string::npos);
        EXPECT_NE(message.find("mitchell"), std::string::npos);
    }
}

}  // namespace
}  // namespace glint
