#pragma once
// Boolean combinations of solids, and solids placed by a transform.
#include <glint/geometry/csg/solid.h>
#include <glint/math/transform.h>

namespace glint {

enum class CsgOperation { kUnion, kIntersection, kDifference };

// An n-ary CSG node. With `shortcuts` on, the bounding boxes of the children prune work:
// an intersection gives up when the ray misses the overlap of its children's boxes, and
// as soon as the running result is empty (finite children are evaluated first, since a
// ray that meets an infinite quadric often misses the solid bounding it; within that,
// the cheapest first); a difference gives up when its first child is missed, and skips
// subtrahends whose boxes the ray misses; a union skips the children whose boxes the ray
// misses. Off, every child is always evaluated (to measure what the shortcuts save).
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
    bool may_hit(const Ray& ray, size_t child) const;

    CsgOperation m_operation;
    std::vector<std::shared_ptr<const Solid>> m_children;
    std::vector<size_t> m_order;  // intersection: finite children first, then by cost
    // The children's boxes, computed once: bounds() can be costly (a transformed solid
    // transforms eight corners), and the shortcuts test them for every ray.
    std::vector<Bounds3> m_child_bounds;
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
