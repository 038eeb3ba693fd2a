// The film's exact sums: the same terms give the same bits in any order and any split, which
// is what makes split renders merge into the whole render exactly (docs/cluster.md).
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/film/film.h>
#include <glint/film/fixed_sum.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

using namespace glint;

namespace {

// Terms over 60 binary orders of magnitude, of both signs, as a film's samples can be.
std::vector<double> wide_terms(int count) {
    Rng rng(7);
    std::vector<double> terms;
    for (int i = 0; i < count; ++i) {
        const double mantissa = rng.next_double() - 0.3;
        terms.push_back(std::ldexp(mantissa, static_cast<int>(rng.next_float() * 60.0f) - 40));
    }
    return terms;
}

bool same_words(const FixedSum& a, const FixedSum& b) {
    for (int i = 0; i < FixedSum::kWords; ++i) {
        if (a.word(i) != b.word(i)) return false;
    }
    return true;
}

TEST(FixedSum, AnyOrderAndAnySplitGiveTheSameBits) {
    std::vector<double> terms = wide_terms(10000);
    FixedSum forward;
    for (double t : terms) forward.add(t);
    FixedSum backward;
    for (auto it = terms.rbegin(); it != terms.rend(); ++it) backward.add(*it);
    EXPECT_TRUE(same_words(forward, backward));
    for (size_t split : {size_t{1}, size_t{3333}, size_t{9999}}) {
        FixedSum head, tail;
        for (size_t i = 0; i < split; ++i) head.add(terms[i]);
        for (size_t i = split; i < terms.size(); ++i) tail.add(terms[i]);
        tail += head;
        EXPECT_TRUE(same_words(forward, tail)) << "split at " << split;
        EXPECT_EQ(forward.value(), tail.value());
    }
    // The reason for it: plain doubles summed in the two orders differ in the last bits.
    double sum_forward = 0.0, sum_backward = 0.0;
    for (double t : terms) sum_forward += t;
    for (auto it = terms.rbegin(); it != terms.rend(); ++it) sum_backward += *it;
    EXPECT_NE(sum_forward, sum_backward);
}

TEST(FixedSum, ValueIsTheSumToWithinTheGridAndOneRounding) {
    const std::vector<double> terms = wide_terms(1000);
    FixedSum sum;
    long double reference = 0.0L;
    for (double t : terms) {
        sum.add(t);
        reference += t;
    }
    // Each term is rounded to 2^-60 at most; the long double reference has 64-bit mantissas.
    const double bound =
        1000 * std::ldexp(1.0, -61) + std::abs(static_cast<double>(reference)) * 1e-15;
    EXPECT_NEAR(sum.value(), static_cast<double>(reference), bound);
}

TEST(FixedSum, WordsRoundTripNegativeSums) {
    FixedSum sum;
    sum.add(-1234.5678);
    sum.add(1e-12);
    uint16_t words[FixedSum::kWords];
    for (int i = 0; i < FixedSum::kWords; ++i) words[i] = sum.word(i);
    const FixedSum back = FixedSum::from_words(words);
    EXPECT_TRUE(back == sum);
    EXPECT_NEAR(back.value(), -1234.5678 + 1e-12, 1e-15 * 1234.5678);
}

TEST(FixedSum, RefusesTermsItCannotHold) {
    EXPECT_TRUE(FixedSum::accepts(1e17));
    EXPECT_FALSE(FixedSum::accepts(2e18));
    EXPECT_FALSE(FixedSum::accepts(std::nan("")));
    EXPECT_FALSE(FixedSum::accepts(INFINITY));
}

// A film given samples 0 .. n-1, against two films given [0, k) and [k, n) whose sums are
// added through the partial-render channels: the same image bit for bit, AOVs included.
TEST(FilmSums, SplitFilmsAddUpToTheWholeFilmExactly) {
    const int w = 5, h = 4, n = 37, k = 13;
    Film whole(w, h, true), first(w, h, true), second(w, h, true);
    Rng rng(3);
    for (int index = 0; index < n; ++index) {
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const float scale =
                    std::ldexp(1.0f, static_cast<int>(rng.next_float() * 40.0f) - 20);
                const Spectrum L =
                    uplift(Rgb(rng.next_float() * scale, rng.next_float(), rng.next_float() * 3.0f),
                           RgbRole::illuminant);
                const float weight = 0.25f + rng.next_float();
                const AovSample aov{Spectrum(rng.next_float()), Vec3(0, 1, 0),
                                    rng.next_float() * 9.0f};
                whole.add_sample({x, y}, L, weight, &aov, index);
                (index < k ? first : second).add_sample({x, y}, L, weight, &aov, index);
            }
        }
    }
    Film merged(w, h, true);
    merged.add_sums_image(second.sums_image());
    merged.add_sums_image(first.sums_image());
    const Image a = merged.resolve(), b = whole.resolve();
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

TEST(FilmSums, MismatchedPartsAreRefused) {
    Film with_aovs(4, 4, true), without(4, 4, false), smaller(3, 4, false);
    EXPECT_THROW(without.add_sums_image(with_aovs.sums_image()), Error);
    EXPECT_THROW(with_aovs.add_sums_image(without.sums_image()), Error);
    EXPECT_THROW(without.add_sums_image(smaller.sums_image()), Error);
    Image broken = without.sums_image();
    broken.at(1, 1, broken.channel_index("sum.R.3")) = 0.5f;  // not a 16-bit word
    EXPECT_THROW(without.add_sums_image(broken), Error);
}

}  // namespace
