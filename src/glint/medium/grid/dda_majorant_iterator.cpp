#include <glint/medium/grid/dda_majorant_iterator.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// The parameter range where o + t d lies inside [0, 1]^3 (slab test); empty when t0 > t1.
void clip_to_unit_box(const Vec3& o, const Vec3& d, float& t0, float& t1) {
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0f) {
            if (o[axis] < 0.0f || o[axis] > 1.0f) t0 = kInfinity;
            continue;
        }
        const float inv = 1.0f / d[axis];
        float near = -o[axis] * inv;
        float far = (1.0f - o[axis]) * inv;
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
    }
}

}  // namespace

DdaMajorantIterator::DdaMajorantIterator(const MajorantGrid& grid, const Vec3& o, const Vec3& d,
                                         float t_min, float t_max)
    : m_grid(&grid), m_origin(o), m_direction(d) {
    clip_to_unit_box(o, d, t_min, t_max);
    m_t = t_min;
    m_t_end = t_max;
    if (!(t_min < t_max)) return;
    // The cell of the entry point, then per axis the parameter of the next cell face the ray
    // crosses and the parameter distance between two faces.
    m_cell = grid.cell_of(o + t_min * d);
    for (int axis = 0; axis < 3; ++axis) {
        m_step[axis] = d[axis] > 0.0f ? 1 : d[axis] < 0.0f ? -1 : 0;
        m_next_crossing[axis] = far_face_t(axis);
    }
}

// The parameter where the ray crosses the current cell's far face along `axis`, computed
// from the face's position each time, so that no error accumulates over long walks.
float DdaMajorantIterator::far_face_t(int axis) const {
    if (m_step[axis] == 0) return kInfinity;
    const int face = m_cell[axis] + (m_step[axis] > 0 ? 1 : 0);
    const float n = static_cast<float>(m_grid->resolution()[axis]);
    return (static_cast<float>(face) / n - m_origin[axis]) / m_direction[axis];
}

std::optional<CellCrossing> DdaMajorantIterator::next() {
    if (!(m_t < m_t_end)) return std::nullopt;
    int axis = 0;
    if (m_next_crossing[1] < m_next_crossing[axis]) axis = 1;
    if (m_next_crossing[2] < m_next_crossing[axis]) axis = 2;
    // Clamped below as well: rounding can put the entry point's cell a hair beyond a face
    // the ray has in fact already crossed.
    const float t_exit = std::clamp(m_next_crossing[axis], m_t, m_t_end);
    CellCrossing crossing{m_t, t_exit, m_grid->cell(m_cell.x, m_cell.y, m_cell.z), m_cell};
    m_t = t_exit;
    int* cell = axis == 0 ? &m_cell.x : axis == 1 ? &m_cell.y : &m_cell.z;
    *cell += m_step[axis];
    m_next_crossing[axis] = far_face_t(axis);
    // Leaving the last cell on an axis means leaving the grid (rounding may put the clipped
    // exit a hair beyond the last face).
    if (*cell < 0 || *cell >= m_grid->resolution()[axis]) m_t_end = m_t;
    return crossing;
}

}  // namespace glint
