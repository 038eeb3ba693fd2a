#include <glint/core/error.h>
#include <glint/scene/import/pbrt/loop_subdivision.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace glint {
namespace {

uint64_t edge_key(uint32_t a, uint32_t b) {
    return (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

// Each edge's faces' third corners (one for a boundary edge, two inside).
struct Edge {
    uint32_t a, b;
    uint32_t opposite[2];
    int faces = 0;
    uint32_t midpoint = 0;
};

struct Topology {
    std::unordered_map<uint64_t, Edge> edges;
    std::vector<std::vector<uint32_t>> neighbours;           // per vertex
    std::vector<std::vector<uint32_t>> boundary_neighbours;  // along boundary edges
};

Topology topology_of(const MeshData& m) {
    Topology t;
    t.neighbours.resize(m.positions.size());
    t.boundary_neighbours.resize(m.positions.size());
    t.edges.reserve(m.indices.size());
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = m.indices[i + k], b = m.indices[i + (k + 1) % 3],
                           c = m.indices[i + (k + 2) % 3];
            Edge& e = t.edges.try_emplace(edge_key(a, b), Edge{a, b, {c, c}, 0, 0}).first->second;
            if (e.faces < 2) e.opposite[e.faces] = c;
            ++e.faces;
        }
    }
    for (const auto& [key, e] : t.edges) {
        t.neighbours[e.a].push_back(e.b);
        t.neighbours[e.b].push_back(e.a);
        if (e.faces == 1) {
            t.boundary_neighbours[e.a].push_back(e.b);
            t.boundary_neighbours[e.b].push_back(e.a);
        }
    }
    return t;
}

// Loop's weight of each neighbour of an interior vertex of valence n (Warren's form, as
// pbrt uses).
double beta(size_t n) {
    return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * static_cast<double>(n));
}

Vec3 sum_of(const MeshData& m, const std::vector<uint32_t>& vertices) {
    Vec3 s(0.0f);
    for (uint32_t v : vertices) s += m.positions[v];
    return s;
}

// A vertex moved by weights `self` for itself and `each` for each neighbour; boundary
// vertices use only their two boundary neighbours, with `boundary_each`.
Vec3 smoothed(const MeshData& m, const Topology& t, uint32_t v, bool limit) {
    const Vec3 p = m.positions[v];
    const auto& boundary = t.boundary_neighbours[v];
    if (boundary.size() == 2) {
        const float w = limit ? 1.0f / 5.0f : 1.0f / 8.0f;
        return (1.0f - 2.0f * w) * p + w * sum_of(m, boundary);
    }
    if (!boundary.empty()) return p;  // a non-manifold corner stays put
    const size_t n = t.neighbours[v].size();
    if (n == 0) return p;
    const double b = beta(n);
    const double w = limit ? 1.0 / (static_cast<double>(n) + 3.0 / (8.0 * b)) : b;
    return static_cast<float>(1.0 - static_cast<double>(n) * w) * p +
           static_cast<float>(w) * sum_of(m, t.neighbours[v]);
}

MeshData one_level(const MeshData& m) {
    Topology t = topology_of(m);
    MeshData out;
    out.positions.reserve(m.positions.size() + t.edges.size());
    for (uint32_t v = 0; v < m.positions.size(); ++v)
        out.positions.push_back(smoothed(m, t, v, false));
    for (auto& [key, e] : t.edges) {
        const Vec3 a = m.positions[e.a], b = m.positions[e.b];
        Vec3 p = 0.5f * (a + b);
        if (e.faces == 2)
            p = 0.375f * (a + b) +
                0.125f * (m.positions[e.opposite[0]] + m.positions[e.opposite[1]]);
        e.midpoint = static_cast<uint32_t>(out.positions.size());
        out.positions.push_back(p);
    }
    out.indices.reserve(m.indices.size() * 4);
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
        const uint32_t ab = t.edges.at(edge_key(a, b)).midpoint;
        const uint32_t bc = t.edges.at(edge_key(b, c)).midpoint;
        const uint32_t ca = t.edges.at(edge_key(c, a)).midpoint;
        out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    return out;
}

}  // namespace

MeshData loop_subdivide(const MeshData& mesh, int levels) {
    if (levels < 0 || levels > 8)
        throw Error(fmt::format("\"levels\" {} is outside [0, 8]", levels));
    MeshData m;
    m.positions = mesh.positions;
    m.indices = mesh.indices;
    for (int level = 0; level < levels; ++level) m = one_level(m);
    // The limit surface's points, and normals averaged from the faces around each vertex
    // (weighted by area), for smooth shading.
    const Topology t = topology_of(m);
    std::vector<Vec3> limit(m.positions.size());
    for (uint32_t v = 0; v < m.positions.size(); ++v) limit[v] = smoothed(m, t, v, true);
    m.positions = std::move(limit);
    m.normals.assign(m.positions.size(), Vec3(0.0f));
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const Vec3 n = glm::cross(m.positions[m.indices[i + 1]] - m.positions[m.indices[i]],
                                  m.positions[m.indices[i + 2]] - m.positions[m.indices[i]]);
        for (int k = 0; k < 3; ++k) m.normals[m.indices[i + k]] += n;
    }
    for (Vec3& n : m.normals) {
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : Vec3(0, 0, 1);
    }
    return m;
}

}  // namespace glint
