#pragma once
// A bounding volume hierarchy over lights for next-event estimation (a "light tree"):
// walking down from the root, each step picks a child in proportion to the light it is
// estimated to send to the receiving point (LightBounds::importance), so that near, bright
// lights facing the point get the samples and far or turned-away ones few or none. Lights
// without bounds (the environment, the sun) are chosen alongside the tree, uniformly.
// The probability of any light at any point is computed exactly, for MIS. A light of
// several pieces (an emitting mesh, Light::piece_count) has a leaf for each piece, so the
// tree chooses a triangle rather than a mesh.
#include <glint/light/light_bounds.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace glint {

class Light;

class LightTree {
public:
    /// A light's piece and its bounds; lights with no bounds go in `unbounded`.
    struct Entry {
        const Light* light;
        LightBounds bounds;
        uint32_t piece = 0;
        bool whole = true;  ///< the light is one piece: choices name kWholeLight
    };
    /// The piece a choice names for a light of one piece: sampled whole, with no piece
    /// lookup (the common case, a lamp, costs nothing extra); pmf() takes it as piece 0.
    static constexpr uint32_t kWholeLight = UINT32_MAX;
    LightTree() = default;
    /// `light_count` bounds the lights' indices (Light::index), for the pmf look-up.
    LightTree(std::vector<Entry> bounded, std::vector<const Light*> unbounded, size_t light_count);

    struct Choice {
        const Light* light = nullptr;
        float pmf = 0.0f;
        uint32_t piece = kWholeLight;
    };
    /// A light for the receiving point `p` with unit normal `n` (zero: a point without a
    /// surface); no light only when the scene has none.
    Choice sample(const Vec3& p, const Vec3& n, float u) const;
    /// The probability that sample(p, n, .) returns piece `piece` of `light`.
    float pmf(const Vec3& p, const Vec3& n, const Light& light, uint32_t piece = 0) const;

    size_t node_count() const { return m_nodes.size(); }
    size_t memory_bytes() const;

private:
    struct Node {
        LightBounds bounds;
        uint32_t second_child_or_light = 0;  // interior: its second child (the first follows
                                             // it); leaf: the index into m_leaves
        bool leaf = false;
    };
    struct Leaf {
        const Light* light = nullptr;
        uint32_t piece = 0;
    };
    // Where a light's leaf is: the turns from the root (bit i: 1 = second child at depth i).
    struct Trail {
        uint64_t turns = 0;
        uint32_t depth = 0;
        bool in_tree = false;
    };
    // One light as the build sees it (light_tree.cpp), and where a split goes.
    struct BuildItem;
    struct Split;
    // The build, in three passes. First the shape of the subtree over items[begin, end),
    // into the nodes from `index` on (a subtree of k lights takes 2k - 1 nodes in preorder,
    // so every subtree's place is known before it is built and subtrees can be built in
    // parallel with the same result); each leaf's node goes in leaf_nodes, by its place.
    // Then the leaves' bounds and lights, from the entries; then every inner node's bounds,
    // from its children's (merge_bounds).
    void build_shape(std::vector<BuildItem>& items, size_t begin, size_t end,
                     const Bounds3& centroids, uint32_t index, uint64_t turns, uint32_t depth,
                     std::vector<uint32_t>& leaf_nodes);
    void merge_bounds(uint32_t index, size_t count);
    static Split choose_split(std::vector<BuildItem>& items, size_t begin, size_t end,
                              const Bounds3& centroids, uint32_t depth);
    float probability_of_tree() const;

    // The trail of piece `piece` of the light with index `light_index`; null for none.
    const Trail* trail_of(int light_index, uint32_t piece) const;

    std::vector<Node> m_nodes;
    std::vector<Leaf> m_leaves;
    std::vector<const Light*> m_unbounded;
    // Each light's pieces' trails, from m_trails[m_first_trail[Light::index]] on.
    std::vector<Trail> m_trails;
    std::vector<size_t> m_first_trail;  // by Light::index, and one past the last
};

}  // namespace glint
