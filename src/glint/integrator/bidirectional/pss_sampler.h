#pragma once
// The primary-sample-space sampler of Metropolis light transport (Kelemen et al. 2002): its
// values are the state of a Markov chain over the unit hypercube, and a mutation changes
// that state rather than drawing a new sample. A path built from the values (the subpaths of
// subpath.h take every random number from a Sampler) is a function of the state, so mutating
// the state mutates the path.
//
// Mutations, one per iteration: a large step replaces every value by a fresh uniform one
// (probability `large_step_probability`), which keeps the chain ergodic; a small step adds to
// each value a normal offset of standard deviation `sigma`, wrapped into [0, 1) (a symmetric
// kernel: T(x -> y) = T(y -> x)). Values are made lazily, when asked for: a value not read
// for n accepted iterations gets the n small steps it missed as one offset of standard
// deviation sigma sqrt(n), or a fresh value if a large step was accepted meanwhile; so a path
// that reads few values costs few, whatever the longest path the chain has made.
//
// Streams: the values are split into interleaved streams (camera, light, connection), each
// with its own running index, so that one stream's i-th value is the same coordinate of the
// state however many values the other streams read: when a mutation changes the length of
// the camera subpath, the light subpath's values stay where they were.
#include <glint/core/rng.h>
#include <glint/core/sampler.h>

#include <array>
#include <vector>

namespace glint {

class PssSampler final : public Sampler {
public:
    enum Stream : int { kCameraStream = 0, kLightStream = 1, kConnectionStream = 2 };
    static constexpr int kStreamCount = 3;

    /// A chain whose random numbers (fresh values, offsets, the choice of step) come from
    /// an RNG keyed by `key`. Its first iteration is a large step.
    PssSampler(uint64_t key, float sigma, float large_step_probability);

    /// Keys the RNG anew (the state is kept): a chain started from a bootstrap sample's state
    /// goes on with random numbers of its own.
    void reseed(uint64_t key);

    /// Starts a mutation: chooses a large or a small step and restarts every stream at its
    /// first value. Then read the values, and accept() or reject().
    void start_iteration();
    /// Makes `stream` the one that get_1d() and get_2d() read from (the camera stream after
    /// start_iteration); a stream keeps its running index when another one is read.
    void set_stream(int stream);
    /// Keeps the values of this iteration.
    void accept();
    /// Restores every value this iteration changed, exactly, as if it never happened.
    void reject();

    /// A uniform number in [0, 1) from the chain's RNG that is no part of the state (the
    /// acceptance test's).
    float uniform() { return m_rng.next_float(); }

    bool large_step() const { return m_large_step; }
    /// Values made so far (all streams, interleaved).
    int dimensions() const { return static_cast<int>(m_values.size()); }
    /// The current value of value `index` of `stream`, without mutating it (tests).
    float peek(int stream, int index) const;

    /// Not positioned by pixels: throws glint::Error.
    void start_pixel_sample(Vec2i pixel, int index) override;
    float get_1d() override;
    Vec2 get_2d() override;
    std::unique_ptr<Sampler> clone() const override;

private:
    struct Value {
        float value = 0.0f;
        int64_t modified = -1;  ///< iteration that last set `value`; -1: never
        float backup = 0.0f;    ///< before this iteration changed it
        int64_t backup_modified = -1;
    };
    // Brings value `dimension` up to the current iteration (see the header comment).
    float update(int dimension);

    Rng m_rng;
    float m_sigma;
    float m_large_step_probability;
    std::vector<Value> m_values;
    // Iterations count accepted mutations (a rejected one is undone), so that the offsets a
    // lazily updated value receives are those of the accepted steps it missed.
    int64_t m_iteration = 0;
    int64_t m_last_large_step = 0;  ///< the last accepted large step (0: the first iteration)
    bool m_large_step = true;
    int m_stream = kCameraStream;
    std::array<int, kStreamCount> m_next{};  ///< running index of each stream
};

}  // namespace glint
