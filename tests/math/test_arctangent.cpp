// atan2_finite against the correctly rounded atan2 (computed in double, then rounded).
#include <glint/core/rng.h>
#include <glint/math/arctangent.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace glint {
namespace {

// Units in the last place between two finite floats of the same sign (or zeros).
int64_t ulp_distance(float a, float b) {
    const auto ordered = [](float f) {
        const int32_t bits = std::bit_cast<int32_t>(f);
        return bits < 0 ? int64_t{INT32_MIN} - bits : int64_t{bits};
    };
    return std::llabs(ordered(a) - ordered(b));
}

float reference(float y, float x) {
    return static_cast<float>(std::atan2(static_cast<double>(y), static_cast<double>(x)));
}

TEST(Arctangent, WithinTwoUlpOverEveryRatio) {
    Rng rng(7);
    int64_t worst = 0;
    for (int i = 0; i < 2000000; ++i) {
        // Magnitudes over 2^-60 .. 2^60 each, so ratios from nearly 0 to huge, every sign.
        const float y =
            std::ldexp(rng.next_float() + 0.5f, static_cast<int>(rng.next_float() * 120) - 60) *
            (rng.next_float() < 0.5f ? -1.0f : 1.0f);
        const float x =
            std::ldexp(rng.next_float() + 0.5f, static_cast<int>(rng.next_float() * 120) - 60) *
            (rng.next_float() < 0.5f ? -1.0f : 1.0f);
        worst = std::max(worst, ulp_distance(atan2_finite(y, x), reference(y, x)));
    }
    EXPECT_LE(worst, 2);
}

TEST(Arctangent, WithinTwoUlpAroundTheCircle) {
    // Directions at every angle (where the reduction switches: the diagonals and the axes).
    int64_t worst = 0;
    for (int i = 0; i < 1000000; ++i) {
        const double angle = -3.14159265358979 + 6.28318530717958 * (i + 0.5) / 1000000.0;
        const float y = static_cast<float>(std::sin(angle)),
                    x = static_cast<float>(std::cos(angle));
        worst = std::max(worst, ulp_distance(atan2_finite(y, x), reference(y, x)));
    }
    EXPECT_LE(worst, 2);
}

TEST(Arctangent, AxesAndSignedZeros) {
    EXPECT_EQ(atan2_finite(0.0f, 1.0f), 0.0f);
    EXPECT_FALSE(std::signbit(atan2_finite(0.0f, 1.0f)));
    EXPECT_TRUE(std::signbit(atan2_finite(-0.0f, 1.0f)));
    EXPECT_EQ(atan2_finite(0.0f, -1.0f), reference(0.0f, -1.0f));
    EXPECT_EQ(atan2_finite(-0.0f, -1.0f), reference(-0.0f, -1.0f));
    EXPECT_EQ(atan2_finite(1.0f, 0.0f), reference(1.0f, 0.0f));
    EXPECT_EQ(atan2_finite(-1.0f, 0.0f), reference(-1.0f, 0.0f));
    // Both zero, as std::atan2: +-0 towards +x, +-pi towards -x.
    EXPECT_EQ(atan2_finite(0.0f, 0.0f), 0.0f);
    EXPECT_EQ(atan2_finite(0.0f, -0.0f), reference(0.0f, -0.0f));
    EXPECT_EQ(atan2_finite(-0.0f, -0.0f), reference(-0.0f, -0.0f));
    EXPECT_LE(ulp_distance(atan2_finite(1.0f, 1.0f), reference(1.0f, 1.0f)), 1);
    // The largest and smallest finite magnitudes: no overflow in the ratio.
    EXPECT_LE(ulp_distance(atan2_finite(3e38f, 1e-38f), reference(3e38f, 1e-38f)), 1);
    EXPECT_LE(ulp_distance(atan2_finite(1e-38f, -3e38f), reference(1e-38f, -3e38f)), 1);
}

}  // namespace
}  // namespace glint
