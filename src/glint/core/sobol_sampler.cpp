#include <glint/core/rng.h>
#include <glint/core/sobol_sampler.h>

#include <cstring>

namespace glint {
namespace {

// Four 32-bit lanes (GCC/Clang vector extension; SSE2 on x86-64): a Sobol group's four
// dimensions are scrambled together, which costs about what one of them costs alone.
using U32x4 = uint32_t __attribute__((vector_size(16)));
using I32x4 = int32_t __attribute__((vector_size(16)));
using F32x4 = detail::SobolLanes;

uint32_t reverse_bits(uint32_t x) {
    x = __builtin_bswap32(x);  // bytes in one instruction; then the bits inside each byte
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// reverse_bits lane by lane; SSE2 has no byte shuffle, so the bytes move by shifts too.
U32x4 reverse_bits(U32x4 x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x >> 8) & 0x00ff00ffu);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    x = ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
    return x;
}

// The Laine-Karras permutation (with Burley's constants): applied to bit-reversed values it
// scrambles each bit depending only on the bits above it, i.e. a nested uniform (Owen)
// scramble, which keeps the sequence's stratification (Burley 2020, "Practical Hash-based
// Owen Scrambling"). The scramble of x is thus reverse_bits(laine_karras(reverse_bits(x))).
// One template for a single value and for four lanes, so both compute the same thing.
template <typename Bits>
Bits laine_karras(Bits x, Bits seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

}  // namespace

namespace detail {

// Sobol's first four dimensions, from their primitive polynomials and initial direction
// numbers (Joe & Kuo 2008; dimension 0 is the radical inverse): the value for an index is
// the XOR of the direction numbers of its set bits. Tabulated per byte of the index's bit
// reversal (which is what the index shuffle produces), with the four dimensions side by
// side in one vector, so any 32-bit index takes four lookups for all of them; stored
// bit-reversed, because the scramble works on reversed values (see SobolSampler). Reversed
// dimension 0 is the index itself.
class SobolTables {
public:
    static constexpr int kDimensions = 4;

    SobolTables() {
        struct Polynomial {
            int degree;
            uint32_t coefficients;  // the inner coefficients a_1..a_{degree-1}, a_1 highest
            uint32_t initial[3];    // m_1..m_degree, odd and below 2^k
        };
        const Polynomial polynomials[kDimensions - 1] = {
            {1, 0, {1}}, {2, 1, {1, 3}}, {3, 1, {1, 3, 1}}};
        uint32_t direction[kDimensions][32];
        for (int k = 0; k < 32; ++k) direction[0][k] = 1u << (31 - k);
        for (int d = 1; d < kDimensions; ++d) {
            const Polynomial& poly = polynomials[d - 1];
            for (int k = 0; k < 32; ++k) {
                if (k < poly.degree) {
                    direction[d][k] = poly.initial[k] << (31 - k);
                    continue;
                }
                direction[d][k] =
                    direction[d][k - poly.degree] ^ (direction[d][k - poly.degree] >> poly.degree);
                for (int j = 1; j < poly.degree; ++j) {
                    if ((poly.coefficients >> (poly.degree - 1 - j)) & 1u)
                        direction[d][k] ^= direction[d][k - j];
                }
            }
        }
        // Byte j of the reversed index is byte 3 - j of the index, with its bits reversed.
        for (int byte = 0; byte < 4; ++byte) {
            for (uint32_t value = 0; value < 256; ++value) {
                const uint32_t index_byte = reverse_bits(value) >> 24;
                for (int d = 0; d < kDimensions; ++d) {
                    uint32_t result = 0;
                    for (int bit = 0; bit < 8; ++bit) {
                        if (index_byte & (1u << bit)) result ^= direction[d][8 * (3 - byte) + bit];
                    }
                    m_table[byte][value][d] = reverse_bits(result);
                }
            }
        }
    }

    // reverse_bits of Sobol dimensions 0 to 3 for the index whose bit reversal is
    // `reversed_index`: the scramble produces the shuffled index reversed, and the tables
    // are indexed by its bytes, so it never has to be reversed back.
    U32x4 for_reversed_index(uint32_t reversed_index) const {
        return m_table[0][reversed_index & 0xff] ^ m_table[1][(reversed_index >> 8) & 0xff] ^
               m_table[2][(reversed_index >> 16) & 0xff] ^ m_table[3][reversed_index >> 24];
    }

private:
    U32x4 m_table[4][256];
};

}  // namespace detail

namespace {

using detail::SobolTables;

const SobolTables& sobol_tables() {
    static const SobolTables tables;
    return tables;
}

// The SSE4.1 path below uses GCC's generic vector shuffle, which Clang spells differently;
// other compilers and CPUs take the portable path, with the same results.
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__clang__)
#define GLINT_SOBOL_SSE41 1
#else
#define GLINT_SOBOL_SSE41 0
#endif

// reverse_bits lane by lane with byte shuffles (SSSE3): reverse the bytes of each lane,
// then the bits of each byte by looking up each nibble's reversal. Only inlined into the
// SSE4.1 path, which enables the instruction.
[[gnu::always_inline]] inline U32x4 reverse_bits_by_shuffles(U32x4 bits) {
#if GLINT_SOBOL_SSE41
    using U8x16 = uint8_t __attribute__((vector_size(16)));
    constexpr U8x16 kByteSwap = {3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12};
    constexpr U8x16 kReversedNibble = {0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe,
                                       0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf};
    const U8x16 bytes = __builtin_shuffle(reinterpret_cast<U8x16>(bits), kByteSwap);
    const U8x16 low = bytes & 0x0f;
    const U8x16 high = reinterpret_cast<U8x16>(reinterpret_cast<U32x4>(bytes) >> 4) & 0x0f;
    const U8x16 reversed =
        (__builtin_shuffle(kReversedNibble, low) << 4) | __builtin_shuffle(kReversedNibble, high);
    return reinterpret_cast<U32x4>(reversed);
#else
    return reverse_bits(bits);
#endif
}

// The four values of a Sobol group: Owen-scrambled Sobol dimensions 0 to 3 of the group's
// shuffled index (given bit-reversed), each scrambled with its own seed derived from the
// group key. Compiled twice (see scramble_group): for SSE2, which every x86-64 has, and for
// SSE4.1, whose lane-wise multiply and byte shuffle take half the instructions. Both give
// the same bits.
template <bool kSse41>
[[gnu::always_inline]] inline F32x4 scramble_group_with(const SobolTables& tables,
                                                        uint32_t reversed_shuffled, uint32_t key) {
    constexpr U32x4 kSeedMultipliers = {0x9e3779b9u, 0x85ebca6bu, 0xc2b2ae35u, 0x27d4eb2fu};
    const U32x4 seeds = key * kSeedMultipliers + U32x4{1, 2, 3, 4};
    U32x4 bits = laine_karras(tables.for_reversed_index(reversed_shuffled), seeds);
    bits = kSse41 ? reverse_bits_by_shuffles(bits) : reverse_bits(bits);
    // bits >> 8 is below 2^24, so the floats are exact and at most 1 - 2^-24.
    return __builtin_convertvector(reinterpret_cast<I32x4>(bits >> 8), F32x4) * 0x1p-24f;
}

F32x4 scramble_group_sse2(const SobolTables& tables, uint32_t reversed_shuffled, uint32_t key) {
    return scramble_group_with<false>(tables, reversed_shuffled, key);
}

#if GLINT_SOBOL_SSE41
[[gnu::target("sse4.1")]] F32x4 scramble_group_sse41(const SobolTables& tables,
                                                     uint32_t reversed_shuffled, uint32_t key) {
    return scramble_group_with<true>(tables, reversed_shuffled, key);
}
#endif

// The fastest version this CPU runs, chosen once.
detail::SobolScramble scramble_group() {
#if GLINT_SOBOL_SSE41
    static const detail::SobolScramble chosen =
        __builtin_cpu_supports("sse4.1") ? scramble_group_sse41 : scramble_group_sse2;
    return chosen;
#else
    return scramble_group_sse2;
#endif
}

}  // namespace

SobolSampler::SobolSampler(int spp, uint64_t seed)
    : Sampler(spp, seed),
      m_tables(&sobol_tables()),
      m_scramble_group(scramble_group()),
      m_keys(std::make_shared<PixelKeys>()) {}

void SobolSampler::start_pixel_sample(Vec2i pixel, int index) {
    // A pixel's samples are taken one after another, and the group keys depend only on
    // (seed, pixel, group): they are hashed once per pixel, not per sample.
    PixelKeys& keys = *m_keys;
    if (pixel != keys.pixel) {
        keys.pixel_key = detail::pixel_sample_key(m_seed, pixel, 0);
        keys.pixel = pixel;
        keys.cached = 0;
    }
    m_reversed_index = reverse_bits(static_cast<uint32_t>(index));
    m_next_group = 0;
    m_ahead_next = kGroupSize;  // no group open
}

std::unique_ptr<Sampler> SobolSampler::clone() const {
    return std::make_unique<SobolSampler>(m_spp, m_seed);
}

std::unique_ptr<Sampler> SobolSampler::clone_for_lane() {
    auto lane = std::make_unique<SobolSampler>(m_spp, m_seed);
    lane->m_keys = m_keys;
    return lane;
}

void SobolSampler::open_group() {
    const uint32_t key = group_key(m_next_group++);
    // The group's shuffle of the index, nested_uniform_scramble(index), is
    // reverse_bits(laine_karras(reverse_bits(index))): the index is reversed once per
    // sample, and the tables take the result still reversed.
    const uint32_t reversed_shuffled = laine_karras(m_reversed_index, key);
    const F32x4 values = m_scramble_group(*m_tables, reversed_shuffled, key);
    static_assert(sizeof(values) == sizeof(m_ahead));
    std::memcpy(m_ahead, &values, sizeof(values));
    m_ahead_next = 0;
}

uint32_t SobolSampler::group_key(uint32_t group) {
    PixelKeys& keys = *m_keys;
    if (group < keys.cached) return keys.keys[group];
    const auto key = static_cast<uint32_t>(hash_combine(keys.pixel_key, group));
    if (group == keys.cached && group < kCachedKeys) keys.keys[keys.cached++] = key;
    return key;
}

detail::SobolGroupPaths detail::sobol_group_by_each_path(uint32_t shuffled_index,
                                                         uint32_t group_key) {
    const uint32_t reversed = reverse_bits(shuffled_index);
    const F32x4 portable = scramble_group_sse2(sobol_tables(), reversed, group_key);
    const F32x4 fastest = scramble_group()(sobol_tables(), reversed, group_key);
    detail::SobolGroupPaths paths;
    for (int d = 0; d < 4; ++d) {
        paths.portable[d] = portable[d];
        paths.fastest[d] = fastest[d];
    }
    return paths;
}

}  // namespace glint
