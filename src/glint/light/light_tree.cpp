#include <glint/core/error.h>
#include <glint/light/light.h>
#include <glint/light/light_tree.h>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace glint {
namespace {

constexpr float kPiF = 3.14159265358979f;
// Bins of the centroids along the widest axis when a node looks for its split.
constexpr int kBins = 16;
// Nodes with fewer lights split at the median: the bins' cost search costs more than it
// gains there (on bench/many_lights_clustered.lua, binning from 4, 8, 16 or 32 lights on
// gave the same error within the noise; from 16 on the build takes a sixth less time than
// from 4).
constexpr size_t kBinnedFrom = 16;
// Subtrees with fewer lights are built by the calling thread: below this a task costs more
// than it saves.
constexpr size_t kParallelFrom = 4096;

// A box round a set of unit directions: merged by min and max, far cheaper than merging
// cones (which takes an acos per merge), and good enough for the split cost. The cone
// round it (cos_theta) is only an estimate, never used as a bound.
struct DirectionBox {
    Vec3 min{kInfinity};
    Vec3 max{-kInfinity};

    void expand(const DirectionBox& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    // The box round a cone: along each axis the directions reach from the cone's edge
    // nearest -axis to its edge nearest +axis; an axis inside the cone is reached fully.
    static DirectionBox of(const DirectionCone& cone) {
        DirectionBox box;
        if (cone.empty) return box;
        for (int i = 0; i < 3; ++i) {
            box.max[i] = cos_of_difference(cone.axis[i], cone.cos_theta);
            box.min[i] = -cos_of_difference(-cone.axis[i], cone.cos_theta);
        }
        return box;
    }
    // The cosine of the half-angle of a cone round the box's corners about its centre's
    // direction; -1 when the box holds the origin (directions every way).
    float cos_theta() const {
        if (min.x > max.x) return 1.0f;
        if (min.x <= 0.0f && max.x >= 0.0f && min.y <= 0.0f && max.y >= 0.0f && min.z <= 0.0f &&
            max.z >= 0.0f)
            return -1.0f;
        const Vec3 axis = glm::normalize(0.5f * (min + max));
        float cos_theta = 1.0f;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 c(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y,
                         corner & 4 ? max.z : min.z);
            const float length = glm::length(c);
            if (length > 0.0f) cos_theta = std::min(cos_theta, glm::dot(axis, c) / length);
        }
        return std::max(cos_theta, -1.0f);
    }

private:
    // cos(max(0, a - b)) from the cosines of angles a, b in [0, pi].
    static float cos_of_difference(float cos_a, float cos_b) {
        if (cos_a >= cos_b) return 1.0f;
        return cos_a * cos_b + std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a)) *
                                   std::sqrt(std::max(0.0f, 1.0f - cos_b * cos_b));
    }
};

// The measure of the directions a cluster emits into, weighted by the cosine of the angle
// past its normal cone: the solid angle of the normal cone (half-angle theta_o) plus, over
// the spread theta_e beyond it, the integral of cos(theta - theta_o) 2 pi sin(theta) from
// theta_o to theta_w = min(theta_o + theta_e, pi). Conty Estevez and Kulla's orientation
// term: a cluster whose lights face many ways is costly to keep together.
float orientation_measure(float cos_theta_o, float cos_theta_e) {
    cos_theta_o = std::clamp(cos_theta_o, -1.0f, 1.0f);
    cos_theta_e = std::clamp(cos_theta_e, -1.0f, 1.0f);
    // Surfaces (cos_theta_e 0) and single normals (cos_theta_o 1) are the common cases: no
    // acos for those.
    const float theta_o = cos_theta_o == 1.0f ? 0.0f : std::acos(cos_theta_o);
    const float theta_e = cos_theta_e == 0.0f ? 0.5f * kPiF : std::acos(cos_theta_e);
    const float sin_theta_o = std::sqrt(1.0f - cos_theta_o * cos_theta_o);
    // cos(2 theta_w - theta_o): with theta_w = pi that is cos(theta_o); otherwise
    // cos(theta_o + 2 theta_e), spelt out so that no cos call is needed.
    float cos_far = cos_theta_o;
    float theta_w = kPiF;
    if (theta_o + theta_e < kPiF) {
        theta_w = theta_o + theta_e;
        const float sin_theta_e = std::sqrt(1.0f - cos_theta_e * cos_theta_e);
        const float cos_2e = 2.0f * cos_theta_e * cos_theta_e - 1.0f;
        const float sin_2e = 2.0f * sin_theta_e * cos_theta_e;
        cos_far = cos_theta_o * cos_2e - sin_theta_o * sin_2e;
    }
    return 2.0f * kPiF * (1.0f - cos_theta_o) +
           0.5f * kPiF * (cos_theta_o - cos_far + 2.0f * (theta_w - theta_o) * sin_theta_o);
}

}  // namespace

// What the split search needs of one light; the items are reordered, the entries never.
struct LightTree::BuildItem {
    Bounds3 bounds;
    DirectionBox normals;
    float phi = 0.0f;
    float cos_theta_e = 1.0f;
    uint32_t entry = 0;  // in the entries
    int64_t slot = -1;   // where its leaf's index goes in m_leaf_of (-1: none)

    Vec3 centroid() const { return bounds.center(); }
};

struct LightTree::Split {
    size_t middle = 0;  // items[begin, middle) go to the first child
    Bounds3 first_centroids, second_centroids;
};

namespace {

// The lights of one bin, or of a run of bins.
struct Bin {
    Bounds3 bounds, centroids;
    DirectionBox normals;
    float phi = 0.0f;
    float cos_theta_e = 1.0f;
    size_t count = 0;

    // Bounds3::expand(Bounds3) tests for an empty box first; an item's box never is.
    template <class Item>  // LightTree::BuildItem, whose name is private
    void add_item(const Item& item) {
        bounds.min = glm::min(bounds.min, item.bounds.min);
        bounds.max = glm::max(bounds.max, item.bounds.max);
        centroids.expand(item.centroid());
        normals.expand(item.normals);
        phi += item.phi;
        cos_theta_e = std::min(cos_theta_e, item.cos_theta_e);
        ++count;
    }
    void add(const Bin& b) {
        bounds.expand(b.bounds);
        centroids.expand(b.centroids);
        normals.expand(b.normals);
        phi += b.phi;
        cos_theta_e = std::min(cos_theta_e, b.cos_theta_e);
        count += b.count;
    }
    // How costly the cluster is to sample as one: its power, times the spread of its
    // directions, times its size (the squared diagonal: the importance's distance clamp and
    // subtended cone both grow with the box's radius, and a flat or point-like box keeps a
    // size, unlike a surface area).
    // In double: power times squared size overflows a float in scenes of large extent.
    double cost() const {
        if (count == 0) return 0.0;
        const glm::dvec3 diagonal(bounds.extent());
        return static_cast<double>(phi) *
               static_cast<double>(orientation_measure(normals.cos_theta(), cos_theta_e)) *
               glm::dot(diagonal, diagonal);
    }
};

int widest_axis(const Vec3& extent) {
    return extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
}

template <class Item>
Bounds3 centroid_bounds(const Item* first, const Item* last) {
    Bounds3 b;
    for (const Item* it = first; it != last; ++it) b.expand(it->centroid());
    return b;
}

}  // namespace

LightTree::LightTree(std::vector<Entry> bounded, std::vector<const Light*> unbounded,
                     size_t light_count)
    : m_unbounded(std::move(unbounded)) {
    // Each light's leaves take as many places as it has pieces here.
    std::vector<size_t> pieces(light_count, 0);
    for (const Entry& e : bounded) {
        const int index = e.light->index();
        if (index >= 0 && static_cast<size_t>(index) < light_count)
            pieces[index] = std::max<size_t>(pieces[index], size_t(e.piece) + 1);
    }
    m_first_piece.resize(light_count + 1, 0);
    for (size_t i = 0; i < light_count; ++i) m_first_piece[i + 1] = m_first_piece[i] + pieces[i];
    m_leaf_of.assign(m_first_piece.back(), UINT32_MAX);
    // Lights that emit nothing never need a sample: leaving them out keeps their pmf 0.
    std::erase_if(bounded, [](const Entry& e) { return !(e.bounds.phi > 0.0f); });
    if (bounded.empty()) return;
    if (bounded.size() >= (uint64_t(1) << 31))
        throw Error("the light tree holds at most 2^31 lights");
    const size_t count = bounded.size();
    std::vector<BuildItem> items(count);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const LightBounds& b = bounded[i].bounds;
            const int index = bounded[i].light->index();
            const bool indexed = index >= 0 && static_cast<size_t>(index) < light_count;
            const int64_t slot =
                indexed ? static_cast<int64_t>(m_first_piece[index] + bounded[i].piece) : -1;
            items[i] = BuildItem{b.bounds,      DirectionBox::of(b.normals), b.phi,
                                 b.cos_theta_e, static_cast<uint32_t>(i),    slot};
        }
    });
    std::vector<BinaryNode> nodes(2 * count - 1);
    m_leaves.resize(count);
    std::vector<uint32_t> leaf_nodes(count);
    const Bounds3 centroids = centroid_bounds(items.data(), items.data() + count);
    build_shape(nodes, items, 0, count, centroids, 0, 0, leaf_nodes);
    // The leaves read their entries in no order that memory can guess: in a flat loop of
    // independent reads the processor keeps many of those misses in flight at once, where
    // inside the recursion it would wait for each in turn.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const auto& range) {
        for (size_t place = range.begin(); place != range.end(); ++place) {
            const Entry& e = bounded[items[place].entry];
            nodes[leaf_nodes[place]].bounds = e.bounds;
            m_leaves[place].light = e.light;
            m_leaves[place].piece = e.whole ? kWholeLight : e.piece;
        }
    });
    merge_bounds(nodes, 0, count);
    collapse(nodes);
}

// Where to split items[begin, end) (at least two): at the cheapest of the boundaries between
// bins of the centroids along the widest axis, the cost of a side being its Bin::cost; the
// items are partitioned accordingly. At the median instead (balanced) for small nodes, when
// the centroids all coincide, and when a lopsided split could take the tree deeper than the
// 64 levels pmf() allows: a binned split is allowed only while median splits from its
// children on would still end within 64 levels, and median splits keep that so (pmf()
// retraces a leaf's path in a fixed array, and the recursions stay shallow).
LightTree::Split LightTree::choose_split(std::vector<BuildItem>& items, size_t begin, size_t end,
                                         const Bounds3& centroids, uint32_t depth) {
    const size_t count = end - begin;
    BuildItem* const first = items.data() + begin;
    BuildItem* const last = items.data() + end;
    const Vec3 extent = centroids.extent();
    const int axis = widest_axis(extent);
    const bool spread = extent[axis] > 0.0f && std::isfinite(extent[axis]);
    const bool deep = depth + 1 + std::bit_width(count - 1) > 64;
    // (A spread so small that kBins / spread overflows is as good as none for the bins.)
    const float scale = static_cast<float>(kBins) / extent[axis];
    if (spread && std::isfinite(scale) && !deep && count >= kBinnedFrom) {
        const float low = centroids.min[axis];
        const auto bin_of = [&](const BuildItem& item) {
            const int b = static_cast<int>((item.centroid()[axis] - low) * scale);
            return std::clamp(b, 0, kBins - 1);
        };
        std::array<Bin, kBins> bins;
        for (const BuildItem* it = first; it != last; ++it) bins[bin_of(*it)].add_item(*it);
        // after[b]: the bins from b on.
        std::array<Bin, kBins> after;
        after[kBins - 1] = bins[kBins - 1];
        for (int b = kBins - 2; b >= 0; --b) {
            after[b] = after[b + 1];
            after[b].add(bins[b]);
        }
        Bin before;
        int best = -1;
        double best_cost = std::numeric_limits<double>::infinity();
        Bin best_before;
        for (int b = 1; b < kBins; ++b) {
            // Behind an empty bin the split is the one before it again.
            if (bins[b - 1].count == 0) continue;
            before.add(bins[b - 1]);
            if (after[b].count == 0) break;
            const double cost = before.cost() + after[b].cost();
            if (cost < best_cost) {
                best_cost = cost;
                best = b;
                best_before = before;
            }
        }
        if (best > 0) {
            BuildItem* const middle = std::partition(
                first, last, [&](const BuildItem& item) { return bin_of(item) < best; });
            return Split{static_cast<size_t>(middle - items.data()), best_before.centroids,
                         after[best].centroids};
        }
    }
    const size_t middle = begin + count / 2;
    if (!spread) return Split{middle, centroids, centroids};
    std::nth_element(first, items.data() + middle, last,
                     [axis](const BuildItem& a, const BuildItem& b) {
                         return a.centroid()[axis] < b.centroid()[axis];
                     });
    return Split{middle, centroid_bounds(first, items.data() + middle),
                 centroid_bounds(items.data() + middle, last)};
}

void LightTree::build_shape(std::vector<BinaryNode>& nodes, std::vector<BuildItem>& items,
                            size_t begin, size_t end, const Bounds3& centroids, uint32_t index,
                            uint32_t depth, std::vector<uint32_t>& leaf_nodes) {
    if (end - begin == 1) {
        nodes[index].second_child_or_leaf = static_cast<uint32_t>(begin);
        nodes[index].leaf = true;
        leaf_nodes[begin] = index;
        if (items[begin].slot >= 0) m_leaf_of[items[begin].slot] = static_cast<uint32_t>(begin);
        return;
    }
    const Split split = choose_split(items, begin, end, centroids, depth);
    const uint32_t second = index + 2 * static_cast<uint32_t>(split.middle - begin);
    nodes[index].second_child_or_leaf = second;
    nodes[index].leaf = false;
    const auto build_first = [&] {
        build_shape(nodes, items, begin, split.middle, split.first_centroids, index + 1, depth + 1,
                    leaf_nodes);
    };
    const auto build_second = [&] {
        build_shape(nodes, items, split.middle, end, split.second_centroids, second, depth + 1,
                    leaf_nodes);
    };
    if (end - begin >= kParallelFrom) {
        tbb::parallel_invoke(build_first, build_second);
    } else {
        build_first();
        build_second();
    }
}

// Each inner node's bounds from its children's, bottom up; subtrees in parallel as in
// build_shape, each merge in the same order for any thread count.
void LightTree::merge_bounds(std::vector<BinaryNode>& nodes, uint32_t index, size_t count) {
    if (count == 1) return;
    const uint32_t second = nodes[index].second_child_or_leaf;
    const size_t first_count = (second - index) / 2;
    if (count >= kParallelFrom) {
        tbb::parallel_invoke([&] { merge_bounds(nodes, index + 1, first_count); },
                             [&] { merge_bounds(nodes, second, count - first_count); });
    } else {
        merge_bounds(nodes, index + 1, first_count);
        merge_bounds(nodes, second, count - first_count);
    }
    nodes[index].bounds = LightBounds::merged(nodes[index + 1].bounds, nodes[second].bounds);
}

// The binary tree as a 4-wide one: each wide node takes a binary node's two children, and
// opens the inner ones among them (the one of most power times squared size first, the
// cluster the walk gains most by seeing into) until it has four. Sequential and in a fixed
// order, so the same for any thread count.
void LightTree::collapse(const std::vector<BinaryNode>& nodes) {
    const auto weight = [&](uint32_t b) {
        const Vec3 diagonal = nodes[b].bounds.bounds.extent();
        return static_cast<double>(nodes[b].bounds.phi) *
               static_cast<double>(glm::dot(diagonal, diagonal));
    };
    struct Pending {
        uint32_t binary, wide;
    };
    std::vector<Pending> pending{{0, 0}};
    // A binary tree of k leaves collapses to about k / 2 wide nodes (k / 3 where all are
    // full): the excess is given back at the end.
    m_nodes.reserve(nodes.size() / 4 + 1);
    m_nodes.emplace_back();
    while (!pending.empty()) {
        const Pending at = pending.back();
        pending.pop_back();
        std::array<uint32_t, 4> group{};
        int size = 0;
        if (nodes[at.binary].leaf) {
            group[size++] = at.binary;  // a tree of one light
        } else {
            group[size++] = at.binary + 1;
            group[size++] = nodes[at.binary].second_child_or_leaf;
        }
        while (size < 4) {
            int open = -1;
            for (int i = 0; i < size; ++i) {
                if (!nodes[group[i]].leaf && (open < 0 || weight(group[i]) > weight(group[open])))
                    open = i;
            }
            if (open < 0) break;
            const uint32_t opened = group[open];
            for (int i = size; i > open + 1; --i) group[i] = group[i - 1];
            group[open] = opened + 1;
            group[open + 1] = nodes[opened].second_child_or_leaf;
            ++size;
        }
        for (int lane = 0; lane < size; ++lane) {
            const BinaryNode& b = nodes[group[lane]];
            m_nodes[at.wide].children.set(lane, b.bounds);
            if (b.leaf) {
                m_nodes[at.wide].child[lane] = kLeafChild | b.second_child_or_leaf;
                m_leaves[b.second_child_or_leaf].node = at.wide;
                m_leaves[b.second_child_or_leaf].lane = static_cast<uint32_t>(lane);
                continue;
            }
            const auto wide = static_cast<uint32_t>(m_nodes.size());
            m_nodes.emplace_back();
            m_nodes[wide].parent = at.wide;
            m_nodes[wide].lane_in_parent = static_cast<uint32_t>(lane);
            m_nodes[at.wide].child[lane] = wide;
            pending.push_back({group[lane], wide});
        }
    }
    m_nodes.shrink_to_fit();
}

// The tree as a whole is one choice among the unbounded lights, all equally likely.
float LightTree::probability_of_tree() const {
    if (m_nodes.empty()) return 0.0f;
    return 1.0f / static_cast<float>(m_unbounded.size() + 1);
}

namespace {

// The weights of a node's four lanes at p: their importances, or, where none of them can
// reach p (the parent's looser bounds could), their powers. Every light then keeps a
// positive probability unless a sibling branch certainly outweighs it, so the probabilities
// over all lights sum to 1, and a light that gets 0 certainly sends p nothing.
struct LaneWeights {
    std::array<float, 4> weight;
    float total;
};
LaneWeights lane_weights(const LightBoundsX4& children, const Vec3& p, const Vec3& n) {
    LaneWeights w{children.importances(p, n), 0.0f};
    w.total = ((w.weight[0] + w.weight[1]) + w.weight[2]) + w.weight[3];
    if (!(w.total > 0.0f) || !std::isfinite(w.total)) {
        w.weight = children.phi;
        w.total = ((w.weight[0] + w.weight[1]) + w.weight[2]) + w.weight[3];
    }
    return w;
}

}  // namespace

LightTree::Step LightTree::choose_child(const WideNode& node, const Vec3& p, const Vec3& n,
                                        float& u) {
    const LaneWeights w = lane_weights(node.children, p, n);
    const float target = u * w.total;
    float before = 0.0f;
    uint32_t lane = 4;
    float lane_start = 0.0f;
    for (uint32_t k = 0; k < 4; ++k) {
        if (!(w.weight[k] > 0.0f)) continue;
        lane = k;  // the last lane of any weight, should rounding carry target past all
        lane_start = before;
        if (target < before + w.weight[k]) break;
        before += w.weight[k];
    }
    const float weight = w.weight[lane];
    u = std::clamp((target - lane_start) / weight, 0.0f, kOneMinusEpsilon);
    return {lane, weight / w.total};
}

float LightTree::child_probability(const WideNode& node, uint32_t lane, const Vec3& p,
                                   const Vec3& n) {
    const LaneWeights w = lane_weights(node.children, p, n);
    return w.weight[lane] / w.total;
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
    for (;;) {
        const Step step = choose_child(m_nodes[node], p, n, u);
        pmf *= step.probability;
        const uint32_t child = m_nodes[node].child[step.lane];
        if (child & kLeafChild) {
            const Leaf& leaf = m_leaves[child & ~kLeafChild];
            return {leaf.light, pmf, leaf.piece};
        }
        node = child;
    }
}

const LightTree::Leaf* LightTree::leaf_of(int light_index, uint32_t piece) const {
    if (piece == kWholeLight) piece = 0;
    if (light_index < 0 || static_cast<size_t>(light_index) + 1 >= m_first_piece.size())
        return nullptr;
    const size_t place = m_first_piece[light_index] + piece;
    if (place >= m_first_piece[light_index + 1] || m_leaf_of[place] == UINT32_MAX) return nullptr;
    return &m_leaves[m_leaf_of[place]];
}

float LightTree::pmf(const Vec3& p, const Vec3& n, const Light& light, uint32_t piece) const {
    const float p_tree = probability_of_tree();
    if (std::find(m_unbounded.begin(), m_unbounded.end(), &light) != m_unbounded.end())
        return (1.0f - p_tree) / static_cast<float>(m_unbounded.size());
    const Leaf* leaf = leaf_of(light.index(), piece);
    if (!leaf) return 0.0f;
    // The steps from the leaf up to the root, then their probabilities multiplied from the
    // root down, in the order sample() multiplies them, so that both give the same bits.
    // The binary tree is at most 64 levels deep (choose_split), the wide one no deeper.
    struct Turn {
        uint32_t node, lane;
    };
    std::array<Turn, 64> path;
    size_t depth = 0;
    Turn turn{leaf->node, leaf->lane};
    for (;;) {
        path[depth++] = turn;
        if (turn.node == 0 || depth == path.size()) break;
        turn = {m_nodes[turn.node].parent, m_nodes[turn.node].lane_in_parent};
    }
    float pmf = p_tree;
    while (depth > 0) {
        const Turn& t = path[--depth];
        pmf *= child_probability(m_nodes[t.node], t.lane, p, n);
    }
    return pmf;
}

size_t LightTree::memory_bytes() const {
    return m_nodes.capacity() * sizeof(WideNode) + m_leaves.capacity() * sizeof(Leaf) +
           m_unbounded.capacity() * sizeof(const Light*) + m_leaf_of.capacity() * sizeof(uint32_t) +
           m_first_piece.capacity() * sizeof(size_t);
}

}  // namespace glint
