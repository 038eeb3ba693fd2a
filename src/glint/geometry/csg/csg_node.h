#pragma once
// Boolean combinations of solids, and solids placed by a transform.
#include <glint/geometry/csg/solid.h>
#include <glint/math/transform.h>

namespace glint {

enum class CsgOperation { kUnion, kIntersection, kDifference };

// An n-ary CSG node. With `shortcuts` on, the bounding boxes of the children prune work:
// an intersection gives up as soon as one child's box is missed (cheapest children are
// tested first) or the running result is empty; a difference gives up when its first
// child is missed, and skips subtrahends whose boxes the ray misses; a union skips the
// children whose boxes the ray misses. Off, every child is always evaluated (to measure
// what the shortcuts save).
class CsgNode final : public Solid {
public:
    // Throws glint::Error when `children` is empty.
    CsgNode(CsgOperation operation, std::vector<std::shared_ptr<const Solid>> children,
            bool shortcuts);

    void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const override;
    bool contains(const Vec3& p) const override;
    Bounds3 bounds() const override { return m_bounds; }
    float cost() const override { return m_cost; }
    std::string describe() const override;

private:
    void evaluate_union(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const;
    void evaluate_intersection(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const;
    void evaluate_difference(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const;
    bool may_hit(const Ray& ray, const Solid& child) const;

    CsgOperation m_operation;
    std::vector<std::shared_ptr<const Solid>> m_children;
    std::vector<size_t> m_order;  // children by increasing cost (intersection)
    Bounds3 m_bounds;
    float m_cost = 0.0f;
    bool m_shortcuts;
};

class TransformedSolid final : public Solid {
public:
    TransformedSolid(std::shared_ptr<const Solid> child, const Transform& to_parent);
    void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const override;
    bool contains(const Vec3& p) const override;
    Bounds3 bounds() const override;
    float cost() const override { return m_child->cost() + 0.2f; }
    std::string describe() const override { return m_child->describe(); }

private:
    std::shared_ptr<const Solid> m_child;
    Transform m_to_parent;
    Transform m_to_child;
};

}  // namespace glint
