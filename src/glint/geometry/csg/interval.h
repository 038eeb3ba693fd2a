#pragma once
// Interval lists along a ray: the spans of the ray parameter t where the ray is inside a
// solid, each end carrying the surface it crosses. CSG combines solids by combining these
// lists (Roth 1982), so every node knows exactly where the ray is inside it.
#include <glint/math/vector.h>

#include <vector>

namespace glint {

// A crossing of a solid's boundary.
struct Crossing {
    float t = 0.0f;
    Vec3 normal{0.0f};  // outward normal of the combined solid at this crossing (not unit)
    int leaf = -1;      // which primitive solid the surface belongs to (its material)
};

// The ray is inside for t in [enter.t, exit.t]; enter.t may be -inf and exit.t +inf for
// unbounded solids or rays that start inside.
struct Interval {
    Crossing enter;
    Crossing exit;
};

// Sorted, disjoint intervals.
using IntervalList = std::vector<Interval>;

// The boolean operations. Results are sorted and disjoint; touching intervals of a union
// merge. In a difference, the subtracted solid's crossings swap roles and their normals
// flip, so they point out of the result.
void interval_union(const IntervalList& a, const IntervalList& b, IntervalList& out);
void interval_intersection(const IntervalList& a, const IntervalList& b, IntervalList& out);
void interval_difference(const IntervalList& a, const IntervalList& b, IntervalList& out);

// The first crossing after `t_min`, or nullptr when there is none.
const Crossing* first_crossing_after(const IntervalList& list, float t_min);

}  // namespace glint
