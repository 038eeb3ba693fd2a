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

ProjectionMap::ProjectionMap(const Scene& scene, const Light& light) {
    const std::optional<Vec3> origin = light.emission_point();
    if (!origin) return;
    m_origin = *origin;
    constexpr int kCells = kThetaCells * kPhiCells;
    std::vector<uint8_t> specular(kCells, 0);
    Arena arena;
    const Vec2 probes[] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.5f, 0.5f}};
    for (int cell = 0; cell < kCells; ++cell) {
        for (const Vec2& u : probes) {
            const Vec3 w = direction(cell, u);
            if (light.intensity(w).is_black()) continue;
            const Ray ray{m_origin, w};
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

std::optional<LightEmission> ProjectionMap::sample(const Light& light, const Vec2& u, float u_cell) const {
    if (m_marked.empty()) return std::nullopt;
    const size_t index = std::min(m_marked.size() - 1, static_cast<size_t>(u_cell * m_marked.size()));
    const Vec3 w = direction(m_marked[index], u);
    // Uniform over the marked solid angle.
    const float pdf = 1.0f / (4.0f * kPi * coverage());
    const Spectrum intensity = light.intensity(w);
    if (intensity.is_black()) return std::nullopt;
    return LightEmission{Ray{m_origin, w}, intensity / pdf};
}

}  // namespace glint
