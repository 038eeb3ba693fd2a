#pragma once
// A Solid is a region of space, not just a surface: it reports every span of a ray that
// lies inside it and answers point membership. Leaf solids (sphere, box, quadrics, closed
// meshes) and CSG nodes share this interface, so nodes nest freely.
#include <glint/core/ray.h>
#include <glint/geometry/csg/interval.h>
#include <glint/math/bounds.h>

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace glint {

// Reusable interval lists, one per level of the CSG tree, so evaluating a ray does not
// allocate once the lists have grown.
class IntervalScratch {
public:
    IntervalList& acquire() {
        if (m_used == m_lists.size()) m_lists.emplace_back();
        IntervalList& list = m_lists[m_used++];
        list.clear();
        return list;
    }
    void release(size_t count) { m_used -= count; }

private:
    std::deque<IntervalList> m_lists;  // a deque: acquired references stay valid as it grows
    size_t m_used = 0;
};

class Solid {
public:
    virtual ~Solid() = default;

    // All spans of the (infinite) line o + t d inside the solid, sorted; `t` ranges over
    // all reals so that rays starting inside are handled.
    virtual void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const = 0;
    virtual bool contains(const Vec3& p) const = 0;
    // Infinite extents on unbounded axes.
    virtual Bounds3 bounds() const = 0;
    // Relative cost of intervals(), so intersection nodes can test cheap children first.
    virtual float cost() const { return 1.0f; }
    virtual std::string describe() const = 0;

    bool is_bounded() const {
        const Bounds3 b = bounds();
        return !b.is_empty() && is_finite(b.min) && is_finite(b.max);
    }
};

// The parameter range [t0, t1] in which `ray` crosses `box`; false when it misses. Infinite
// boxes are handled (an unbounded axis never clips).
bool ray_box_range(const Ray& ray, const Bounds3& box, float& t0, float& t1);

}  // namespace glint
