#pragma once
// Multiple importance sampling for bidirectional path tracing (Veach 1997, sec. 10.2-10.3):
// a path of k vertices x_0 (on a light) ... x_{k-1} (on the lens) can be made by k
// strategies, s = 0 .. k-1 vertices from the light and t = k - s >= 1 from the camera. With
// p_L(i) the density with which a light walk makes x_i (given x_0 .. x_{i-1}) and p_C(i) the
// density with which a camera walk makes it (given x_{k-1} .. x_{i+1}), strategy s has
//   p_s = p_L(0) ... p_L(s-1) p_C(s) ... p_C(k-1),
// and its weight is p_s^b / sum_j p_j^b (b = 1: balance heuristic, b = 2: power). These
// densities belong to the path, not to the strategy that made it, so the weights of one path
// sum to 1. The ratios p_{s-1} / p_s = p_C(s-1) / p_L(s-1) and p_{s+1} / p_s =
// p_L(s) / p_C(s) give every weight in one pass, without products that under- or overflow.
//
// Strategies that cannot make the path are left out: one that would join the subpaths at a
// vertex with a delta lobe (x_{j-1} or x_j, for s = j >= 1), and s = 0 when the light is a
// delta light (a point, a spot or a direction: no camera path hits it). A delta vertex
// stores its densities as 0, counted as 1 in the ratios (the delta lobe's probability is
// taken to be the same from both sides), as in pbrt; but the two densities that enter a
// chain of delta vertices, one from each side, are not per unit area at the chain's first
// vertex as pbrt has them: the caller gives them as each walk makes the chain's far end
// (bdpt.cpp, weigh_specular_chains), else light tracing and merging are weighed far too low
// for caustics seen directly or through glass.
//
// Vertex connection and merging (Georgiev et al. 2012) adds one more strategy per inner
// vertex x_i (1 <= i <= k-2, no delta lobe there): the camera walk makes x_{k-1} .. x_i, the
// light walk x_0 .. x_{i-1} and then a point near x_i, accepted within a disc of radius r.
// With n light paths merged per camera path its density counts as
//   p_VM(i) = p_i p_L(i) eta,   eta = n pi r^2,
// against 1 light path per camera path for the connections (Georgiev's eta_VCM). The same
// ratios give its weight, and the weights of connections and merges of a path sum to 1.
//
// Sample counts (Veach's n_j in n_s p_s / sum_j n_j p_j): every connection with t >= 2 and
// every merge is made once per camera subpath, so their counts are 1 and eta. Light tracing
// (t = 1, the strategy s = k - 1) is made once per light subpath, and the lens density p_C
// of x_{k-1} is over the whole frame (camera.h): with n_L light subpaths for n_C camera
// subpaths (pixels) per iteration its count is n_L / n_C, 1 for bdpt.
#include <span>

namespace glint {

/// One vertex of a complete path as the weights see it.
struct MisVertex {
    float pdf_light = 0.0f;   ///< p_L: density of the vertex from the light's walk
    float pdf_camera = 0.0f;  ///< p_C: density of the vertex from the camera's walk
    bool delta = false;       ///< a delta lobe scatters here: no strategy joins here
    /// A merge here against one on a surface: 1 on a surface, 0 where no merge happens (a
    /// point in a medium when merging is on surfaces only), and at a point in a medium the
    /// ball's volume over the disc's area, 4 r / 3 (its merges count n_L 4/3 pi r^3 where
    /// a surface's count n_L pi r^2).
    float merge_scale = 1.0f;
};

enum class MisHeuristic {
    kBalance,  ///< p_s / sum p_j
    kPower,    ///< p_s^2 / sum p_j^2
};

/// The weight of strategy `s` (light vertices; 0 <= s < path.size()) for `path`, ordered from
/// the light (index 0) to the lens (the last). `delta_light`: x_0 is a delta light, which
/// strategy 0 cannot hit.
float strategy_weight(std::span<const MisVertex> path, int s, bool delta_light,
                      MisHeuristic heuristic);

/// The weight of a strategy of vertex connection and merging for `path` (as above): the
/// connection with `s` light vertices (merge false), or the merge at vertex x_s (merge true,
/// 1 <= s <= path.size() - 2), among every connection and every merge that can make the
/// path. `merge_eta` is eta = n pi r^2 (n light paths merged, r the merging radius, in the
/// units of the per-area densities); 0 leaves merging out, which is strategy_weight.
/// `light_tracing_count` is n_L / n_C, the count of strategy s = path.size() - 1 (t = 1)
/// relative to the others (see above); 1 when there is one light subpath per camera subpath.
float vcm_strategy_weight(std::span<const MisVertex> path, int s, bool merge, bool delta_light,
                          float merge_eta, MisHeuristic heuristic,
                          float light_tracing_count = 1.0f);

}  // namespace glint
