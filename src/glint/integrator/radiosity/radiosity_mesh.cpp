#include <glint/core/arena.h>
#include <glint/core/error.h>
#include <glint/geometry/mesh.h>
#include <glint/integrator/radiosity/radiosity_mesh.h>
#include <glint/material/material.h>
#include <glint/scene/scene.h>

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace glint {
namespace {

// Form factors are evaluated this fraction of the way from a vertex towards its input
// triangle's centroid: a vertex on the edge where a floor meets a wall would otherwise
// start its rays on the wall's plane, and see the wall block half of them.
constexpr float kInset = 1e-4f;

uint64_t surface_key(unsigned top, unsigned local) {
    return (static_cast<uint64_t>(top) << 32) | local;
}

// Index of grid vertex (i, j) of an n-grid: rows of n + 1, n, ..., 1 vertices.
uint32_t grid_vertex(uint32_t n, uint32_t i, uint32_t j) {
    return j * (n + 1) - j * (j - 1) / 2 + i;
}

// Barycentric weights of `p` in the 2D triangle (a, b, c).
Vec3 weights_in(const std::array<Vec2, 3>& t, const Vec2& p) {
    const Vec2 v0 = t[1] - t[0], v1 = t[2] - t[0], v2 = p - t[0];
    const float d = v0.x * v1.y - v1.x * v0.y;
    if (d == 0.0f) return Vec3(1.0f, 0.0f, 0.0f);
    const float wb = (v2.x * v1.y - v1.x * v2.y) / d;
    const float wc = (v0.x * v2.y - v2.x * v0.y) / d;
    return Vec3(1.0f - wb - wc, wb, wc);
}

// What a material is to the radiosity solve: an emitter, a diffuse reflector, or neither
// (then its surfaces are not meshed).
enum class SurfaceKind { kNone, kEmitter, kDiffuse };

SurfaceKind kind_of(const Material& material, const TriangleMesh& mesh, Arena& arena) {
    if (material.is_emissive()) return SurfaceKind::kEmitter;
    if (mesh.triangle_count() == 0) return SurfaceKind::kNone;
    HitRecord hit{};
    hit.primitive = 0;
    hit.barycentric = Vec2(1.0f / 3.0f);
    SurfaceInteraction si;
    mesh.fill_interaction(Ray{}, hit, si);
    si.material = &material;
    const Bsdf* bsdf = material.bsdf(si, arena);
    if (!bsdf) return SurfaceKind::kNone;
    const uint32_t flags = bsdf->flags();
    const bool diffuse_only =
        (flags & kBsdfDiffuse) && (flags & ~(kBsdfDiffuse | kBsdfReflection)) == 0;
    return diffuse_only ? SurfaceKind::kDiffuse : SurfaceKind::kNone;
}

uint64_t hash_float(uint64_t h, float f) {
    return hash_combine(h, std::bit_cast<uint32_t>(f));
}
uint64_t hash_vec(uint64_t h, const Vec3& v) {
    return hash_float(hash_float(hash_float(h, v.x), v.y), v.z);
}
uint64_t hash_spectrum(uint64_t h, const Spectrum& s) {
    for (const float v : s.stored()) h = hash_float(h, v);
    return h;
}

// The lights that shoot by sampling (point, spot, directional, environment, area lights not
// meshed) are not in the mesh, yet the solve depends on them: each is hashed by its power
// and by a few rays it emits (their origins, directions and emission), which change when
// it moves, turns or changes its light.
uint64_t hash_lights(uint64_t h, const Scene& scene, const std::vector<const Light*>& meshed) {
    for (const std::unique_ptr<Light>& light : scene.lights()) {
        if (std::find(meshed.begin(), meshed.end(), light.get()) != meshed.end()) continue;
        h = hash_spectrum(h, light->power());
        for (const float u : {0.125f, 0.375f, 0.625f, 0.875f}) {
            const auto emission = light->sample_le(Vec2(u, 1.0f - u), Vec2(1.0f - u, u), u);
            if (!emission) {
                h = hash_combine(h, 0);
                continue;
            }
            h = hash_vec(hash_vec(h, emission->ray.origin), emission->ray.direction);
            h = hash_spectrum(h, emission->Le);
        }
    }
    return h;
}

}  // namespace

RadiosityMesh RadiosityMesh::build(const Scene& scene, float patch_size, size_t max_patches) {
    RadiosityMesh mesh;
    Arena arena;
    for (const ScenePlacement& placement : scene.placements()) {
        const auto* triangle_mesh = dynamic_cast<const TriangleMesh*>(placement.shape);
        if (!triangle_mesh || placement.materials.empty()) continue;
        const Material& material = *placement.materials.front();
        arena.reset();
        const SurfaceKind kind = kind_of(material, *triangle_mesh, arena);
        if (kind == SurfaceKind::kNone) continue;
        if (kind == SurfaceKind::kEmitter && placement.light)
            mesh.meshed_lights.push_back(placement.light);
        mesh.m_surfaces[surface_key(placement.top_geometry, placement.local_geometry)] = {
            static_cast<uint32_t>(mesh.triangles.size())};
        const Spectrum emission = kPi * material.emission().spectrum();
        const bool two_sided = material.emits_two_sided();

        const MeshData& data = triangle_mesh->data();
        for (size_t t = 0; t < data.indices.size() / 3; ++t) {
            std::array<Vec3, 3> corners;
            for (int k = 0; k < 3; ++k)
                corners[k] = placement.to_world.point(data.positions[data.indices[3 * t + k]]);
            const Vec3 cross = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
            const float length = glm::length(cross);
            RadiosityTriangle triangle;
            triangle.first_patch = static_cast<uint32_t>(mesh.patches.size());
            const float longest = std::max({glm::length(corners[1] - corners[0]),
                                            glm::length(corners[2] - corners[1]),
                                            glm::length(corners[0] - corners[2])});
            const float cells = std::ceil(longest / patch_size);
            if (!(cells >= 1.0f) || !(length > 0.0f)) {
                // Degenerate (TriangleMesh dropped these already) or not finite: one patch of
                // no area, which never shoots, so that primitive indices still line up.
                triangle.grid = 1;
            } else {
                if (cells * cells + static_cast<float>(mesh.patches.size()) >
                    static_cast<float>(max_patches)) {
                    throw Error(fmt::format(
                        "radiosity: meshing the scene with patches of at most {} makes more "
                        "than {} patches; raise 'radiosity_patch_size'",
                        patch_size, max_patches));
                }
                triangle.grid = static_cast<uint32_t>(cells);
            }
            mesh.triangles.push_back(triangle);
            mesh.m_corners.push_back(corners);
            const uint32_t n = triangle.grid;
            const Vec3 normal = length > 0.0f ? cross / length : Vec3(0.0f, 0.0f, 1.0f);
            const Vec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.0f;

            // Grid vertices, with the reflectance where each lies.
            const uint32_t first_vertex = static_cast<uint32_t>(mesh.vertices.size());
            for (uint32_t j = 0; j <= n; ++j) {
                for (uint32_t i = 0; i + j <= n; ++i) {
                    const Vec2 uv(static_cast<float>(i) / n, static_cast<float>(j) / n);
                    RadiosityVertex v;
                    const Vec3 p = corners[0] + uv.x * (corners[1] - corners[0]) +
                                   uv.y * (corners[2] - corners[0]);
                    v.p = p + kInset * (centroid - p);
                    v.n = normal;
                    if (kind == SurfaceKind::kDiffuse) {
                        HitRecord hit{};
                        hit.primitive = static_cast<unsigned>(t);
                        hit.barycentric = uv;
                        SurfaceInteraction si;
                        triangle_mesh->fill_interaction(Ray{}, hit, si);
                        si.material = &material;
                        v.rho = material.albedo(si).clamped(0.0f, 1.0f);
                    } else {
                        v.rho = Spectrum(0.0f);
                    }
                    mesh.vertices.push_back(v);
                }
            }
            // Patches row by row: the lower cell of (i, j), then its upper one.
            for (uint32_t j = 0; j < n; ++j) {
                for (uint32_t i = 0; i + j < n; ++i) {
                    for (int upper = 0; upper < 2; ++upper) {
                        if (upper && i + j + 1 >= n) continue;
                        std::array<Vec2, 3> uv;
                        std::array<uint32_t, 3> v;
                        const std::array<std::array<uint32_t, 2>, 3> cells_ij =
                            upper ? std::array<std::array<uint32_t, 2>, 3>{{{i + 1, j},
                                                                            {i + 1, j + 1},
                                                                            {i, j + 1}}}
                                  : std::array<std::array<uint32_t, 2>, 3>{
                                        {{i, j}, {i + 1, j}, {i, j + 1}}};
                        for (int k = 0; k < 3; ++k) {
                            uv[k] = Vec2(static_cast<float>(cells_ij[k][0]) / n,
                                         static_cast<float>(cells_ij[k][1]) / n);
                            v[k] = first_vertex + grid_vertex(n, cells_ij[k][0], cells_ij[k][1]);
                        }
                        RadiosityPatch patch;
                        const uint32_t patch_index = static_cast<uint32_t>(mesh.patches.size());
                        mesh.m_patch_triangle.push_back(
                            static_cast<uint32_t>(mesh.triangles.size() - 1));
                        ShootingTriangle& shooter = patch.triangle;
                        shooter.a = mesh.point_of_triangle(mesh.triangles.size() - 1, uv[0]);
                        shooter.b = mesh.point_of_triangle(mesh.triangles.size() - 1, uv[1]);
                        shooter.c = mesh.point_of_triangle(mesh.triangles.size() - 1, uv[2]);
                        shooter.n = normal;
                        shooter.area = 0.5f * glm::length(glm::cross(shooter.b - shooter.a,
                                                                     shooter.c - shooter.a));
                        patch.rho = (mesh.vertices[v[0]].rho + mesh.vertices[v[1]].rho +
                                     mesh.vertices[v[2]].rho) /
                                    3.0f;
                        if (kind == SurfaceKind::kEmitter && shooter.area > 0.0f) {
                            patch.unshot[0] = patch.unshot_emission[0] = emission;
                            if (two_sided) patch.unshot[1] = patch.unshot_emission[1] = emission;
                        }
                        patch.element = static_cast<uint32_t>(mesh.elements.size());
                        RadiosityElement element;
                        element.v = v;
                        element.uv = uv;
                        element.patch = patch_index;
                        element.area = shooter.area;
                        mesh.elements.push_back(element);
                        mesh.patches.push_back(patch);
                    }
                }
            }
        }
    }
    mesh.fingerprint_at_build = hash_lights(mesh.fingerprint(), scene, mesh.meshed_lights);
    return mesh;
}

Vec3 RadiosityMesh::point_of_triangle(size_t triangle, const Vec2& uv) const {
    const std::array<Vec3, 3>& c = m_corners[triangle];
    return c[0] + uv.x * (c[1] - c[0]) + uv.y * (c[2] - c[0]);
}

std::optional<RadiosityLocation> RadiosityMesh::locate(const HitRecord& hit) const {
    const auto it = m_surfaces.find(surface_key(hit.top_geometry, hit.local_geometry));
    if (it == m_surfaces.end()) return std::nullopt;
    const size_t t = it->second.first_triangle + hit.primitive;
    if (t >= triangles.size()) return std::nullopt;
    const RadiosityTriangle& triangle = triangles[t];
    const uint32_t n = triangle.grid;
    const Vec2 uv = glm::clamp(hit.barycentric, Vec2(0.0f), Vec2(1.0f));
    const float fu = uv.x * n, fv = uv.y * n;
    uint32_t j = std::min(static_cast<uint32_t>(fv), n - 1);
    uint32_t i = std::min(static_cast<uint32_t>(fu), n - 1 - j);
    const bool upper = i + j + 1 < n && (fu - i) + (fv - j) > 1.0f;
    uint32_t element =
        patches[triangle.first_patch + 2 * n * j - j * j + 2 * i + (upper ? 1 : 0)].element;
    // Down the quadtree: into the child that holds the point best (the largest least
    // weight; a point on an edge between two children goes to either).
    while (elements[element].first_child >= 0) {
        const uint32_t first = static_cast<uint32_t>(elements[element].first_child);
        uint32_t best = first;
        float best_weight = -kInfinity;
        for (uint32_t c = first; c < first + 4; ++c) {
            const Vec3 weights = weights_in(elements[c].uv, uv);
            const float w = std::min({weights.x, weights.y, weights.z});
            if (w > best_weight) {
                best_weight = w;
                best = c;
            }
        }
        element = best;
    }
    Vec3 w = glm::max(weights_in(elements[element].uv, uv), Vec3(0.0f));
    const float sum = w.x + w.y + w.z;
    w = sum > 0.0f ? w / sum : Vec3(1.0f / 3.0f);
    return RadiosityLocation{element, w};
}

uint32_t RadiosityMesh::split(uint32_t index) {
    const RadiosityElement parent = elements[index];
    const size_t triangle = m_patch_triangle[parent.patch];
    const std::array<Vec3, 3>& c = m_corners[triangle];
    const Vec3 centroid = (c[0] + c[1] + c[2]) / 3.0f;
    auto midpoint = [&](int a, int b) {
        const uint32_t va = parent.v[a], vb = parent.v[b];
        const uint64_t key = (static_cast<uint64_t>(std::min(va, vb)) << 32) | std::max(va, vb);
        const auto found = m_midpoints.find(key);
        if (found != m_midpoints.end()) return found->second;
        const RadiosityVertex& x = vertices[va];
        const RadiosityVertex& y = vertices[vb];
        RadiosityVertex m;
        const Vec3 p = point_of_triangle(triangle, 0.5f * (parent.uv[a] + parent.uv[b]));
        m.p = p + kInset * (centroid - p);
        m.n = x.n;
        m.rho = 0.5f * (x.rho + y.rho);
        for (int s = 0; s < 2; ++s) {
            m.b[s] = 0.5f * (x.b[s] + y.b[s]);
            m.b_direct[s] = 0.5f * (x.b_direct[s] + y.b_direct[s]);
        }
        const uint32_t id = static_cast<uint32_t>(vertices.size());
        vertices.push_back(m);
        m_midpoints.emplace(key, id);
        return id;
    };
    const uint32_t m01 = midpoint(0, 1), m12 = midpoint(1, 2), m20 = midpoint(2, 0);
    const Vec2 u01 = 0.5f * (parent.uv[0] + parent.uv[1]);
    const Vec2 u12 = 0.5f * (parent.uv[1] + parent.uv[2]);
    const Vec2 u20 = 0.5f * (parent.uv[2] + parent.uv[0]);
    const uint32_t first = static_cast<uint32_t>(elements.size());
    auto child = [&](std::array<uint32_t, 3> v, std::array<Vec2, 3> uv) {
        RadiosityElement e;
        e.v = v;
        e.uv = uv;
        e.patch = parent.patch;
        e.area = 0.25f * parent.area;
        elements.push_back(e);
    };
    child({parent.v[0], m01, m20}, {parent.uv[0], u01, u20});
    child({m01, parent.v[1], m12}, {u01, parent.uv[1], u12});
    child({m20, m12, parent.v[2]}, {u20, u12, parent.uv[2]});
    child({m01, m12, m20}, {u01, u12, u20});
    elements[index].first_child = static_cast<int32_t>(first);
    return first;
}

float RadiosityMesh::longest_edge(uint32_t index) const {
    const RadiosityElement& e = elements[index];
    const size_t triangle = m_patch_triangle[e.patch];
    const Vec3 a = point_of_triangle(triangle, e.uv[0]);
    const Vec3 b = point_of_triangle(triangle, e.uv[1]);
    const Vec3 c = point_of_triangle(triangle, e.uv[2]);
    return std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

double RadiosityMesh::bytes_per_element() const {
    size_t leaves = 0;
    for (const RadiosityElement& e : elements) leaves += e.first_child < 0;
    if (leaves == 0) return 0.0;
    const double bytes = static_cast<double>(
        vertices.size() * sizeof(RadiosityVertex) + elements.size() * sizeof(RadiosityElement) +
        patches.size() * sizeof(RadiosityPatch) + triangles.size() * sizeof(RadiosityTriangle));
    return bytes / static_cast<double>(leaves);
}

uint64_t RadiosityMesh::fingerprint() const {
    uint64_t h = hash_combine(patches.size(), vertices.size());
    h = hash_combine(h, triangles.size());
    for (const RadiosityPatch& p : patches) {
        h = hash_vec(hash_vec(hash_vec(h, p.triangle.a), p.triangle.b), p.triangle.c);
        h = hash_spectrum(hash_spectrum(h, p.unshot_emission[0]), p.unshot_emission[1]);
    }
    for (const RadiosityVertex& v : vertices) h = hash_spectrum(h, v.rho);
    return h;
}

}  // namespace glint
