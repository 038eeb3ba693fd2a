#include <glint/core/error.h>
#include <glint/geometry/csg/csg_node.h>

#include <algorithm>
#include <numeric>

namespace glint {
namespace {

Bounds3 infinite_bounds() {
    return {Vec3(-kInfinity), Vec3(kInfinity)};
}

Bounds3 overlap(const Bounds3& a, const Bounds3& b) {
    return {glm::max(a.min, b.min), glm::min(a.max, b.max)};
}

}  // namespace

CsgNode::CsgNode(CsgOperation operation, std::vector<std::shared_ptr<const Solid>> children,
                 bool shortcuts)
    : m_operation(operation), m_children(std::move(children)), m_shortcuts(shortcuts) {
    if (m_children.empty()) throw Error("a CSG node needs at least one solid");
    m_order.resize(m_children.size());
    std::iota(m_order.begin(), m_order.end(), 0);
    // Intersections evaluate finite children first: a ray that meets an infinite quadric
    // very often misses the finite solid that bounds it, and then the result is empty
    // before any quadric is evaluated. Within each group, the cheapest first.
    std::stable_sort(m_order.begin(), m_order.end(), [&](size_t a, size_t b) {
        const bool finite_a = m_children[a]->is_bounded(), finite_b = m_children[b]->is_bounded();
        if (finite_a != finite_b) return finite_a;
        return m_children[a]->cost() < m_children[b]->cost();
    });
    for (const auto& child : m_children) {
        m_cost += child->cost();
        m_child_bounds.push_back(child->bounds());
    }

    switch (m_operation) {
        case CsgOperation::kUnion:
            for (const auto& child : m_children) m_bounds.expand(child->bounds());
            break;
        case CsgOperation::kIntersection:
            m_bounds = infinite_bounds();
            for (const auto& child : m_children) m_bounds = overlap(m_bounds, child->bounds());
            break;
        case CsgOperation::kDifference:
            m_bounds = m_children.front()->bounds();
            break;
    }
}

std::string CsgNode::describe() const {
    switch (m_operation) {
        case CsgOperation::kUnion:
            return "union";
        case CsgOperation::kIntersection:
            return "intersection";
        default:
            return "difference";
    }
}

bool CsgNode::may_hit(const Ray& ray, size_t child) const {
    float t0, t1;
    return ray_box_range(ray, m_child_bounds[child], t0, t1);
}

void CsgNode::intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const {
    out.clear();
    switch (m_operation) {
        case CsgOperation::kUnion:
            evaluate_union(ray, out, scratch);
            break;
        case CsgOperation::kIntersection:
            evaluate_intersection(ray, out, scratch);
            break;
        case CsgOperation::kDifference:
            evaluate_difference(ray, out, scratch);
            break;
    }
}

void CsgNode::evaluate_union(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const {
    IntervalList& child_spans = scratch.acquire();
    IntervalList& merged = scratch.acquire();
    for (size_t i = 0; i < m_children.size(); ++i) {
        if (m_shortcuts && !may_hit(ray, i)) continue;
        m_children[i]->intervals(ray, child_spans, scratch);
        if (child_spans.empty()) continue;
        interval_union(out, child_spans, merged);
        out.swap(merged);
    }
    scratch.release(2);
}

void CsgNode::evaluate_intersection(const Ray& ray, IntervalList& out,
                                    IntervalScratch& scratch) const {
    if (m_shortcuts) {
        // The overlap of the children's boxes holds the whole intersection: one test,
        // tighter than testing each child's box.
        float t0, t1;
        if (!ray_box_range(ray, m_bounds, t0, t1)) return;
    }
    IntervalList& child_spans = scratch.acquire();
    IntervalList& merged = scratch.acquire();
    bool first = true;
    for (size_t index : m_order) {
        m_children[index]->intervals(ray, child_spans, scratch);
        if (first) {
            out.swap(child_spans);
            first = false;
        } else {
            interval_intersection(out, child_spans, merged);
            out.swap(merged);
        }
        if (m_shortcuts && out.empty()) break;
    }
    scratch.release(2);
}

void CsgNode::evaluate_difference(const Ray& ray, IntervalList& out,
                                  IntervalScratch& scratch) const {
    if (m_shortcuts && !may_hit(ray, 0)) return;
    m_children.front()->intervals(ray, out, scratch);
    IntervalList& child_spans = scratch.acquire();
    IntervalList& merged = scratch.acquire();
    for (size_t i = 1; i < m_children.size(); ++i) {
        if (m_shortcuts && (out.empty() || !may_hit(ray, i))) continue;
        m_children[i]->intervals(ray, child_spans, scratch);
        interval_difference(out, child_spans, merged);
        out.swap(merged);
    }
    scratch.release(2);
}

bool CsgNode::contains(const Vec3& p) const {
    switch (m_operation) {
        case CsgOperation::kUnion:
            return std::any_of(m_children.begin(), m_children.end(),
                               [&](const auto& c) { return c->contains(p); });
        case CsgOperation::kIntersection:
            return std::all_of(m_children.begin(), m_children.end(),
                               [&](const auto& c) { return c->contains(p); });
        default:
            if (!m_children.front()->contains(p)) return false;
            return std::none_of(m_children.begin() + 1, m_children.end(),
                                [&](const auto& c) { return c->contains(p); });
    }
}

// ---------------------------------------------------------------------------------------
TransformedSolid::TransformedSolid(std::shared_ptr<const Solid> child, const Transform& to_parent)
    : m_child(std::move(child)), m_to_parent(to_parent), m_to_child(to_parent.inverse()) {}

void TransformedSolid::intervals(const Ray& ray, IntervalList& out,
                                 IntervalScratch& scratch) const {
    // The parameter t is the same in both spaces because the direction is not renormalised.
    const Ray local{m_to_child.point(ray.origin), m_to_child.vector(ray.direction), ray.t_min,
                    ray.t_max};
    m_child->intervals(local, out, scratch);
    for (Interval& span : out) {
        span.enter.normal = m_to_parent.normal(span.enter.normal);
        span.exit.normal = m_to_parent.normal(span.exit.normal);
    }
}

bool TransformedSolid::contains(const Vec3& p) const {
    return m_child->contains(m_to_child.point(p));
}

Bounds3 TransformedSolid::bounds() const {
    const Bounds3 b = m_child->bounds();
    if (!is_finite(b.min) || !is_finite(b.max)) return infinite_bounds();
    return b.transformed(m_to_parent);
}

}  // namespace glint
