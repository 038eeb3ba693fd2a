// Strict parsing of command-line numbers: whole text, no wrap-around, no stray sign.
#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/strict_number.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

using namespace glint;

TEST(StrictNumber, IntegersInRangeParse) {
    EXPECT_EQ(parse_integer("16", 1, 100), 16);
    EXPECT_EQ(parse_integer("-5", -10, 10), -5);
    EXPECT_EQ(parse_integer("2147483647", 1, 2147483647), 2147483647);
}

TEST(StrictNumber, IntegersRejectWrapJunkAndRange) {
    EXPECT_FALSE(parse_integer("4294967312", 1, 65536));  // sscanf("%d") wraps this to 16
    EXPECT_FALSE(parse_integer("99999999999999999999", 1, 65536));
    EXPECT_FALSE(parse_integer("12abc", 1, 100));
    EXPECT_FALSE(parse_integer("1.5", 1, 100));
    EXPECT_FALSE(parse_integer("", 1, 100));
    EXPECT_FALSE(parse_integer(" 5", 1, 100));
    EXPECT_FALSE(parse_integer("+5", 1, 100));
    EXPECT_FALSE(parse_integer("0", 1, 100));
    EXPECT_FALSE(parse_integer("101", 1, 100));
}

TEST(StrictNumber, UnsignedTakesTheFullRangeButNoSign) {
    EXPECT_EQ(parse_unsigned("18446744073709551615", UINT64_MAX), UINT64_MAX);
    EXPECT_EQ(parse_unsigned("0", UINT64_MAX), 0u);
    EXPECT_FALSE(parse_unsigned("-1", UINT64_MAX));  // CLI11 turned this into 2^64 - 1
    EXPECT_FALSE(parse_unsigned("18446744073709551616", UINT64_MAX));
    EXPECT_FALSE(parse_unsigned("+1", UINT64_MAX));
    EXPECT_FALSE(parse_unsigned("7x", UINT64_MAX));
}

TEST(StrictNumber, FiniteRejectsNanInfinityAndJunk) {
    EXPECT_EQ(parse_finite("0.25"), 0.25);
    EXPECT_EQ(parse_finite("-2e-3"), -2e-3);
    EXPECT_FALSE(parse_finite("nan"));
    EXPECT_FALSE(parse_finite("inf"));
    EXPECT_FALSE(parse_finite("-inf"));
    EXPECT_FALSE(parse_finite("1e999"));
    EXPECT_FALSE(parse_finite("0.1x"));
    EXPECT_FALSE(parse_finite(""));
}

TEST(StrictNumber, Resolution) {
    EXPECT_EQ(parse_resolution("640x480", 65536), std::make_pair(640, 480));
    EXPECT_EQ(parse_resolution("8X8", 65536), std::make_pair(8, 8));
    EXPECT_EQ(parse_resolution("65536x1", 65536), std::make_pair(65536, 1));
    EXPECT_FALSE(parse_resolution("4294967312x16", 65536));
    EXPECT_FALSE(parse_resolution("70000x1", 65536));
    EXPECT_FALSE(parse_resolution("0x8", 65536));
    EXPECT_FALSE(parse_resolution("8x8x", 65536));
    EXPECT_FALSE(parse_resolution("88", 65536));
    EXPECT_FALSE(parse_resolution("x8", 65536));
}

TEST(Memory, SaturatingProductDoesNotWrap) {
    EXPECT_EQ(saturating_product(1u << 20, 1u << 20), uint64_t{1} << 40);
    EXPECT_EQ(saturating_product(uint64_t{1} << 40, uint64_t{1} << 40), UINT64_MAX);
    EXPECT_EQ(format_bytes(uint64_t{40} << 30), "40.0 GiB");
    EXPECT_EQ(format_bytes(100), "100 bytes");
}

TEST(Memory, ImageHeadersAreCheckedAgainstTheFileSize) {
    // 100000 x 100000 x 3 bytes claimed by a 100-byte file: a lie.
    EXPECT_THROW(check_image_header("a.png", 100000, 100000, 3, 1, 100), Error);
    EXPECT_THROW(check_image_header("a.png", 0, 10, 3, 1, 100), Error);
    EXPECT_THROW(check_image_header("a.png", 10, 10, 0, 1, 100), Error);
    EXPECT_THROW(check_image_header("a.png", (int64_t{1} << 20) + 1, 1, 3, 1, 1u << 30), Error);
    EXPECT_NO_THROW(check_image_header("a.png", 1024, 1024, 3, 1, 2000));
}
