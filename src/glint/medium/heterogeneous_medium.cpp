#include <glint/medium/delta_tracking.h>
#include <glint/medium/grid/dda_majorant_iterator.h>
#include <glint/medium/heterogeneous_medium.h>

namespace glint {

HeterogeneousMedium::HeterogeneousMedium(VoxelGrid grid, const Transform& grid_to_world,
                                         const Rgb& sigma_a, const Rgb& sigma_s, float g,
                                         int majorant_resolution)
    : m_grid(std::move(grid)),
      m_majorants(m_grid, majorant_resolution),
      m_world_to_unit(Transform::scale(1.0f / m_grid.bounds().extent()) *
                      Transform::translate(-m_grid.bounds().min) * grid_to_world.inverse()),
      m_sigma_a(sigma_a),
      m_sigma_s(sigma_s),
      m_g(g) {}

MediumPoint HeterogeneousMedium::at(const Vec3& p) const {
    const float density = m_grid.density(m_world_to_unit.point(p));
    return MediumPoint{uplift(m_sigma_a, RgbRole::unbounded) * density,
                       uplift(m_sigma_s, RgbRole::unbounded) * density};
}

void HeterogeneousMedium::majorants(const Ray& ray, float t_max, MajorantVisitor visit) const {
    // The map to grid space is affine, so t means the same on both sides of it.
    // The extinction at density 1, uplifted as at() uplifts it: times a cell's largest
    // density it bounds every voxel of the cell at every wavelength.
    const Spectrum sigma_t =
        uplift(m_sigma_a, RgbRole::unbounded) + uplift(m_sigma_s, RgbRole::unbounded);
    DdaMajorantIterator cells(m_majorants, m_world_to_unit.point(ray.origin),
                              m_world_to_unit.vector(ray.direction), 0.0f, t_max);
    while (const std::optional<CellCrossing> crossing = cells.next()) {
        if (crossing->max_density == 0.0f) continue;
        if (!visit(MajorantSegment{crossing->t_min, crossing->t_max,
                                   sigma_t * crossing->max_density})) {
            return;
        }
    }
}

Spectrum HeterogeneousMedium::transmittance(const Ray& ray, float t, Rng& rng) const {
    return ratio_tracking_transmittance(*this, ray, t, rng);
}

}  // namespace glint
