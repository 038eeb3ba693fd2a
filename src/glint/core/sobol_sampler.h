#pragma once
// Owen-scrambled Sobol sampling, declared in a header of its own so that hot loops which
// know their sampler is this one (the path tracer's bounce loop) call get_1d() and get_2d()
// directly, inlined, rather than through Sampler's virtual table. Everyone else uses it as
// a plain Sampler via make_sampler("sobol", ...).
#include <glint/core/sampler.h>

#include <array>
#include <cstdint>
#include <memory>

namespace glint {

namespace detail {
class SobolTables;  // sobol_sampler.cpp
// A group's four values in vector lanes (GCC/Clang vector extension; SSE on x86-64).
using SobolLanes = float __attribute__((vector_size(16)));
using SobolScramble = SobolLanes (*)(const SobolTables&, uint32_t reversed_shuffled, uint32_t key);
}  // namespace detail

/// Owen-scrambled Sobol, "padded" in groups of four dimensions: each group is Sobol's first
/// four dimensions with its own shuffle of the sample index and its own scramble, keyed by
/// (seed, pixel, group) (Burley 2020). A 2D request always starts a group, so it gets the
/// first two dimensions, a (0,2)-sequence; 1D requests take the group's next free dimension,
/// each a (0,1)-sequence. An integrator that asks for a 2D and two 1D values per step (the
/// light sample, then the BSDF sample with its lobe choice and roulette) thus uses a whole
/// group per step, and a group's four values are computed together, in vector lanes. Any
/// prefix of a pixel's samples is well stratified, which adaptive sampling relies on.
class SobolSampler final : public Sampler {
public:
    SobolSampler(int spp, uint64_t seed);

    void start_pixel_sample(Vec2i pixel, int index) override;

    Vec2 get_2d() override {
        open_group();
        m_ahead_next = 2;
        return Vec2(m_ahead[0], m_ahead[1]);
    }
    // 1D values take the open group's remaining dimensions, then the next group's.
    float get_1d() override {
        if (m_ahead_next >= kGroupSize) open_group();
        return m_ahead[m_ahead_next++];
    }

    std::unique_ptr<Sampler> clone() const override;
    // Lanes of one thread take samples of the same pixel: they share its group keys.
    std::unique_ptr<Sampler> clone_for_lane() override;

private:
    static constexpr int kGroupSize = 4;
    static constexpr uint32_t kCachedKeys = 32;  // deeper groups are hashed each time

    // The group keys of the pixel last started, hashed as they are first asked for.
    struct PixelKeys {
        Vec2i pixel{-1, -1};  // no pixel yet: film pixels are never negative
        uint64_t pixel_key = 0;
        uint32_t cached = 0;  // keys[0, cached) hold this pixel's first keys
        std::array<uint32_t, kCachedKeys> keys{};
    };

    // Computes the next group's four values into m_ahead and makes them the open group.
    void open_group();
    uint32_t group_key(uint32_t group);

    const detail::SobolTables* m_tables;
    detail::SobolScramble m_scramble_group;
    std::shared_ptr<PixelKeys> m_keys;  // shared with the lanes cloned from this sampler
    uint32_t m_reversed_index = 0;
    uint32_t m_next_group = 0;
    // The open group's values: m_ahead[m_ahead_next, kGroupSize) are the next 1D values;
    // m_ahead_next == kGroupSize when no group is open.
    float m_ahead[kGroupSize] = {};
    int m_ahead_next = kGroupSize;
};

}  // namespace glint
