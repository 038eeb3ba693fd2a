#pragma once
// Samplers hand out the random numbers of one pixel sample. They are deterministic in
// (seed, pixel, sample index, dimension) so an image is bit-identical for any thread count.
#include <glint/math/vector.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace glint {

class Sampler {
public:
    Sampler(int samples_per_pixel, uint64_t seed) : m_spp(samples_per_pixel), m_seed(seed) {}
    virtual ~Sampler() = default;

    // Positions the sampler at sample `index` of `pixel`; dimensions restart at 0.
    virtual void start_pixel_sample(Vec2i pixel, int index) = 0;
    // The next value of the sample, in [0, 1).
    virtual float get_1d() = 0;
    // The next two values, as one 2D sample (stratified together where the sampler can).
    virtual Vec2 get_2d() = 0;
    // The 2D sample that positions the film sample inside its pixel.
    virtual Vec2 get_pixel_2d() { return get_2d(); }
    // A fresh sampler with the same settings, for another thread.
    virtual std::unique_ptr<Sampler> clone() const = 0;
    // A fresh sampler for another lane of the same thread, which takes other samples of the
    // same pixels: it may share what this one computes once per pixel (and so must not be
    // used concurrently with it). Gives the same values as clone() would.
    virtual std::unique_ptr<Sampler> clone_for_lane() { return clone(); }

    int samples_per_pixel() const { return m_spp; }
    uint64_t seed() const { return m_seed; }

protected:
    int m_spp;
    uint64_t m_seed;
};

// Names: "independent", "stratified", "sobol". Throws glint::Error for anything else.
std::unique_ptr<Sampler> make_sampler(const std::string& name, int samples_per_pixel,
                                      uint64_t seed);

namespace detail {
// The key of sample `index` of `pixel` under `seed`, from which samplers derive their
// values: the same (seed, pixel, index) always gives the same key.
uint64_t pixel_sample_key(uint64_t seed, Vec2i pixel, int index);

// For tests: the Sobol sampler computes a group's four values with SIMD code chosen by
// what the CPU supports; each path's values for one (shuffled index, group key), which
// must agree bit for bit. `fastest` is the path the sampler uses on this CPU.
struct SobolGroupPaths {
    std::array<float, 4> portable;
    std::array<float, 4> fastest;
};
SobolGroupPaths sobol_group_by_each_path(uint32_t shuffled_index, uint32_t group_key);
}  // namespace detail

}  // namespace glint
