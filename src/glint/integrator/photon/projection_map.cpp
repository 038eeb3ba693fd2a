#include <glint/core/arena.h>
#include <glint/integrator/photon/projection_map.h>
#include <glint/integrator/transport/shading.h>
#include <glint/material/material.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace glint {

Vec3 ProjectionMap::direction(int cell, const Vec2& u) const {
    const int ti = cell / kPhiCells, pi = cell % kPhiCells;
    const float z = -1.0f + 2.0f * (ti + u.x) / kThetaCells;
    const float phi = 2.0f * kPi * (pi + u.y) / kPhiCells;
    const float r = safe_sqrt(1.0f - z * z);
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

namespace {

bool has_surface(const LightEmission& e) {
    return e.n.x != 0.0f || e.n.y != 0.0f || e.n.z != 0.0f;
}

// sample_le moves its origin off the surface to the side its own ray leaves by; a ray
// towards `w` on the other side (a two-sided light) must start on that side instead: moving
// by the offset twice towards `w` crosses the surface and ends as far from it there.
Vec3 origin_towards(const LightEmission& e, const Vec3& w) {
    if (glm::dot(e.n, w) * glm::dot(e.n, e.ray.direction) >= 0.0f) return e.ray.origin;
    return offset_ray_origin(offset_ray_origin(e.ray.origin, e.n, w), e.n, w);
}

}  // namespace

// Photons are aimed from where the light's photons start, so the light must start them
// inside the scene: from one point into many directions (a delta position: the origin
// moves with neither sample) or from a surface (sample_le gives its normal). Directional
// and environment light enter through a disc outside the scene along directions of their
// own (a directional light's never changes, even when a point-sized scene shrinks its
// disc to a point): nothing there to probe from.
bool ProjectionMap::supports(const Light& light) {
    if (light.is_infinite()) return false;
    const std::optional<LightEmission> a = light.sample_le(Vec2(0.25f), Vec2(0.25f), 0.5f);
    const std::optional<LightEmission> b = light.sample_le(Vec2(0.75f), Vec2(0.75f), 0.5f);
    if (!a || !b) return false;
    if (has_surface(*a)) return true;
    return light.is_delta() && a->ray.origin == b->ray.origin &&
           a->ray.direction != b->ray.direction;
}

template <typename Emits>
void ProjectionMap::probe(const Scene& scene, const Vec3& origin, const Emits& emits,
                          std::vector<uint8_t>& specular) const {
    const Vec2 probes[] = {
        {0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.5f, 0.5f}};
    // Cells are independent (each writes its own flag): in parallel, the same map for any
    // thread count. A light move rebuilds the maps, so this is on the viewer's first pass.
    tbb::parallel_for(tbb::blocked_range<int>(0, kThetaCells * kPhiCells, 256),
                      [&](const tbb::blocked_range<int>& cells) {
                          Arena arena;
                          for (int cell = cells.begin(); cell < cells.end(); ++cell) {
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
                      });
}

ProjectionMap::ProjectionMap(const Scene& scene, const Light& light) {
    constexpr int kCells = kThetaCells * kPhiCells;
    std::vector<uint8_t> specular(kCells, 0);
    const std::optional<LightEmission> centre = light.sample_le(Vec2(0.5f), Vec2(0.5f), 0.5f);
    if (!centre) return;
    if (!has_surface(*centre)) {
        m_origin = centre->ray.origin;
        const Vec3 no_normal(0.0f);
        probe(
            scene, m_origin,
            [&](const Vec3& w) { return !light.emitted(m_origin, no_normal, w).is_black(); },
            specular);
    } else {
        m_surface = true;
        for (int i = 0; i < 9; ++i) {
            const Vec2 u((i % 3 + 0.5f) / 3.0f, (i / 3 + 0.5f) / 3.0f);
            const std::optional<LightEmission> point =
                light.sample_le(u, Vec2(0.5f), (i + 0.5f) / 9.0f);
            if (!point) return;
            auto emits = [&](const Vec3& w) {
                return !light.emitted(point->ray.origin, point->n, w).is_black();
            };
            // Leave the surface on the side the probe goes to, as a photon would.
            probe(scene, origin_towards(*point, point->n), emits, specular);
            probe(scene, origin_towards(*point, -point->n), emits, specular);
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
    const size_t index =
        std::min(m_marked.size() - 1, static_cast<size_t>(u_cell * m_marked.size()));
    const Vec3 w = direction(m_marked[index], u_direction);
    // Uniform over the marked solid angle.
    const float pdf_direction = 1.0f / (4.0f * kPi * coverage());
    LightEmission e;
    e.pdf_dir = pdf_direction;
    if (!m_surface) {
        e.Le = light.emitted(m_origin, Vec3(0.0f), w);
        if (e.Le.is_black()) return std::nullopt;
        e.ray = Ray{m_origin, w};
        e.pdf_pos = 1.0f;
        return e;
    }
    // From a point uniform on the surface, as sample_le picks it (its direction is not
    // used): radiance times the cosine at the surface, over the densities of the point
    // (per area) and of the direction (per solid angle).
    // What u_cell has left after choosing the cell is uniform and independent of the cell:
    // it picks the triangle (and side), so position and direction stay independent.
    const float u_select =
        std::clamp(u_cell * static_cast<float>(m_marked.size()) - static_cast<float>(index), 0.0f,
                   0x1.fffffep-1f);
    const std::optional<LightEmission> point = light.sample_le(u_position, Vec2(0.5f), u_select);
    if (!point || !(point->pdf_pos > 0.0f)) return std::nullopt;
    e.Le = light.emitted(point->ray.origin, point->n, w);
    if (e.Le.is_black() || glm::dot(point->n, w) == 0.0f) return std::nullopt;
    e.ray = Ray{origin_towards(*point, w), w};
    e.n = point->n;
    e.pdf_pos = point->pdf_pos;
    return e;
}

float ProjectionMap::carrying_fraction(const Light& light) const {
    constexpr int kSide = 16;
    int carrying = 0;
    for (int i = 0; i < kSide; ++i) {
        for (int j = 0; j < kSide; ++j) {
            const Vec2 u((i + 0.5f) / kSide, (j + 0.5f) / kSide);
            const float u_cell =
                ((i * kSide + j) * 0.618034f) - std::floor((i * kSide + j) * 0.618034f);
            const std::optional<LightEmission> e = sample(light, Vec2(0.5f), u, u_cell);
            if (e && !e->Le.is_black()) ++carrying;
        }
    }
    return static_cast<float>(carrying) / (kSide * kSide);
}

bool ProjectionMap::scene_has_specular_surfaces(const Scene& scene) {
    for (const std::unique_ptr<Material>& material : scene.materials())
        if (material->may_scatter_specularly()) return true;
    return false;
}

std::optional<ProjectionMap> ProjectionMap::make_if_useful(const Scene& scene, const Light& light) {
    if (!supports(light) || !scene_has_specular_surfaces(scene)) return std::nullopt;
    ProjectionMap map(scene, light);
    if (map.carrying_fraction(light) < 0.5f) return std::nullopt;
    return map;
}

}  // namespace glint
