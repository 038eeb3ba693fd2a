#include <glint/core/arena.h>
#include <glint/integrator/projection_map.h>
#include <glint/integrator/shading.h>
#include <glint/material/material.h>

namespace glint {

Vec3 ProjectionMap::direction(int cell, const Vec2& u) const {
    const int ti = cell / kPhiCells, pi = cell % kPhiCells;
    const float z = -1.0f + 2.0f * (ti + u.x) / kThetaCells;
    const float phi = 2.0f * kPi * (pi + u.y) / kPhiCells;
    const float r = safe_sqrt(1.0f - z * z);
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

bool ProjectionMap::supports(const Light& light) {
    return light.emission_point().has_value() ||
           light.sample_surface_point(Vec2(0.5f), 0.5f).has_value();
}

template <typename Emits>
void ProjectionMap::probe(const Scene& scene, const Vec3& origin, const Emits& emits,
                          std::vector<uint8_t>& specular) const {
    Arena arena;
    const Vec2 probes[] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.5f, 0.5f}};
    for (int cell = 0; cell < kThetaCells * kPhiCells; ++cell) {
        if (specular[cell]) continue;
        for (const Vec2& u : probes) {
            const Vec3 w = direction(cell, u);
            if (!emits(w)) continue;
            const Ray ray{origin, w};
            auto hit = scene.intersect(ray);
            if (!hit) continue;
            arena.reset();
            const Bsdf* bsdf = shade(scene, ray, *hit, arena);
            if (bsdf && bsdf->is_delta()) {
                specular[cell] = 1;
                break;
            }
        }
    }
}

ProjectionMap::ProjectionMap(const Scene& scene, const Light& light) {
    constexpr int kCells = kThetaCells * kPhiCells;
    std::vector<uint8_t> specular(kCells, 0);
    if (const std::optional<Vec3> origin = light.emission_point()) {
        m_origin = *origin;
        probe(scene, m_origin, [&](const Vec3& w) { return !light.intensity(w).is_black(); }, specular);
    } else {
        m_surface = true;
        for (int i = 0; i < 9; ++i) {
            const Vec2 u((i % 3 + 0.5f) / 3.0f, (i / 3 + 0.5f) / 3.0f);
            const std::optional<SurfacePoint> point = light.sample_surface_point(u, (i + 0.5f) / 9.0f);
            if (!point) return;
            auto emits = [&](const Vec3& w) { return !light.emitted_from(*point, w).is_black(); };
            // Leave the surface on the side the probe goes to, as a photon would.
            auto origin_for = [&](const Vec3& w) { return offset_ray_origin(point->p, point->n, w); };
            probe(scene, origin_for(point->n), emits, specular);
            probe(scene, origin_for(-point->n), emits, specular);
        }
    }
    for (int cell = 0; cell < kCells; ++cell) {
        const int ti = cell / kPhiCells, pi = cell % kPhiCells;
        bool near_specular = false;
        for (int dt = -1; dt <= 1 && !near_specular; ++dt) {
            for (int dp = -1; dp <= 1 && !near_specular; ++dp) {
                const int t = ti + dt, p = (pi + dp + kPhiCells) % kPhiCells;
                near_specular = t >= 0 && t < kThetaCells && specular[t * kPhiCells + p];
            }
        }
        if (near_specular) m_marked.push_back(cell);
    }
}

float ProjectionMap::coverage() const {
    return static_cast<float>(m_marked.size()) / static_cast<float>(kThetaCells * kPhiCells);
}

std::optional<LightEmission> ProjectionMap::sample(const Light& light, const Vec2& u_position,
                                                   const Vec2& u_direction, float u_cell) const {
    if (m_marked.empty()) return std::nullopt;
    const size_t index = std::min(m_marked.size() - 1, static_cast<size_t>(u_cell * m_marked.size()));
    const Vec3 w = direction(m_marked[index], u_direction);
    // Uniform over the marked solid angle.
    const float pdf_direction = 1.0f / (4.0f * kPi * coverage());
    if (!m_surface) {
        const Spectrum intensity = light.intensity(w);
        if (intensity.is_black()) return std::nullopt;
        return LightEmission{Ray{m_origin, w}, intensity / pdf_direction};
    }
    // From a point uniform on the surface: radiance times the cosine at the surface, over
    // the densities of the point (per area) and of the direction (per solid angle).
    // What u_cell has left after choosing the cell is uniform and independent of the cell:
    // it picks the triangle, so position and direction stay independent.
    const float u_select = std::clamp(
        u_cell * static_cast<float>(m_marked.size()) - static_cast<float>(index), 0.0f, 0x1.fffffep-1f);
    const std::optional<SurfacePoint> point = light.sample_surface_point(u_position, u_select);
    if (!point || !(point->pdf_area > 0.0f)) return std::nullopt;
    const Spectrum radiance = light.emitted_from(*point, w);
    const float cosine = std::abs(glm::dot(point->n, w));
    if (radiance.is_black() || cosine == 0.0f) return std::nullopt;
    return LightEmission{Ray{offset_ray_origin(point->p, point->n, w), w},
                         radiance * (cosine / (point->pdf_area * pdf_direction))};
}

}  // namespace glint
