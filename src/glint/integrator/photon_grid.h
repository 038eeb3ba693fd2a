#pragma once
// Photons in a hashed uniform grid, for fixed-radius queries (progressive photon mapping):
// every query has the same radius r, and cells are r wide, so every photon within r of a
// point lies in the 3 x 3 x 3 cells around it -- fewer, since a cell whose box is farther
// than r from the point is skipped (on a surface about nine cells remain, 9 r^2 of area
// for the pi r^2 that counts). Built in O(n) by a counting sort of the photons by bucket;
// each photon keeps its cell, so one whose cell merely shares a bucket with the cell a
// query visits is not counted (nor counted twice). Unlike PhotonMap's k-nearest kd-tree,
// a query costs the photons near the point, and a point far from every photon a few empty
// buckets: what a caustic estimate made at every pixel of every frame needs. Most points
// are far from every photon (caustics are small): a bit set over coarser cells (2r, hashed
// into 64 Kbit, 8 KB) marks the cells some photon's r-ball reaches, and a query whose
// coarse cell is unmarked ends after one bit, without touching the buckets.
#include <glint/integrator/photon_map.h>

#include <cstdint>
#include <vector>

namespace glint {

class PhotonGrid {
public:
    PhotonGrid() = default;

    /// Indexes `photons` for queries of radius `radius` (> 0, scene units).
    void build(const std::vector<Photon>& photons, float radius);

    /// Calls visit(photon) for every photon strictly within the radius of `p`, in an order
    /// that depends only on the photons and `p` (never on threads).
    template <typename Visit>
    void for_each_near(const Vec3& p, Visit&& visit) const;

    size_t size() const { return m_photons.size(); }
    float radius() const { return m_radius; }

private:
    glm::ivec3 cell_of(const Vec3& p) const { return glm::ivec3(glm::floor(p * m_inverse_cell)); }
    uint32_t bucket_of(const glm::ivec3& c) const {
        uint32_t h = static_cast<uint32_t>(c.x) * 73856093u ^
                     static_cast<uint32_t>(c.y) * 19349663u ^
                     static_cast<uint32_t>(c.z) * 83492791u;
        h ^= h >> 15;
        return h & m_mask;
    }
    uint32_t coarse_bit(const Vec3& p) const {
        const glm::ivec3 c(glm::floor(p * (0.5f * m_inverse_cell)));
        uint32_t h = static_cast<uint32_t>(c.x) * 2654435761u ^
                     static_cast<uint32_t>(c.y) * 2246822519u ^
                     static_cast<uint32_t>(c.z) * 3266489917u;
        return (h ^ (h >> 16)) & (kCoarseBits - 1);
    }
    bool coarse_marked(const Vec3& p) const {
        const uint32_t bit = coarse_bit(p);
        return (m_coarse[bit >> 6] >> (bit & 63)) & 1u;
    }
    static constexpr uint32_t kCoarseBits = 1u << 16;
    // What a query reads of every candidate; the rest of the photon only on a hit.
    struct Entry {
        Vec3 p;
        glm::ivec3 cell;
    };

    float m_radius = 0.0f;
    float m_cell = 0.0f;
    float m_inverse_cell = 0.0f;
    uint32_t m_mask = 0;             // bucket count - 1 (a power of two)
    std::vector<Entry> m_entries;    // sorted by bucket
    std::vector<Photon> m_photons;   // in the same order
    std::vector<uint32_t> m_start;   // bucket b holds [m_start[b], m_start[b + 1])
    std::vector<uint64_t> m_coarse;  // kCoarseBits bits: coarse cells within r of a photon
};

template <typename Visit>
void PhotonGrid::for_each_near(const Vec3& p, Visit&& visit) const {
    if (m_photons.empty() || !coarse_marked(p)) return;
    const glm::ivec3 centre = cell_of(p);
    const float r2 = m_radius * m_radius;
    // Squared distance from p to the slabs of cells centre - 1, centre and centre + 1 on
    // each axis (0 for its own cell).
    float d2[3][3];
    for (int a = 0; a < 3; ++a) {
        const float below = p[a] - static_cast<float>(centre[a]) * m_cell;
        const float above = static_cast<float>(centre[a] + 1) * m_cell - p[a];
        d2[a][0] = below * below;
        d2[a][1] = 0.0f;
        d2[a][2] = above * above;
    }
    for (int z = 0; z < 3; ++z) {
        for (int y = 0; y < 3; ++y) {
            const float dyz = d2[2][z] + d2[1][y];
            if (dyz >= r2) continue;
            for (int x = 0; x < 3; ++x) {
                if (dyz + d2[0][x] >= r2) continue;
                const glm::ivec3 cell = centre + glm::ivec3(x - 1, y - 1, z - 1);
                const uint32_t b = bucket_of(cell);
                for (uint32_t i = m_start[b]; i < m_start[b + 1]; ++i) {
                    const Entry& e = m_entries[i];
                    if (e.cell == cell && length_squared(e.p - p) < r2) visit(m_photons[i]);
                }
            }
        }
    }
}

}  // namespace glint
