#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/core/sampler.h>
#include <glint/core/sobol_sampler.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

uint64_t detail::pixel_sample_key(uint64_t seed, Vec2i pixel, int index) {
    const uint64_t packed_pixel = (static_cast<uint64_t>(static_cast<uint32_t>(pixel.x)) << 32) |
                                  static_cast<uint32_t>(pixel.y);
    return hash_combine(hash_combine(mix_bits(seed), packed_pixel), static_cast<uint64_t>(index));
}

namespace {

using detail::pixel_sample_key;

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
