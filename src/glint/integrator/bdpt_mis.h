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
// taken to be the same from both sides), as in pbrt.
#include <span>

namespace glint {

/// One vertex of a complete path as the weights see it.
struct MisVertex {
    float pdf_light = 0.0f;   ///< p_L: density of the vertex from the light's walk
    float pdf_camera = 0.0f;  ///< p_C: density of the vertex from the camera's walk
    bool delta = false;       ///< a delta lobe scatters here: no strategy joins here
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

}  // namespace glint
