#include <glint/core/error.h>
#include <glint/integrator/transport/hash_grid.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace glint {

// The coarse cells are 2r wide: the ball of radius r around p reaches at most two per axis,
// those of its bounding box's corners p - r and p + r.
void HashGrid::mark_coarse(const Vec3& p) {
    const glm::ivec3 low = coarse_cell_of(p - Vec3(m_radius));
    const glm::ivec3 high = coarse_cell_of(p + Vec3(m_radius));
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 c((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y,
                           (corner & 4) ? high.z : low.z);
        const uint32_t bit = coarse_bit(c);
        m_coarse[bit >> 6] |= uint64_t{1} << (bit & 63);
    }
}

void HashGrid::build(std::span<const Vec3> points, float radius, Numbering numbering) {
    if (!(radius > 0.0f) || !std::isfinite(radius))
        throw Error("hash grid: the query radius must be a finite number > 0");
    if (points.size() >= kNoCell) throw Error("hash grid: too many points");
    m_radius = radius;
    ++m_build;
    m_inverse_cell = 1.0f / radius;
    // Twice as many slots as points, so at least twice as many as cells, for the build.
    const size_t wanted = std::clamp<size_t>(2 * points.size(), 16, size_t{1} << 31);
    const uint32_t slots = std::bit_ceil(static_cast<uint32_t>(wanted));
    m_mask = slots - 1;
    m_slots.assign(slots, kNoCell);
    m_cells.clear();
    const uint64_t coarse_bits =
        std::bit_ceil(std::clamp<uint64_t>(256 * uint64_t{points.size()}, 1u << 16, 1u << 20));
    m_coarse_mask = static_cast<uint32_t>(coarse_bits - 1);
    m_coarse.assign(coarse_bits / 64, 0);
    // Each point's cell, the cells numbered in order of their first point; the cells' `end`
    // counts their points for now.
    std::vector<uint32_t> cell_of_point(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        mark_coarse(points[i]);
        const glm::ivec3 key = cell_of(points[i]);
        uint32_t slot = hash_cell(key) & m_mask;
        while (m_slots[slot] != kNoCell && m_cells[m_slots[slot]].key != key)
            slot = (slot + 1) & m_mask;
        if (m_slots[slot] == kNoCell) {
            m_slots[slot] = static_cast<uint32_t>(m_cells.size());
            m_cells.push_back({key, 0, 0});
        }
        cell_of_point[i] = m_slots[slot];
        ++m_cells[m_slots[slot]].end;
    }
    // The table sized for the points was for building; queries, most of which probe empty
    // cells, want the smallest table that keeps probes short (twice the cells' slots): it
    // stays in the nearer caches.
    const uint32_t small =
        std::bit_ceil(std::max<uint32_t>(16, 2 * static_cast<uint32_t>(m_cells.size())));
    if (small < slots) {
        m_mask = small - 1;
        m_slots.assign(small, kNoCell);
        for (uint32_t c = 0; c < m_cells.size(); ++c) {
            uint32_t slot = hash_cell(m_cells[c].key) & m_mask;
            while (m_slots[slot] != kNoCell) slot = (slot + 1) & m_mask;
            m_slots[slot] = c;
        }
    }
    const uint32_t occupied_bits = std::bit_ceil(
        std::clamp<uint32_t>(16 * static_cast<uint32_t>(std::min<size_t>(m_cells.size(), 1u << 20)),
                             1u << 12, 1u << 20));
    m_occupied_shift = 32 - std::countr_zero(occupied_bits);
    m_occupied.assign(occupied_bits / 64, 0);
    for (const Cell& cell : m_cells) {
        const uint32_t bit = hash_cell(cell.key) >> m_occupied_shift;
        m_occupied[bit >> 6] |= uint64_t{1} << (bit & 63);
    }
    uint32_t offset = 0;
    for (Cell& cell : m_cells) {
        cell.begin = offset;
        offset += cell.end;
        cell.end = cell.begin;
    }
    // A stable counting sort: points keep their order within a cell, so the sums over a
    // query's points come in the same order on every build of the same points.
    m_positions.resize(points.size());
    m_order.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const uint32_t to = m_cells[cell_of_point[i]].end++;
        m_positions[to] = points[i];
        m_order[to] = static_cast<uint32_t>(i);
    }
    if (numbering == Numbering::kGiven) {
        m_indices = m_order;
    } else {
        m_indices.resize(points.size());
        for (uint32_t k = 0; k < m_indices.size(); ++k) m_indices[k] = k;
    }
}

}  // namespace glint
