#include <glint/geometry/mesh_sampler.h>
#include <glint/math/spherical_rectangle.h>
#include <glint/math/spherical_triangle.h>
#include <glint/math/warp.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

// The cone about the mean normal that holds every normal (the whole sphere when they
// cancel out).
DirectionCone cone_of(const std::vector<Vec3>& normals) {
    Vec3 sum(0.0f);
    for (const Vec3& n : normals) sum += n;
    const float len = glm::length(sum);
    if (!(len > 1e-4f * static_cast<float>(normals.size()))) return DirectionCone::whole_sphere();
    const Vec3 axis = sum / len;
    float cos_theta = 1.0f;
    for (const Vec3& n : normals) cos_theta = std::min(cos_theta, glm::dot(n, axis));
    return {axis, cos_theta, false};
}

// Where the ray from `ref` along unit `w` meets the plane through `v` with normal `n`.
Vec3 on_plane(const Vec3& ref, const Vec3& w, const Vec3& v, const Vec3& n) {
    const double t = glm::dot(glm::dvec3(n), glm::dvec3(v) - glm::dvec3(ref)) /
                     glm::dot(glm::dvec3(n), glm::dvec3(w));
    return Vec3(glm::dvec3(ref) + t * glm::dvec3(w));
}

}  // namespace

MeshSampler::MeshSampler(const MeshData& mesh, const Transform& to_world) {
    // A mirroring placement reverses the winding, so the cross product of the placed
    // vertices points inwards; flip it to keep the emitting side where the hit sees it.
    const float orientation = to_world.swaps_handedness() ? -1.0f : 1.0f;
    const size_t count = mesh.indices.size() / 3;
    m_vertices.reserve(count * 3);
    m_cumulative_area.reserve(count);
    double total = 0.0;
    for (size_t i = 0; i < count; ++i) {
        for (int k = 0; k < 3; ++k) {
            m_vertices.push_back(to_world.point(mesh.positions[mesh.indices[3 * i + k]]));
            m_bounds.expand(m_vertices.back());
        }
        const Vec3* v = &m_vertices[3 * i];
        const Vec3 cross = glm::cross(v[1] - v[0], v[2] - v[0]);
        total += 0.5 * glm::length(cross);
        m_normals.push_back(orientation * glm::normalize(cross));
        m_cumulative_area.push_back(total);
    }
    m_area = static_cast<float>(total);
    m_inverse_area = 1.0f / m_area;
    m_normal_cone = cone_of(m_normals);
    m_rectangle = as_rectangle(m_vertices, m_normals);
}

// Two triangles sharing a diagonal, with the same normal, whose fourth corner completes a
// rectangle: the corner opposite the shared diagonal, and the edges from it.
std::optional<MeshSampler::Rectangle> MeshSampler::as_rectangle(const std::vector<Vec3>& vertices,
                                                                const std::vector<Vec3>& normals) {
    if (vertices.size() != 6 || glm::dot(normals[0], normals[1]) < 1.0f - 1e-5f)
        return std::nullopt;
    const Vec3* t0 = &vertices[0];
    const Vec3* t1 = &vertices[3];
    const Vec3* other = nullptr;
    for (int k = 0; k < 3; ++k) {
        if (t1[k] != t0[0] && t1[k] != t0[1] && t1[k] != t0[2]) {
            if (other) return std::nullopt;
            other = &t1[k];
        }
    }
    if (!other) return std::nullopt;
    for (int k = 0; k < 3; ++k) {
        const Vec3 corner = t0[k];
        const Vec3 e1 = t0[(k + 1) % 3] - corner, e2 = t0[(k + 2) % 3] - corner;
        const float scale = glm::length(e1) + glm::length(e2);
        const bool completes = glm::length(corner + e1 + e2 - *other) <= 1e-5f * scale;
        const bool square_corner =
            std::abs(glm::dot(e1, e2)) <= 1e-5f * glm::length(e1) * glm::length(e2);
        if (completes && square_corner) return Rectangle{corner, e1, e2};
    }
    return std::nullopt;
}

// The estimate decides the lower limit, the exact solid angle the upper one (and
// degenerate projections): both sample() and pdf() ask the same questions of the same
// point, so they always agree on the strategy.
bool MeshSampler::spherical_pays(double solid_angle) {
    return solid_angle > 1e-9 && solid_angle <= kMaxSphericalSolidAngle;
}

bool MeshSampler::may_pay(const Vec3& ref, const Vec3& c, const Vec3& n, float area) {
    const Vec3 d = ref - c;
    const float dist2 = glm::dot(d, d);
    const float dist = std::sqrt(dist2);
    return area * std::abs(glm::dot(n, d)) >=
           static_cast<float>(kMinSphericalSolidAngle) * dist2 * dist;
}

ShapeSample MeshSampler::sample_area(const Vec2& u, float u_select) const {
    const size_t tri = pick_triangle(u_select);
    return {point_in(tri, u), m_normals[tri], m_inverse_area};
}

ShapeSample MeshSampler::sample(const Vec3& ref, const Vec2& u, float u_select) const {
    ShapeSample s;
    if (m_rectangle && may_pay(ref, rectangle_centre(), m_normals[0], m_area)) {
        const SphericalRectangle sr(ref, m_rectangle->corner, m_rectangle->edge_x,
                                    m_rectangle->edge_y);
        if (spherical_pays(sr.solid_angle())) {
            s.p = sr.sample(u);
            s.n = m_normals[0];
            s.pdf = static_cast<float>(1.0 / sr.solid_angle());
            return s;
        }
    } else if (!m_rectangle && m_normals.size() <= kSolidAngleTriangles) {
        const size_t tri = pick_triangle(u_select);
        s = sample_triangle(ref, u, tri);
        s.pdf *= triangle_area(tri) * m_inverse_area;  // times the triangle's probability
        return s;
    }
    const size_t tri = pick_triangle(u_select);
    s.p = point_in(tri, u);
    s.n = m_normals[tri];
    s.pdf = area_to_solid_angle_pdf(m_inverse_area, ref, s.p, s.n);
    return s;
}

float MeshSampler::pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const {
    if (m_rectangle && may_pay(ref, rectangle_centre(), m_normals[0], m_area)) {
        const SphericalRectangle sr(ref, m_rectangle->corner, m_rectangle->edge_x,
                                    m_rectangle->edge_y);
        if (spherical_pays(sr.solid_angle())) return static_cast<float>(1.0 / sr.solid_angle());
    } else if (!m_rectangle && m_normals.size() <= kSolidAngleTriangles) {
        const size_t tri = triangle_holding(p);
        return pdf_in_triangle(ref, p, n, tri) * (triangle_area(tri) * m_inverse_area);
    }
    return area_to_solid_angle_pdf(m_inverse_area, ref, p, n);
}

ShapeSample MeshSampler::sample_triangle(const Vec3& ref, const Vec2& u, size_t tri) const {
    const Vec3* v = &m_vertices[3 * tri];
    const Vec3 centroid = (v[0] + v[1] + v[2]) * (1.0f / 3.0f);
    const float area = triangle_area(tri);
    const bool worth = may_pay(ref, centroid, m_normals[tri], area);
    const SphericalTriangle st =
        worth ? SphericalTriangle(ref, v[0], v[1], v[2]) : SphericalTriangle(ref, v[0], v[0], v[0]);
    ShapeSample s;
    s.n = m_normals[tri];
    if (worth && spherical_pays(st.solid_angle())) {
        s.p = on_plane(ref, st.sample(u), v[0], m_normals[tri]);
        s.pdf = static_cast<float>(1.0 / st.solid_angle());
        return s;
    }
    s.p = point_in(tri, u);
    s.pdf = area_to_solid_angle_pdf(1.0f / area, ref, s.p, s.n);
    return s;
}

float MeshSampler::pdf_in_triangle(const Vec3& ref, const Vec3& p, const Vec3& n,
                                   size_t tri) const {
    const Vec3* v = &m_vertices[3 * tri];
    const Vec3 centroid = (v[0] + v[1] + v[2]) * (1.0f / 3.0f);
    const float area = triangle_area(tri);
    if (may_pay(ref, centroid, m_normals[tri], area)) {
        const SphericalTriangle st(ref, v[0], v[1], v[2]);
        if (spherical_pays(st.solid_angle())) return static_cast<float>(1.0 / st.solid_angle());
    }
    return area_to_solid_angle_pdf(1.0f / area, ref, p, n);
}

Bounds3 MeshSampler::piece_bounds(uint32_t piece) const {
    if (!is_piece(piece)) return m_bounds;
    Bounds3 b;
    for (int k = 0; k < 3; ++k) b.expand(m_vertices[3 * piece + k]);
    return b;
}

DirectionCone MeshSampler::piece_normal_cone(uint32_t piece) const {
    if (!is_piece(piece)) return m_normal_cone;
    return {m_normals[piece], 1.0f, false};
}

float MeshSampler::piece_area(uint32_t piece) const {
    return is_piece(piece) ? triangle_area(piece) : m_area;
}

ShapeSample MeshSampler::sample_piece(const Vec3& ref, const Vec2& u, float u_select,
                                      uint32_t piece) const {
    return is_piece(piece) ? sample_triangle(ref, u, piece) : sample(ref, u, u_select);
}

float MeshSampler::pdf_piece(const Vec3& ref, const Vec3& p, const Vec3& n, uint32_t piece) const {
    return is_piece(piece) ? pdf_in_triangle(ref, p, n, piece) : pdf(ref, p, n);
}

// A triangle chosen with probability proportional to its area.
size_t MeshSampler::pick_triangle(float u_select) const {
    const double target = u_select * static_cast<double>(m_area);
    const size_t last = m_cumulative_area.size() - 1;
    // Emitters are often a few triangles (a quad is two): a scan that stops at the first
    // cumulative area above the target is what upper_bound finds, without its loop setup.
    if (last < kSolidAngleTriangles) {
        size_t tri = 0;
        while (tri < last && !(target < m_cumulative_area[tri])) ++tri;
        return tri;
    }
    auto it = std::upper_bound(m_cumulative_area.begin(), m_cumulative_area.end(), target);
    return std::min<size_t>(it - m_cumulative_area.begin(), last);
}

float MeshSampler::triangle_area(size_t tri) const {
    const double before = tri > 0 ? m_cumulative_area[tri - 1] : 0.0;
    return static_cast<float>(m_cumulative_area[tri] - before);
}

// A point uniformly distributed over triangle `tri`.
Vec3 MeshSampler::point_in(size_t tri, const Vec2& u) const {
    const Vec3* v = &m_vertices[3 * tri];
    const Vec2 b = warp::square_to_uniform_triangle(u);
    return (1.0f - b.x - b.y) * v[0] + b.x * v[1] + b.y * v[2];
}

// The triangle a point on the mesh lies on: the one it is nearest to, measured by its
// distance from the plane plus how far its barycentric coordinates leave the triangle
// (scaled to a length), so that points rounded just off an edge still find their triangle.
size_t MeshSampler::triangle_holding(const Vec3& p) const {
    size_t best = 0;
    double best_miss = INFINITY;
    for (size_t tri = 0; tri < m_normals.size(); ++tri) {
        const glm::dvec3 a(m_vertices[3 * tri]), b(m_vertices[3 * tri + 1]),
            c(m_vertices[3 * tri + 2]);
        const glm::dvec3 e1 = b - a, e2 = c - a, d = glm::dvec3(p) - a;
        const glm::dvec3 n = glm::cross(e1, e2);
        const double n2 = glm::dot(n, n);
        const double beta = glm::dot(glm::cross(d, e2), n) / n2;
        const double gamma = glm::dot(glm::cross(e1, d), n) / n2;
        const double alpha = 1.0 - beta - gamma;
        const double outside = std::max({0.0, -alpha, -beta, -gamma});
        const double size = std::sqrt(std::sqrt(n2));
        const double miss = std::abs(glm::dot(d, n)) / std::sqrt(n2) + outside * size;
        if (miss < best_miss) {
            best_miss = miss;
            best = tri;
        }
    }
    return best;
}

}  // namespace glint
