#pragma once
// A bounding volume hierarchy over lights for next-event estimation (a "light tree"):
// walking down from the root, each step picks a child in proportion to the light it is
// estimated to send to the receiving point (LightBoundsX4::importances), so that near,
// bright lights facing the point get the samples and far or turned-away ones few or none.
// Lights without bounds (the environment, the sun) are chosen alongside the tree, uniformly.
// The probability of any light at any point is computed exactly, for MIS. A light of
// several pieces (an emitting mesh, Light::piece_count) has a leaf for each piece, so the
// tree chooses a triangle rather than a mesh.
//
// The tree is built binary (a split cost over power, size and orientation) and then
// collapsed into a 4-wide tree, whose nodes keep their children's bounds lane by lane: each
// step of the walk weighs four children with one SIMD evaluation, and half as many steps
// reach a leaf.
#include <glint/light/light_bounds.h>

#include <array>
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

    /// The 4-wide nodes, and the leaves (one per light piece that emits).
    size_t node_count() const { return m_nodes.size(); }
    size_t leaf_count() const { return m_leaves.size(); }
    size_t memory_bytes() const;

private:
    // A node of the binary tree the build makes (and then collapses).
    struct BinaryNode {
        LightBounds bounds;
        uint32_t second_child_or_leaf = 0;  // interior: its second child (the first follows
                                            // it); leaf: the index into m_leaves
        bool leaf = false;
    };
    // A node of the 4-wide tree the walks use: up to four children, each another node or a
    // leaf (kLeafChild | leaf index); lanes without a child have no power.
    struct WideNode {
        LightBoundsX4 children;
        std::array<uint32_t, 4> child{};
        uint32_t parent = 0;          // the root is its own parent
        uint32_t lane_in_parent = 0;  // which of the parent's children this node is
    };
    static constexpr uint32_t kLeafChild = 0x80000000u;
    struct Leaf {
        const Light* light = nullptr;
        uint32_t piece = 0;
        uint32_t node = 0;  // the wide node that holds the leaf, and in which lane
        uint32_t lane = 0;
    };
    // One light as the build sees it (light_tree.cpp), and where a split goes.
    struct BuildItem;
    struct Split;
    // The build, in four passes. First the shape of the binary subtree over
    // items[begin, end), into the nodes from `index` on (a subtree of k lights takes 2k - 1
    // nodes in preorder, so every subtree's place is known before it is built and subtrees
    // can be built in parallel with the same result); each leaf's node goes in leaf_nodes,
    // by its place. Then the leaves' bounds and lights, from the entries; then every inner
    // node's bounds, from its children's (merge_bounds); then the collapse to 4 wide.
    void build_shape(std::vector<BinaryNode>& nodes, std::vector<BuildItem>& items, size_t begin,
                     size_t end, const Bounds3& centroids, uint32_t index, uint32_t depth,
                     std::vector<uint32_t>& leaf_nodes);
    static void merge_bounds(std::vector<BinaryNode>& nodes, uint32_t index, size_t count);
    void collapse(const std::vector<BinaryNode>& nodes);
    static Split choose_split(std::vector<BuildItem>& items, size_t begin, size_t end,
                              const Bounds3& centroids, uint32_t depth);
    float probability_of_tree() const;
    // The probability of each lane of `node` at p, and the lane that u picks (u is then
    // rescaled for the next step).
    struct Step {
        uint32_t lane = 0;
        float probability = 0.0f;
    };
    static Step choose_child(const WideNode& node, const Vec3& p, const Vec3& n, float& u);
    static float child_probability(const WideNode& node, uint32_t lane, const Vec3& p,
                                   const Vec3& n);

    // The leaf of piece `piece` of the light with index `light_index`; null for none.
    const Leaf* leaf_of(int light_index, uint32_t piece) const;

    std::vector<WideNode> m_nodes;
    std::vector<Leaf> m_leaves;
    std::vector<const Light*> m_unbounded;
    // Each light's pieces' leaves, from m_leaf_of[m_first_piece[Light::index]] on (UINT32_MAX
    // for none: a piece that emits nothing).
    std::vector<uint32_t> m_leaf_of;
    std::vector<size_t> m_first_piece;  // by Light::index, and one past the last
};

}  // namespace glint
