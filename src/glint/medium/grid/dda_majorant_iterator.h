#pragma once
// Walks a ray through the cells of a MajorantGrid in order with a 3D DDA (Amanatides and Woo
// 1987), giving for each cell the stretch of the ray inside it and the cell's majorant.
#include <glint/medium/grid/majorant_grid.h>

#include <optional>

namespace glint {

/// A stretch [t_min, t_max] of a ray inside one majorant cell, with the cell's density bound.
struct CellCrossing {
    float t_min = 0.0f;
    float t_max = 0.0f;
    float max_density = 0.0f;
    GridIndex cell;
};

class DdaMajorantIterator {
public:
    /// A ray o + t d in normalised grid space ([0, 1]^3 is the grid), walked over
    /// [t_min, t_max] clipped to the grid's box. `d` need not be unit length; t keeps the
    /// caller's parametrisation.
    DdaMajorantIterator(const MajorantGrid& grid, const Vec3& o, const Vec3& d, float t_min,
                        float t_max);

    /// The next cell along the ray, or nothing once the ray has left the grid or t_max.
    std::optional<CellCrossing> next();

private:
    const MajorantGrid* m_grid;
    float m_t = 0.0f;
    float m_t_end = 0.0f;
    GridIndex m_cell;
    Vec3 m_origin{0.0f};
    Vec3 m_direction{0.0f};
    int m_step[3] = {0, 0, 0};
    float m_next_crossing[3] = {0, 0, 0};

    float far_face_t(int axis) const;
};

}  // namespace glint
