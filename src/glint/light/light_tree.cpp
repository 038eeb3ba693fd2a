#include <glint/core/error.h>
#include <glint/light/light.h>
#include <glint/light/light_tree.h>

#include <algorithm>

namespace glint {
namespace {

// The first child's share of the light reaching p, from the two importances. Where neither
// child can reach p (the parent's looser bounds could), the walk goes on by power: every
// light then keeps a positive probability unless a sibling branch certainly outweighs it, so
// the probabilities over all lights sum to 1, and a light that gets 0 certainly sends p
// nothing.
float first_share(const LightBounds& first, const LightBounds& second, const Vec3& p,
                  const Vec3& n) {
    const float a = first.importance(p, n), b = second.importance(p, n);
    if (a + b > 0.0f) return a / (a + b);
    return first.phi / (first.phi + second.phi);
}

}  // namespace

LightTree::LightTree(std::vector<Entry> bounded, std::vector<const Light*> unbounded,
                     size_t light_count)
    : m_unbounded(std::move(unbounded)), m_trails(light_count) {
    // Lights that emit nothing never need a sample: leaving them out keeps their pmf 0.
    std::erase_if(bounded, [](const Entry& e) { return !(e.bounds.phi > 0.0f); });
    if (bounded.empty()) return;
    if (bounded.size() >= (uint64_t(1) << 31))
        throw Error("the light tree holds at most 2^31 lights");
    m_nodes.reserve(2 * bounded.size() - 1);
    m_leaf_lights.reserve(bounded.size());
    build(bounded, 0, bounded.size(), 0, 0);
}

// Splits at the median of the centroids along the widest axis of their box: a balanced tree
// (depth log2 n, so a light's trail fits 64 bits) built in O(n log n) with nth_element.
uint32_t LightTree::build(std::vector<Entry>& entries, size_t begin, size_t end, uint64_t turns,
                          uint32_t depth) {
    const uint32_t index = static_cast<uint32_t>(m_nodes.size());
    m_nodes.emplace_back();
    if (end - begin == 1) {
        const Entry& e = entries[begin];
        m_nodes[index] = Node{e.bounds, static_cast<uint32_t>(m_leaf_lights.size()), true};
        m_leaf_lights.push_back(e.light);
        const int light_index = e.light->index();
        if (light_index >= 0 && static_cast<size_t>(light_index) < m_trails.size())
            m_trails[light_index] = Trail{turns, depth, true};
        return index;
    }
    Bounds3 centroids;
    for (size_t i = begin; i < end; ++i) centroids.expand(entries[i].bounds.bounds.center());
    const Vec3 extent = centroids.extent();
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t middle = begin + (end - begin) / 2;
    std::nth_element(entries.begin() + begin, entries.begin() + middle, entries.begin() + end,
                     [axis](const Entry& a, const Entry& b) {
                         return a.bounds.bounds.center()[axis] < b.bounds.bounds.center()[axis];
                     });
    build(entries, begin, middle, turns, depth + 1);
    const uint32_t second = build(entries, middle, end, turns | (uint64_t(1) << depth), depth + 1);
    const LightBounds merged =
        LightBounds::merged(m_nodes[index + 1].bounds, m_nodes[second].bounds);
    m_nodes[index] = Node{merged, second, false};
    return index;
}

// The tree as a whole is one choice among the unbounded lights, all equally likely.
float LightTree::probability_of_tree() const {
    if (m_nodes.empty()) return 0.0f;
    return 1.0f / static_cast<float>(m_unbounded.size() + 1);
}

LightTree::Choice LightTree::sample(const Vec3& p, const Vec3& n, float u) const {
    const float p_tree = probability_of_tree();
    const float p_unbounded = 1.0f - p_tree;
    if (u < p_unbounded) {
        const size_t count = m_unbounded.size();
        const size_t i = std::min(static_cast<size_t>(u / p_unbounded * count), count - 1);
        return {m_unbounded[i], p_unbounded / static_cast<float>(count)};
    }
    u = std::min((u - p_unbounded) / p_tree, kOneMinusEpsilon);
    float pmf = p_tree;
    uint32_t node = 0;
    while (!m_nodes[node].leaf) {
        const uint32_t second = m_nodes[node].second_child_or_light;
        const float share = first_share(m_nodes[node + 1].bounds, m_nodes[second].bounds, p, n);
        if (u < share) {
            u = std::min(u / share, kOneMinusEpsilon);
            pmf *= share;
            ++node;
        } else {
            u = std::min((u - share) / (1.0f - share), kOneMinusEpsilon);
            pmf *= 1.0f - share;
            node = second;
        }
    }
    return {m_leaf_lights[m_nodes[node].second_child_or_light], pmf};
}

float LightTree::pmf(const Vec3& p, const Vec3& n, const Light& light) const {
    const float p_tree = probability_of_tree();
    if (std::find(m_unbounded.begin(), m_unbounded.end(), &light) != m_unbounded.end())
        return (1.0f - p_tree) / static_cast<float>(m_unbounded.size());
    const int index = light.index();
    if (index < 0 || static_cast<size_t>(index) >= m_trails.size()) return 0.0f;
    const Trail& trail = m_trails[index];
    if (!trail.in_tree) return 0.0f;
    float pmf = p_tree;
    uint32_t node = 0;
    for (uint32_t level = 0; level < trail.depth; ++level) {
        const uint32_t second = m_nodes[node].second_child_or_light;
        const float share = first_share(m_nodes[node + 1].bounds, m_nodes[second].bounds, p, n);
        if ((trail.turns >> level) & 1u) {
            pmf *= 1.0f - share;
            node = second;
        } else {
            pmf *= share;
            ++node;
        }
    }
    return pmf;
}

size_t LightTree::memory_bytes() const {
    return m_nodes.capacity() * sizeof(Node) + m_leaf_lights.capacity() * sizeof(const Light*) +
           m_unbounded.capacity() * sizeof(const Light*) + m_trails.capacity() * sizeof(Trail);
}

}  // namespace glint
