#pragma once
// Points in a hashed uniform grid, for fixed-radius queries: every photon gather of the
// renderer (the preview's caustic photons, VCM's merges, SPPM's photons against visible
// points) asks "which points lie within r of x", r the same for every query of a build.
// Cells are r wide, so every such point lies in the 3 x 3 x 3 cells around x -- fewer,
// since a cell whose box is farther than r from x is skipped (on a surface about nine
// cells remain, 9 r^2 of area for the pi r^2 that counts). A query costs the points near
// x, and a point far from every point a few empty cells.
//
// The grid holds positions and indices; what a point carries stays in the caller's arrays.
// The layout is for the query. Only occupied cells are stored, in an open-addressing hash
// table of 32-bit slots (linear probing, at most half full) that points into a dense array
// of cells; each cell's points are contiguous, their positions in an array of their own
// (12 bytes a point: all a query reads of a point it rejects), their indices in a parallel
// array read only on a hit. An empty cell thus costs a hash and one bit of a small set
// of the occupied cells (usually; find_cell); an occupied one a slot, a key compare and a
// linear walk of positions. Most queries of a caustic are
// far from every point: a bit set over coarser cells (2r, hashed) marks the cells some
// point's r-ball reaches, and a query whose coarse cell is unmarked ends after one bit,
// without touching the table. The set has 256 bits per point, from 64 Kbit (8 KB) up to
// 1 Mbit (128 KB, which stays in the level-2 cache while the points mark it): each point
// marks at most 8, so up to 4,096 points at most about 3 % of the bits are set and a query
// far from every point rarely passes (bench/README.md, stop 45: a fixed 8 KB let 42 % of the
// preview's caustic queries through with 4,700 photons, most of them to 27 empty cells).
//
// Points of different radii (SPPM's visible points, each with its own shrinking radius)
// are found by building with the largest radius and letting the caller reject a point
// beyond its own: one query shape for every user, each point stored once.
#include <glint/math/vector.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace glint {

class HashGrid {
public:
    /// What a visit's index names: the position in the array given to build() (the
    /// default), or the position in the grid's storage order, for a caller that lays its
    /// payload out in that order (order()) so that a query reads it contiguously.
    enum class Numbering { kGiven, kStorage };
    /// Which points at exactly the radius count: all (kClosed: distance <= radius) or none
    /// (kOpen: distance < radius), as each user's estimator was defined.
    enum class Ball { kClosed, kOpen };

    HashGrid() = default;

    /// Indexes `points` for queries of radius `radius` (> 0, scene units).
    void build(std::span<const Vec3> points, float radius, Numbering numbering = Numbering::kGiven);

    /// The given index of each point, in storage order: storage position k holds point
    /// order()[k]. Points of one cell keep the order they were given in.
    const std::vector<uint32_t>& order() const { return m_order; }

    /// What one thread keeps from query to query: where the points of the cells around the
    /// last query's cell are. Neighbouring queries (a tile's pixels) mostly fall in the
    /// same cell, and then skip the table's probes. A cache notices a rebuild of its grid
    /// and starts afresh; it must not outlive the grid (nor be used after the grid is
    /// assigned another). It only saves work: results never depend on it.
    class Cache {
        friend class HashGrid;
        // The occupied cells around a centre cell, in z, y, x order: where each lies
        // (0, 1, 2 per axis for centre - 1, centre, centre + 1) and its points.
        struct Neighbourhood {
            glm::ivec3 centre{0};
            int count = 0;
            struct Occupied {
                uint8_t x, y, z;
                uint32_t begin, end;
            };
            std::array<Occupied, 27> cells;
        };
        const HashGrid* grid = nullptr;
        uint64_t build = 0;
        // The last two centres: a floor at y = 0 puts hit points on either side of a cell
        // boundary, by rounding, from one pixel to the next.
        std::array<Neighbourhood, 2> recent;
        std::array<bool, 2> filled{false, false};
        int newest = 0;
    };

    /// Calls visit(index, distance2) for every point within the radius of `x` (the ball
    /// closed or open), distance2 = length_squared(point - x): the cells around x in z, y,
    /// x order, and each cell's points in the order build() was given them -- an order that
    /// depends only on the points and `x` (never on threads or on the cache).
    template <Ball ball = Ball::kClosed, typename Visit>
    void for_each_near(const Vec3& x, Cache& cache, Visit&& visit) const;
    template <Ball ball = Ball::kClosed, typename Visit>
    void for_each_near(const Vec3& x, Visit&& visit) const {
        Cache cache;
        for_each_near<ball>(x, cache, visit);
    }

    size_t size() const { return m_positions.size(); }
    float radius() const { return m_radius; }

private:
    glm::ivec3 cell_of(const Vec3& p) const { return glm::ivec3(glm::floor(p * m_inverse_cell)); }
    // A full avalanche of the three coordinates (a multiply-xorshift mix): neighbouring
    // cells must land in unrelated slots, or linear probing runs into clusters.
    static uint32_t hash_cell(const glm::ivec3& c) {
        uint64_t h = static_cast<uint32_t>(c.x) * 0x9e3779b97f4a7c15ull;
        h ^= static_cast<uint32_t>(c.y) * 0xc2b2ae3d27d4eb4full;
        h ^= static_cast<uint32_t>(c.z) * 0x165667b19e3779f9ull;
        h ^= h >> 29;
        h *= 0xbf58476d1ce4e5b9ull;
        return static_cast<uint32_t>(h >> 32);
    }
    // The occupied cells around `centre`, from `cache` or looked up into it.
    const Cache::Neighbourhood& neighbourhood(Cache& cache, const glm::ivec3& centre) const;
    // The index into m_cells of cell `c`, or kNoCell when no point lies in it. A cell whose
    // bit in m_occupied is clear is empty without a look at the table: a query's 27 cells
    // are mostly empty, and the table's slots, pushed out of the nearer caches by the
    // renderer's other work between queries, cost a wait each (two thirds of the preview's
    // caustic estimates went on them); the bits are few enough to stay.
    uint32_t find_cell(const glm::ivec3& c) const {
        const uint32_t hash = hash_cell(c);
        const uint32_t bit = hash >> m_occupied_shift;
        if (!((m_occupied[bit >> 6] >> (bit & 63)) & 1u)) return kNoCell;
        for (uint32_t slot = hash & m_mask;; slot = (slot + 1) & m_mask) {
            const uint32_t index = m_slots[slot];
            if (index == kNoCell || m_cells[index].key == c) return index;
        }
    }
    glm::ivec3 coarse_cell_of(const Vec3& p) const {
        return glm::ivec3(glm::floor(p * (0.5f * m_inverse_cell)));
    }
    uint32_t coarse_bit(const glm::ivec3& c) const {
        uint32_t h = static_cast<uint32_t>(c.x) * 2654435761u ^
                     static_cast<uint32_t>(c.y) * 2246822519u ^
                     static_cast<uint32_t>(c.z) * 3266489917u;
        return (h ^ (h >> 16)) & m_coarse_mask;
    }
    void mark_coarse(const Vec3& p);
    bool coarse_marked(const Vec3& p) const {
        const uint32_t bit = coarse_bit(coarse_cell_of(p));
        return (m_coarse[bit >> 6] >> (bit & 63)) & 1u;
    }
    template <Ball ball>
    static bool inside(float distance2, float radius2) {
        return ball == Ball::kClosed ? distance2 <= radius2 : distance2 < radius2;
    }
    static constexpr uint32_t kNoCell = ~0u;
    struct Cell {
        glm::ivec3 key;
        uint32_t begin, end;  // its points: [begin, end) of m_positions and m_indices
    };

    float m_radius = 0.0f;
    uint64_t m_build = 0;  // builds so far: a cache filled by an earlier one is refilled
    float m_inverse_cell = 0.0f;
    uint32_t m_mask = 0;              // slot count - 1 (a power of two)
    std::vector<uint32_t> m_slots;    // index into m_cells, or kNoCell
    std::vector<Cell> m_cells;        // the occupied cells, in order of first point
    std::vector<Vec3> m_positions;    // the points' positions, cell by cell
    std::vector<uint32_t> m_indices;  // what a visit reports of each, in the same order
    std::vector<uint32_t> m_order;    // the given index of each, in the same order
    // A bit per occupied cell, at the top bits of its hash_cell() (the slot takes the
    // bottom ones): 16 bits per cell, from 4 Kbit up to 1 Mbit.
    std::vector<uint64_t> m_occupied;
    int m_occupied_shift = 32;
    std::vector<uint64_t> m_coarse;  // m_coarse_mask + 1 bits: coarse cells within r of a point
    uint32_t m_coarse_mask = 0;
};

template <HashGrid::Ball ball, typename Visit>
void HashGrid::for_each_near(const Vec3& x, Cache& cache, Visit&& visit) const {
    if (m_positions.empty() || !coarse_marked(x)) return;
    const glm::ivec3 centre = cell_of(x);
    const Cache::Neighbourhood& near = neighbourhood(cache, centre);
    if (near.count == 0) return;
    const float r2 = m_radius * m_radius;
    // Squared distance from x to the slabs of cells centre - 1, centre and centre + 1 on
    // each axis (0 for its own cell).
    float d2[3][3];
    for (int a = 0; a < 3; ++a) {
        const float below = x[a] - static_cast<float>(centre[a]) * m_radius;
        const float above = static_cast<float>(centre[a] + 1) * m_radius - x[a];
        d2[a][0] = below * below;
        d2[a][1] = 0.0f;
        d2[a][2] = above * above;
    }
    for (int c = 0; c < near.count; ++c) {
        const Cache::Neighbourhood::Occupied& cell = near.cells[c];
        // A cell whose box lies outside the ball is skipped.
        const float dyz = d2[2][cell.z] + d2[1][cell.y];
        if (!inside<ball>(dyz, r2) || !inside<ball>(dyz + d2[0][cell.x], r2)) continue;
        for (uint32_t i = cell.begin; i < cell.end; ++i) {
            const float distance2 = length_squared(m_positions[i] - x);
            if (inside<ball>(distance2, r2)) visit(m_indices[i], distance2);
        }
    }
}

inline const HashGrid::Cache::Neighbourhood& HashGrid::neighbourhood(
    Cache& cache, const glm::ivec3& centre) const {
    if (cache.grid != this || cache.build != m_build) {
        cache.grid = this;
        cache.build = m_build;
        cache.filled = {false, false};
    }
    for (int i : {cache.newest, 1 - cache.newest})
        if (cache.filled[i] && cache.recent[i].centre == centre) return cache.recent[i];
    cache.newest = 1 - cache.newest;  // the older one makes way
    cache.filled[cache.newest] = true;
    Cache::Neighbourhood& near = cache.recent[cache.newest];
    near.centre = centre;
    near.count = 0;
    for (uint8_t z = 0; z < 3; ++z) {
        for (uint8_t y = 0; y < 3; ++y) {
            for (uint8_t x = 0; x < 3; ++x) {
                const uint32_t index = find_cell(centre + glm::ivec3(x - 1, y - 1, z - 1));
                if (index != kNoCell)
                    near.cells[near.count++] = {x, y, z, m_cells[index].begin, m_cells[index].end};
            }
        }
    }
    return near;
}

}  // namespace glint
