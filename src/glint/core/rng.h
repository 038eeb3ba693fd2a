#pragma once
// PCG32 (O'Neill 2014): small state, good statistics, and cheap to seed per pixel and
// sample, which is what makes images independent of thread count.
#include <cstdint>

namespace glint {

// SplitMix64 finaliser: turns structured keys (seed, pixel, index) into well-mixed bits.
inline uint64_t mix_bits(uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ULL;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dULL;
    v ^= v >> 33;
    return v;
}

inline uint64_t hash_combine(uint64_t a, uint64_t b) {
    return mix_bits(a ^ (b + 0x9e3779b97f4a7c15ULL + (a << 6) + (a >> 2)));
}

class Rng {
public:
    Rng() { seed(0); }
    explicit Rng(uint64_t seed_value, uint64_t stream = 0) { seed(seed_value, stream); }

    void seed(uint64_t seed_value, uint64_t stream = 0) {
        m_state = 0;
        m_inc = (stream << 1u) | 1u;
        next_u32();
        m_state += seed_value;
        next_u32();
    }

    uint32_t next_u32() {
        const uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_inc;
        const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
    }

    // Uniform float in [0, 1).
    float next_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }
    double next_double() {
        const uint64_t bits = (static_cast<uint64_t>(next_u32()) << 32) | next_u32();
        return static_cast<double>(bits >> 11) * 0x1p-53;
    }

private:
    uint64_t m_state = 0;
    uint64_t m_inc = 1;
};

}  // namespace glint
