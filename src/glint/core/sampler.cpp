#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/core/sampler.h>

#include <fmt/format.h>

namespace glint {
namespace {

uint64_t pixel_sample_key(uint64_t seed, Vec2i pixel, int index) {
    const uint64_t packed_pixel = (static_cast<uint64_t>(static_cast<uint32_t>(pixel.x)) << 32) |
                                  static_cast<uint32_t>(pixel.y);
    return hash_combine(hash_combine(mix_bits(seed), packed_pixel), static_cast<uint64_t>(index));
}

// Every dimension draws from a PCG stream keyed by (seed, pixel, index).
class IndependentSampler final : public Sampler {
public:
    using Sampler::Sampler;

    void start_pixel_sample(Vec2i pixel, int index) override {
        m_rng.seed(pixel_sample_key(m_seed, pixel, index));
    }
    float get_1d() override { return m_rng.next_float(); }
    Vec2 get_2d() override {
        const float x = m_rng.next_float();
        return Vec2(x, m_rng.next_float());
    }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<IndependentSampler>(m_spp, m_seed);
    }

private:
    Rng m_rng;
};

// A random permutation of [0, n) evaluated one element at a time (Kensler 2013,
// "Correlated Multi-Jittered Sampling"), so no per-pixel tables are needed.
uint32_t permute(uint32_t i, uint32_t n, uint32_t key) {
    uint32_t mask = n - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    do {
        i ^= key;
        i *= 0xe170893d;
        i ^= key >> 16;
        i ^= (i & mask) >> 4;
        i ^= key >> 8;
        i *= 0x0929eb3f;
        i ^= key >> 23;
        i ^= (i & mask) >> 1;
        i *= 1 | key >> 27;
        i *= 0x6935fa69;
        i ^= (i & mask) >> 11;
        i *= 0x74dcb303;
        i ^= (i & mask) >> 2;
        i *= 0x9e501cc3;
        i ^= (i & mask) >> 2;
        i *= 0xc860a3df;
        i &= mask;
        i ^= i >> 5;
    } while (i >= n);
    return i;
}

// Each dimension (pair) gets its own shuffled set of strata: a jittered grid when spp is a
// perfect square, Latin hypercube otherwise. The shuffle decorrelates dimensions.
class StratifiedSampler final : public Sampler {
public:
    StratifiedSampler(int spp, uint64_t seed) : Sampler(spp, seed) {
        m_grid = static_cast<int>(std::sqrt(static_cast<double>(spp)));
        if (m_grid * m_grid != spp) m_grid = 0;
    }

    void start_pixel_sample(Vec2i pixel, int index) override {
        m_pixel_key = pixel_sample_key(m_seed, pixel, 0);
        m_index = static_cast<uint32_t>(index);
        m_dimension = 0;
        m_rng.seed(pixel_sample_key(m_seed, pixel, index));
    }

    float get_1d() override {
        const uint32_t stratum = permute(m_index, m_spp, next_dimension_key());
        return (static_cast<float>(stratum) + jitter()) / static_cast<float>(m_spp);
    }

    Vec2 get_2d() override {
        if (m_grid > 0) {
            const uint32_t cell = permute(m_index, m_spp, next_dimension_key());
            const uint32_t g = static_cast<uint32_t>(m_grid);
            const float x = (static_cast<float>(cell % g) + jitter()) / static_cast<float>(g);
            const float y = (static_cast<float>(cell / g) + jitter()) / static_cast<float>(g);
            return Vec2(x, y);
        }
        const float x = get_1d();
        return Vec2(x, get_1d());
    }

    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<StratifiedSampler>(m_spp, m_seed);
    }

private:
    uint32_t next_dimension_key() {
        return static_cast<uint32_t>(hash_combine(m_pixel_key, m_dimension++));
    }
    // Keeps the jittered value strictly inside its stratum.
    float jitter() { return std::min(m_rng.next_float(), 0x1.fffffep-1f); }

    int m_grid = 0;
    uint64_t m_pixel_key = 0;
    uint32_t m_index = 0;
    uint64_t m_dimension = 0;
    Rng m_rng;
};

uint32_t reverse_bits(uint32_t x) {
    x = __builtin_bswap32(x);  // bytes in one instruction; then the bits inside each byte
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// The Laine-Karras permutation (with Burley's constants): applied to bit-reversed values it
// scrambles each bit depending only on the bits above it, i.e. a nested uniform (Owen)
// scramble, which keeps the sequence's stratification (Burley 2020, "Practical Hash-based
// Owen Scrambling"). The scramble of x is thus reverse_bits(laine_karras(reverse_bits(x))).
uint32_t laine_karras(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// The second Sobol dimension: its generator matrix is Pascal's triangle mod 2, so the
// direction numbers follow v <- v ^ (v >> 1). Tabulated per byte of the index, so any
// 32-bit index takes four lookups.
class SobolSecondDimension {
public:
    SobolSecondDimension() {
        uint32_t direction[32];
        uint32_t v = 1u << 31;
        for (int bit = 0; bit < 32; ++bit, v ^= v >> 1) direction[bit] = v;
        for (int byte = 0; byte < 4; ++byte) {
            for (uint32_t value = 0; value < 256; ++value) {
                uint32_t result = 0;
                for (int bit = 0; bit < 8; ++bit) {
                    if (value & (1u << bit)) result ^= direction[8 * byte + bit];
                }
                // Stored bit-reversed: the scramble works on reversed values (see below).
                m_table[byte][value] = reverse_bits(result);
            }
        }
    }
    // reverse_bits of the dimension's value for `index`.
    uint32_t reversed(uint32_t index) const {
        return m_table[0][index & 0xff] ^ m_table[1][(index >> 8) & 0xff] ^
               m_table[2][(index >> 16) & 0xff] ^ m_table[3][index >> 24];
    }

private:
    uint32_t m_table[4][256];
};

const SobolSecondDimension& sobol_dimension_1() {
    static const SobolSecondDimension table;
    return table;
}

float to_unit_float(uint32_t bits) {
    return std::min(static_cast<float>(bits >> 8) * 0x1p-24f, 0x1.fffffep-1f);
}

// Owen-scrambled Sobol, "padded" per dimension pair: each pair of dimensions uses the
// (0,2)-sequence with its own index shuffle and scramble, keyed by (seed, pixel, dimension).
// Any prefix of a pixel's samples is well stratified, which adaptive sampling relies on.
class SobolSampler final : public Sampler {
public:
    using Sampler::Sampler;

    void start_pixel_sample(Vec2i pixel, int index) override {
        m_pixel_key = pixel_sample_key(m_seed, pixel, 0);
        m_reversed_index = reverse_bits(static_cast<uint32_t>(index));
        m_dimension = 0;
    }

    // The first Sobol dimension is the bit reversal of the index, so scrambling it is
    // reverse(LK(index)): one reversal instead of three.
    float get_1d() override {
        const uint32_t key = next_dimension_key();
        return to_unit_float(
            reverse_bits(laine_karras(shuffled_index(key), key * 0x9e3779b9u + 1u)));
    }

    Vec2 get_2d() override {
        const uint32_t key = next_dimension_key();
        const uint32_t shuffled = shuffled_index(key);
        const uint32_t x = reverse_bits(laine_karras(shuffled, key * 0x9e3779b9u + 1u));
        // nested_uniform_scramble of the second dimension, whose table is already reversed.
        const uint32_t y = reverse_bits(
            laine_karras(sobol_dimension_1().reversed(shuffled), key * 0x85ebca6bu + 2u));
        return Vec2(to_unit_float(x), to_unit_float(y));
    }

    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<SobolSampler>(m_spp, m_seed);
    }

private:
    uint32_t next_dimension_key() {
        return static_cast<uint32_t>(hash_combine(m_pixel_key, m_dimension++));
    }
    // The sample index shuffled for this dimension (pair): nested_uniform_scramble(index),
    // with the index's reversal done once per sample.
    uint32_t shuffled_index(uint32_t key) const {
        return reverse_bits(laine_karras(m_reversed_index, key));
    }

    uint64_t m_pixel_key = 0;
    uint32_t m_reversed_index = 0;
    uint64_t m_dimension = 0;
};

}  // namespace

std::unique_ptr<Sampler> make_sampler(const std::string& name, int samples_per_pixel,
                                      uint64_t seed) {
    if (samples_per_pixel < 1) throw Error("samples per pixel must be at least 1");
    if (name == "independent") return std::make_unique<IndependentSampler>(samples_per_pixel, seed);
    if (name == "stratified") return std::make_unique<StratifiedSampler>(samples_per_pixel, seed);
    if (name == "sobol") return std::make_unique<SobolSampler>(samples_per_pixel, seed);
    throw Error(
        fmt::format("unknown sampler '{}' (expected: independent, stratified, sobol)", name));
}

}  // namespace glint
