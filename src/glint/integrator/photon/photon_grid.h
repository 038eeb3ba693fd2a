#pragma once
// Photons in a hashed uniform grid, for fixed-radius queries (progressive photon mapping):
// every query has the same radius r, and cells are r wide, so every photon within r of a
// point lies in the 3 x 3 x 3 cells around it -- fewer, since a cell whose box is farther
// than r from the point is skipped (on a surface about nine cells remain, 9 r^2 of area
// for the pi r^2 that counts). Unlike PhotonMap's k-nearest kd-tree, a query costs the
// photons near the point, and a point far from every photon a few empty cells: what a
// caustic estimate made at every pixel of every frame needs.
//
// The layout is for that query. Only occupied cells are stored, in an open-addressing hash
// table of 32-bit slots (linear probing, at most half full) that points into a dense array
// of cells; each cell's photons are contiguous, their positions in an array of their own
// (12 bytes a photon: all a query reads of a photon it rejects), the rest of each photon
// in a parallel array read only on a hit. An empty cell thus costs a hash and one slot
// (usually); an occupied one a key compare and a linear walk of positions. Most points
// are far from every photon (caustics are small): a bit set over coarser cells (2r, hashed
// into 64 Kbit, 8 KB) marks the cells some photon's r-ball reaches, and a query whose
// coarse cell is unmarked ends after one bit, without touching the table.
#include <glint/integrator/photon/photon_map.h>

#include <array>
#include <cstdint>
#include <vector>

namespace glint {

class PhotonGrid {
public:
    PhotonGrid() = default;

    /// Indexes `photons` for queries of radius `radius` (> 0, scene units).
    void build(const std::vector<Photon>& photons, float radius);

    /// What one thread keeps from query to query: where the photons of the cells around
    /// the last query's cell are. Neighbouring pixels' queries mostly fall in the same cell
    /// (a cell is several pixels wide), and then skip the table's probes. A cache notices
    /// a rebuild of its grid and starts afresh; it must not outlive the grid (nor be used
    /// after the grid is assigned another). It only saves work: results never depend on it.
    class Cache {
        friend class PhotonGrid;
        // The occupied cells around a centre cell, in z, y, x order: where each lies
        // (0, 1, 2 per axis for centre - 1, centre, centre + 1) and its photons.
        struct Neighbourhood {
            glm::ivec3 centre{0};
            int count = 0;
            struct Occupied {
                uint8_t x, y, z;
                uint32_t begin, end;
            };
            std::array<Occupied, 27> cells;
        };
        const PhotonGrid* grid = nullptr;
        uint64_t build = 0;
        // The last two centres: a floor at y = 0 puts hit points on either side of a cell
        // boundary, by rounding, from one pixel to the next.
        std::array<Neighbourhood, 2> recent;
        std::array<bool, 2> filled{false, false};
        int newest = 0;
    };

    /// Calls visit(photon) for every photon strictly within the radius of `p`: the cells
    /// around p in z, y, x order, and each cell's photons in the order build() was given
    /// them -- an order that depends only on the photons and `p` (never on threads or on
    /// the cache).
    template <typename Visit>
    void for_each_near(const Vec3& p, Cache& cache, Visit&& visit) const;
    template <typename Visit>
    void for_each_near(const Vec3& p, Visit&& visit) const {
        Cache cache;
        for_each_near(p, cache, visit);
    }

    size_t size() const { return m_photons.size(); }
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
    // The index into m_cells of cell `c`, or kNoCell when no photon lies in it.
    uint32_t find_cell(const glm::ivec3& c) const {
        for (uint32_t slot = hash_cell(c) & m_mask;; slot = (slot + 1) & m_mask) {
            const uint32_t index = m_slots[slot];
            if (index == kNoCell || m_cells[index].key == c) return index;
        }
    }
    glm::ivec3 coarse_cell_of(const Vec3& p) const {
        return glm::ivec3(glm::floor(p * (0.5f * m_inverse_cell)));
    }
    static uint32_t coarse_bit(const glm::ivec3& c) {
        uint32_t h = static_cast<uint32_t>(c.x) * 2654435761u ^
                     static_cast<uint32_t>(c.y) * 2246822519u ^
                     static_cast<uint32_t>(c.z) * 3266489917u;
        return (h ^ (h >> 16)) & (kCoarseBits - 1);
    }
    bool coarse_marked(const Vec3& p) const {
        const uint32_t bit = coarse_bit(coarse_cell_of(p));
        return (m_coarse[bit >> 6] >> (bit & 63)) & 1u;
    }
    static constexpr uint32_t kCoarseBits = 1u << 16;
    static constexpr uint32_t kNoCell = ~0u;
    struct Cell {
        glm::ivec3 key;
        uint32_t begin, end;  // its photons: [begin, end) of m_positions and m_photons
    };

    float m_radius = 0.0f;
    uint64_t m_build = 0;  // builds so far: a cache filled by an earlier one is refilled
    float m_inverse_cell = 0.0f;
    uint32_t m_mask = 0;             // slot count - 1 (a power of two)
    std::vector<uint32_t> m_slots;   // index into m_cells, or kNoCell
    std::vector<Cell> m_cells;       // the occupied cells, in order of first photon
    std::vector<Vec3> m_positions;   // the photons' positions, cell by cell
    std::vector<Photon> m_photons;   // the same photons in the same order
    std::vector<uint64_t> m_coarse;  // kCoarseBits bits: coarse cells within r of a photon
};

template <typename Visit>
void PhotonGrid::for_each_near(const Vec3& p, Cache& cache, Visit&& visit) const {
    if (m_photons.empty() || !coarse_marked(p)) return;
    const glm::ivec3 centre = cell_of(p);
    const Cache::Neighbourhood& near = neighbourhood(cache, centre);
    if (near.count == 0) return;
    const float r2 = m_radius * m_radius;
    // Squared distance from p to the slabs of cells centre - 1, centre and centre + 1 on
    // each axis (0 for its own cell).
    float d2[3][3];
    for (int a = 0; a < 3; ++a) {
        const float below = p[a] - static_cast<float>(centre[a]) * m_radius;
        const float above = static_cast<float>(centre[a] + 1) * m_radius - p[a];
        d2[a][0] = below * below;
        d2[a][1] = 0.0f;
        d2[a][2] = above * above;
    }
    for (int c = 0; c < near.count; ++c) {
        const Cache::Neighbourhood::Occupied& cell = near.cells[c];
        // A cell whose box is at least r from p is skipped.
        const float dyz = d2[2][cell.z] + d2[1][cell.y];
        if (dyz >= r2 || dyz + d2[0][cell.x] >= r2) continue;
        for (uint32_t i = cell.begin; i < cell.end; ++i)
            if (length_squared(m_positions[i] - p) < r2) visit(m_photons[i]);
    }
}

inline const PhotonGrid::Cache::Neighbourhood& PhotonGrid::neighbourhood(
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
