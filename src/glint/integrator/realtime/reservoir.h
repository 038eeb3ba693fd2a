#pragma once
// Weighted reservoir sampling (Chao 1982), the data structure of ReSTIR (Bitterli et al.
// 2020): a stream of candidates, each with a resampling weight w, goes through one slot;
// the slot keeps candidate i with probability w_i / sum(w), so whatever the stream's
// length, the kept sample was chosen in proportion to its weight, and the reservoir needs
// no more memory than one sample. Besides the sample it keeps what reuse needs:
//   weight_sum  the sum of the weights it has seen (the RIS estimate's numerator),
//   count       M, the number of candidates the weights stand for (a reservoir merged into
//               another stands for all the candidates it saw),
//   target      the target function at the sample, where the reservoir's owner evaluated it,
//   W           the unbiased contribution weight of the sample, set by finish(): an estimate
//               of 1 / (the density the sample has), so that f(y) W estimates the integral
//               of f.

namespace glint {

template <typename Sample>
struct Reservoir {
    Sample sample{};
    float weight_sum = 0.0f;
    float count = 0.0f;   ///< M; a float, since temporal reuse caps and scales it
    float target = 0.0f;  ///< the owner's target function at `sample`
    float W = 0.0f;       ///< unbiased contribution weight of `sample` (0: none)

    bool has_sample() const { return W > 0.0f; }

    /// Offers a candidate of resampling weight `w` whose target at the owner is `target`;
    /// `u` uniform in [0, 1) decides. True when it replaced the sample. Does not change
    /// `count`: a caller that streams raw candidates adds one per candidate (those that
    /// carry nothing included), a merge adds the other reservoir's count.
    bool update(const Sample& candidate, float w, float candidate_target, float u) {
        if (!(w > 0.0f)) return false;
        weight_sum += w;
        if (u * weight_sum >= w) return false;
        sample = candidate;
        target = candidate_target;
        return true;
    }

    /// Offers another reservoir's sample as one candidate standing for its `count`
    /// candidates: its weight is the target here times its contribution weight times its
    /// count (target_here = this owner's target function at other.sample).
    bool merge(const Reservoir& other, float target_here, float u) {
        const bool chosen =
            other.has_sample() &&
            update(other.sample, target_here * other.W * other.count, target_here, u);
        count += other.count;
        return chosen;
    }

    /// RIS's contribution weight with the 1/M weights: weight_sum / (M target). Unbiased
    /// when every candidate came from a density that covers wherever the target is
    /// non-zero (raw candidates from one light sampler); biased when merged reservoirs
    /// could not have produced the sample (see restir_di.h).
    void finish_uniform() {
        W = (target > 0.0f && count > 0.0f) ? weight_sum / (count * target) : 0.0f;
    }

    /// The contribution weight with a multiple-importance weight `mis` of the chosen
    /// sample (Bitterli et al. 2020, eq. 22 and Algorithm 6): weight_sum mis / target. Any
    /// weights that sum to one over the candidates that could have produced the sample
    /// keep the estimate unbiased.
    void finish_weighted(float mis) { W = (target > 0.0f) ? weight_sum * mis / target : 0.0f; }
};

}  // namespace glint
