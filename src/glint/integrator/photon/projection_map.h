#pragma once
// Projection map (Jensen 2001, ch. 5): the cells of directions from a light that reach
// specular geometry. Caustic photons are emitted only into those cells, with their power
// scaled by the fraction of the sphere the cells cover, so the caustic map gets many more
// photons for the same effort and stays unbiased for the caustics it covers.
//
// Lights are seen only through Light::sample_le (where photons start: the origin, its
// normal, its density) and Light::emitted (what leaves towards a direction). Lights that
// emit from one point (point, spot) are probed from it. Lights with a surface (area) are
// probed from a 3 x 3 grid of points spread over it, and a photon then leaves a point that
// sample_le picks (uniform on the surface) into a marked cell: a direction that reaches glass or a
// mirror from a point between the probes is found as long as some probe sees the same object
// through a cell at most one away (the map grows by one cell for that).
#include <glint/light/light.h>
#include <glint/scene/scene.h>

#include <optional>
#include <vector>

namespace glint {

class ProjectionMap {
public:
    // Marks the cells around `light` that see a specular surface (tested by a few rays per
    // cell and probe point, then grown by one cell so narrow objects are not missed).
    ProjectionMap(const Scene& scene, const Light& light);

    // Whether projection maps can aim this light's photons: lights whose photons start at
    // one point (a delta position) or on a surface (point, spot and area lights).
    static bool supports(const Light& light);

    // A photon into a marked cell, or nullopt when no cell is marked or it carries nothing.
    // u_position picks the point on an area light, u_direction and u_cell the direction.
    std::optional<LightEmission> sample(const Light& light, const Vec2& u_position,
                                        const Vec2& u_direction, float u_cell) const;
    // Fraction of all directions that are marked.
    float coverage() const;
    // Fraction of this map's photons that carry light (from 256 stratified draws). A spot
    // light narrower than the cells it is aimed through sends most of them outside its cone
    // (a 0.4 degree beam through a prism: a few photons in ten thousand); such a light is
    // better left to its own emission sampling, whose every photon carries light.
    float carrying_fraction(const Light& light) const;

    // The projection map for `light` when one helps: the scene has a surface that may
    // scatter specularly, the light is supported, and at least half of its photons carry
    // light; nullopt otherwise.
    static std::optional<ProjectionMap> make_if_useful(const Scene& scene, const Light& light);
    // Whether some material of the scene may scatter specularly
    // (Material::may_scatter_specularly): without one there are no caustic paths to aim at,
    // and probing (tens of milliseconds a light) would find nothing.
    static bool scene_has_specular_surfaces(const Scene& scene);

private:
    static constexpr int kThetaCells =
        64;  // uniform in cos(theta): every cell has equal solid angle
    static constexpr int kPhiCells = 128;
    Vec3 direction(int cell, const Vec2& u) const;
    // Marks cell entries of `specular` whose probe rays from `origin` hit a delta BSDF;
    // `emits` says whether the light sends anything that way.
    template <typename Emits>
    void probe(const Scene& scene, const Vec3& origin, const Emits& emits,
               std::vector<uint8_t>& specular) const;

    bool m_surface = false;     // an area light: photons start anywhere on it
    Vec3 m_origin{0.0f};        // a point light's position
    std::vector<int> m_marked;  // indices of marked cells
};

}  // namespace glint
