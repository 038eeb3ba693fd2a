#pragma once
// An exact sum of doubles, independent of the order of its terms: what the film accumulates
// in, so that a render split into sample ranges (`glint render --samples A:B`, MPI ranks)
// adds up to exactly the image of one render. A sum of doubles rounds after every addition,
// so (a + b) + c and a + (b + c) differ in the last bits; here every term is rounded once,
// to a fixed grid of 2^-60, and the rounded terms are added as 128-bit integers, whose
// addition is associative.
#include <cmath>
#include <cstdint>

namespace glint {

class FixedSum {
public:
    /// Binary digits after the point: terms are rounded to multiples of 2^-60 (about 8.7e-19).
    static constexpr int kFractionBits = 60;
    /// Terms must be smaller than this in magnitude (2^60, about 1.2e18). A sum wraps around
    /// only beyond 2^67 (about 1.5e20), far past any film's weighted radiance.
    static constexpr double kMaxTerm = 0x1p60;
    /// 16-bit words of the 128-bit value, for storing it exactly in float image channels.
    static constexpr int kWords = 8;
    /// 2^kFractionBits: what a term is multiplied by before rounding.
    static constexpr double kScale = 0x1p60;

    /// Whether add(term) keeps the sum exact: `term` is finite and below kMaxTerm.
    static bool accepts(double term) { return std::abs(term) < kMaxTerm; }

    /// Adds `term`, which must satisfy accepts().
    void add(double term) {
        // Scaling by a power of two is exact. Most terms are below 8, so their scaled value
        // fits 64 bits and one rounding conversion does; only larger ones take the 128-bit
        // conversion, a library call. Both round to nearest even: the bits are the same.
        const double scaled = term * kScale;
        if (std::abs(scaled) < 0x1p62) {
            m_value += static_cast<Bits>(static_cast<Signed>(std::llrint(scaled)));
            return;
        }
        m_value += static_cast<Bits>(static_cast<Signed>(std::rint(scaled)));
    }
    FixedSum& operator+=(const FixedSum& other) {
        m_value += other.m_value;
        return *this;
    }
    bool operator==(const FixedSum& other) const = default;

    /// The sum, rounded once to the nearest double. (The product by 2^-60 is exact, as
    /// std::ldexp would be, without its library call: a nonzero sum is at least 2^-60.)
    double value() const { return static_cast<double>(static_cast<Signed>(m_value)) * 0x1p-60; }

    /// Word `i` (0 = least significant) of the two's-complement value.
    uint16_t word(int i) const { return static_cast<uint16_t>(m_value >> (16 * i)); }
    /// The sum whose words are `words[0 .. kWords)`.
    static FixedSum from_words(const uint16_t* words) {
        FixedSum sum;
        for (int i = kWords - 1; i >= 0; --i) sum.m_value = (sum.m_value << 16) | words[i];
        return sum;
    }

private:
    // Unsigned arithmetic wraps instead of overflowing, and wrapping addition is still
    // associative; the signed view is only taken to read the value.
    __extension__ typedef unsigned __int128 Bits;
    __extension__ typedef __int128 Signed;
    Bits m_value = 0;
};

}  // namespace glint
