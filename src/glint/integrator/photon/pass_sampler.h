#pragma once
// PassSampler, the preview integrator's sampler (integrator/photon/preview.h).
#include <glint/core/rng.h>
#include <glint/core/sampler.h>

#include <cstdint>
#include <memory>

namespace glint {

// The preview's sampler: one sample per pixel per pass, the pass being the sample index.
// The film position is the pass's point of the 2D Sobol sequence (van der Corput and
// Sobol's second dimension, a (0,2)-sequence: any 2^k consecutive passes stratify the
// pixel), shifted by a per-pixel random offset modulo 1 (Cranley-Patterson rotation), so
// that pixels do not share their jitter; every other value is drawn from a PCG stream keyed
// by (seed, pixel, pass). The preview is biased already and its noise is the photons';
// this costs a few hashes per pixel where the Owen-scrambled Sobol sampler costs a
// scramble per group of four values, 7 % of the camera pass. Like every sampler it depends
// only on (seed, pixel, pass): the image is the same for any thread count.
class PassSampler final : public Sampler {
public:
    explicit PassSampler(uint64_t seed = 0) : Sampler(1, seed) {}

    void start_pixel_sample(Vec2i pixel, int index) override {
        const uint64_t packed = (static_cast<uint64_t>(static_cast<uint32_t>(pixel.x)) << 32) |
                                static_cast<uint32_t>(pixel.y);
        const uint64_t pixel_key = hash_combine(m_seed_key, packed);
        m_shift = pixel_key;
        m_index = static_cast<uint32_t>(index);
        m_rng.seed(hash_combine(pixel_key, m_index));
    }
    float get_1d() override { return m_rng.next_float(); }
    Vec2 get_2d() override {
        const float x = m_rng.next_float();
        return Vec2(x, m_rng.next_float());
    }
    // The rotated Sobol point; wrapping 32-bit addition is the shift modulo 1.
    Vec2 get_pixel_2d() override {
        const uint32_t x = bit_reverse(m_index) + static_cast<uint32_t>(m_shift);
        const uint32_t y = sobol_second(m_index) + static_cast<uint32_t>(m_shift >> 32);
        return Vec2(static_cast<float>(x >> 8) * 0x1p-24f, static_cast<float>(y >> 8) * 0x1p-24f);
    }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<PassSampler>(m_seed);
    }
    void set_seed(uint64_t seed) {
        m_seed = seed;
        m_seed_key = mix_bits(seed);
    }

private:
    static uint32_t bit_reverse(uint32_t v) {
        v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
        v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
        v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
        v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
        return (v >> 16) | (v << 16);
    }
    // Sobol's second dimension: its generator matrix is Pascal's triangle mod 2, whose
    // column k is the previous one xor itself shifted by one.
    static uint32_t sobol_second(uint32_t index) {
        uint32_t result = 0;
        for (uint32_t column = 1u << 31; index != 0; index >>= 1, column ^= column >> 1)
            if (index & 1u) result ^= column;
        return result;
    }

    uint64_t m_seed_key = mix_bits(m_seed);
    uint64_t m_shift = 0;
    uint32_t m_index = 0;
    Rng m_rng;
};

}  // namespace glint
