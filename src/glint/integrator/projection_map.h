#pragma once
// Projection map (Jensen 2001, ch. 5): the cells of directions from a point light that
// reach specular geometry. Caustic photons are emitted only into those cells, with their
// power scaled by the fraction of the sphere the cells cover, so the caustic map gets
// many more photons for the same effort and stays unbiased for the caustics it covers.
#include <glint/light/light.h>
#include <glint/scene/scene.h>

#include <optional>
#include <vector>

namespace glint {

class ProjectionMap {
public:
    // Marks the cells around `light`'s emission point that see a specular surface (tested
    // by a few rays per cell, then grown by one cell so narrow objects are not missed).
    ProjectionMap(const Scene& scene, const Light& light);

    // A photon into a marked cell, or nullopt when no cell is marked.
    std::optional<LightEmission> sample(const Light& light, const Vec2& u, float u_cell) const;
    // Fraction of all directions that are marked.
    float coverage() const;

private:
    static constexpr int kThetaCells = 64;  // uniform in cos(theta): every cell has equal solid angle
    static constexpr int kPhiCells = 128;
    Vec3 direction(int cell, const Vec2& u) const;

    Vec3 m_origin{0.0f};
    std::vector<int> m_marked;  // indices of marked cells
};

}  // namespace glint
