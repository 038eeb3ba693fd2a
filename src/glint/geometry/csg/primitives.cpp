#include <glint/core/error.h>
#include <glint/geometry/csg/primitives.h>

#include <fmt/format.h>

#include <algorithm>
#include <map>

namespace glint {

bool ray_box_range(const Ray& ray, const Bounds3& box, float& t0, float& t1) {
    t0 = -kInfinity;
    t1 = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = box.min[axis], hi = box.max[axis];
        if (lo == -kInfinity && hi == kInfinity) continue;
        const float inv = 1.0f / ray.direction[axis];
        float near_t = (lo - ray.origin[axis]) * inv;
        float far_t = (hi - ray.origin[axis]) * inv;
        if (std::isnan(near_t) || std::isnan(far_t)) {
            // Parallel to this slab: inside it or missing for good.
            if (ray.origin[axis] < lo || ray.origin[axis] > hi) return false;
            continue;
        }
        if (near_t > far_t) std::swap(near_t, far_t);
        t0 = std::max(t0, near_t);
        t1 = std::min(t1, far_t);
        if (t0 > t1) return false;
    }
    return true;
}

// ---------------------------------------------------------------------------------------
SphereSolid::SphereSolid(const Vec3& center, float radius, int part)
    : m_center(center), m_radius(radius), m_part(part) {}

void SphereSolid::intervals(const Ray& ray, IntervalList& out, IntervalScratch&) const {
    out.clear();
    const Vec3 o = ray.origin - m_center;
    const float a = glm::dot(ray.direction, ray.direction);
    const float b = glm::dot(o, ray.direction);
    const Vec3 closest = o - (b / a) * ray.direction;
    const float discriminant = a * (m_radius * m_radius - glm::dot(closest, closest));
    if (discriminant <= 0.0f) return;
    const float q = b < 0.0f ? -b + std::sqrt(discriminant) : -b - std::sqrt(discriminant);
    float t0 = (glm::dot(o, o) - m_radius * m_radius) / q, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    out.push_back({{t0, ray.at(t0) - m_center, m_part}, {t1, ray.at(t1) - m_center, m_part}});
}

bool SphereSolid::contains(const Vec3& p) const {
    return length_squared(p - m_center) <= m_radius * m_radius;
}

Bounds3 SphereSolid::bounds() const {
    return {m_center - Vec3(m_radius), m_center + Vec3(m_radius)};
}

// ---------------------------------------------------------------------------------------
BoxSolid::BoxSolid(const Vec3& min, const Vec3& max, int part) : m_box{min, max}, m_part(part) {}

void BoxSolid::intervals(const Ray& ray, IntervalList& out, IntervalScratch&) const {
    out.clear();
    Crossing enter{-kInfinity, Vec3(0.0f), m_part}, exit{kInfinity, Vec3(0.0f), m_part};
    for (int axis = 0; axis < 3; ++axis) {
        const float d = ray.direction[axis];
        if (d == 0.0f) {
            if (ray.origin[axis] < m_box.min[axis] || ray.origin[axis] > m_box.max[axis]) return;
            continue;
        }
        const float t_lo = (m_box.min[axis] - ray.origin[axis]) / d;
        const float t_hi = (m_box.max[axis] - ray.origin[axis]) / d;
        // Entering through the face the ray faces: the min face for d > 0.
        Vec3 n(0.0f);
        n[axis] = -1.0f;
        const float t_in = d > 0.0f ? t_lo : t_hi;
        const float t_out = d > 0.0f ? t_hi : t_lo;
        if (t_in > enter.t) enter = {t_in, d > 0.0f ? n : -n, m_part};
        if (t_out < exit.t) exit = {t_out, d > 0.0f ? -n : n, m_part};
    }
    if (enter.t < exit.t) out.push_back({enter, exit});
}

bool BoxSolid::contains(const Vec3& p) const {
    return glm::all(glm::greaterThanEqual(p, m_box.min)) &&
           glm::all(glm::lessThanEqual(p, m_box.max));
}

// ---------------------------------------------------------------------------------------
QuadricSolid::QuadricSolid(const glm::dmat4& q, std::string name, int part)
    : m_q(q), m_name(std::move(name)), m_part(part) {}

double QuadricSolid::value(const glm::dvec3& p) const {
    const glm::dvec4 x(p, 1.0);
    return glm::dot(x, m_q * x);
}

bool QuadricSolid::contains(const Vec3& p) const {
    return value(glm::dvec3(p)) <= 0.0;
}

Crossing QuadricSolid::crossing(const Ray& ray, double t) const {
    const glm::dvec4 x(glm::dvec3(ray.origin) + t * glm::dvec3(ray.direction), 1.0);
    return {static_cast<float>(t), Vec3(glm::dvec3(m_q * x)), m_part};
}

void QuadricSolid::intervals(const Ray& ray, IntervalList& out, IntervalScratch&) const {
    out.clear();
    const glm::dvec4 o(glm::dvec3(ray.origin), 1.0), d(glm::dvec3(ray.direction), 0.0);
    const glm::dvec4 qd = m_q * d;
    // f(t) = a t^2 + 2 b t + c; inside where f <= 0.
    const double a = glm::dot(d, qd);
    const double b = glm::dot(o, qd);
    const double c = glm::dot(o, m_q * o);
    const Crossing minus_infinity{-kInfinity, Vec3(0.0f), m_part};
    const Crossing plus_infinity{kInfinity, Vec3(0.0f), m_part};
    if (a == 0.0) {
        // Along an asymptotic direction the quadric is a line's worth of linear function.
        if (b == 0.0) {
            if (c <= 0.0) out.push_back({minus_infinity, plus_infinity});
            return;
        }
        const double t = -c / (2.0 * b);
        if (b > 0.0)
            out.push_back({minus_infinity, crossing(ray, t)});
        else
            out.push_back({crossing(ray, t), plus_infinity});
        return;
    }
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) {
        if (a < 0.0) out.push_back({minus_infinity, plus_infinity});
        return;
    }
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (a > 0.0) {
        out.push_back({crossing(ray, t0), crossing(ray, t1)});
    } else {
        out.push_back({minus_infinity, crossing(ray, t0)});
        out.push_back({crossing(ray, t1), plus_infinity});
    }
}

Bounds3 QuadricSolid::bounds() const {
    // Bounded exactly when the quadratic part is positive definite (an ellipsoid): then the
    // extent along each axis follows from the matrix (the support of the ellipsoid).
    const glm::dmat3 A(m_q);
    const glm::dvec3 bvec(m_q[3]);
    const double det = glm::determinant(A);
    const bool positive_definite =
        A[0][0] > 0 && (A[0][0] * A[1][1] - A[1][0] * A[0][1]) > 0 && det > 0;
    if (!positive_definite) return {Vec3(-kInfinity), Vec3(kInfinity)};
    const glm::dmat3 inverse = glm::inverse(A);
    const glm::dvec3 center = -inverse * bvec;
    const double k = glm::dot(bvec, inverse * bvec) - m_q[3][3];
    if (k <= 0.0) return {};  // empty
    Bounds3 box;
    for (int axis = 0; axis < 3; ++axis) {
        const double half = std::sqrt(k * inverse[axis][axis]);
        box.min[axis] = static_cast<float>(center[axis] - half);
        box.max[axis] = static_cast<float>(center[axis] + half);
    }
    return box;
}

// ---------------------------------------------------------------------------------------
MeshSolid::MeshSolid(const MeshData& mesh, int part) : m_part(part) {
    // Closed and consistently oriented: every directed edge appears once and its reverse once.
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = mesh.indices[t + k], to = mesh.indices[t + (k + 1) % 3];
            ++directed[{from, to}];
        }
        for (int k = 0; k < 3; ++k) m_triangles.push_back(mesh.positions[mesh.indices[t + k]]);
    }
    for (const auto& [edge, count] : directed) {
        auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) {
            throw Error(
                fmt::format("the mesh is not a closed, consistently oriented surface: the edge "
                            "between vertices {} and {} is used {} time(s) in one direction and "
                            "{} in the other",
                            edge.first + 1, edge.second + 1, count,
                            reverse == directed.end() ? 0 : reverse->second));
        }
    }
    if (m_triangles.empty()) throw Error("the mesh has no triangles");
    for (const Vec3& p : m_triangles) m_bounds.expand(p);
}

void MeshSolid::intervals(const Ray& ray, IntervalList& out, IntervalScratch&) const {
    out.clear();
    float box_t0, box_t1;
    if (!ray_box_range(ray, m_bounds, box_t0, box_t1)) return;
    struct Hit {
        float t;
        Vec3 n;
    };
    thread_local std::vector<Hit> hits;
    hits.clear();
    for (size_t i = 0; i < m_triangles.size(); i += 3) {
        // Möller–Trumbore over the whole line (t of either sign).
        const Vec3 e1 = m_triangles[i + 1] - m_triangles[i],
                   e2 = m_triangles[i + 2] - m_triangles[i];
        const Vec3 pvec = glm::cross(ray.direction, e2);
        const float det = glm::dot(e1, pvec);
        if (det == 0.0f) continue;
        const float inv = 1.0f / det;
        const Vec3 tvec = ray.origin - m_triangles[i];
        const float u = glm::dot(tvec, pvec) * inv;
        if (u < 0.0f || u > 1.0f) continue;
        const Vec3 qvec = glm::cross(tvec, e1);
        const float v = glm::dot(ray.direction, qvec) * inv;
        if (v < 0.0f || u + v > 1.0f) continue;
        hits.push_back({glm::dot(e2, qvec) * inv, glm::cross(e1, e2)});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) { return x.t < y.t; });
    // Winding number along the line: inside while it is positive.
    int winding = 0;
    Crossing enter;
    for (const Hit& h : hits) {
        const bool entering = glm::dot(h.n, ray.direction) < 0.0f;
        if (entering) {
            if (winding++ == 0) enter = {h.t, h.n, m_part};
        } else if (winding > 0 && --winding == 0) {
            if (!out.empty() && enter.t <= out.back().exit.t)
                out.back().exit = {h.t, h.n, m_part};
            else
                out.push_back({enter, {h.t, h.n, m_part}});
        }
    }
}

bool MeshSolid::contains(const Vec3& p) const {
    // Parity of crossings along a fixed, irrational-looking direction (avoids edges).
    const Ray ray{p, glm::normalize(Vec3(0.5773f, 0.6129f, 0.5396f))};
    IntervalScratch scratch;
    IntervalList spans;
    intervals(ray, spans, scratch);
    for (const Interval& span : spans) {
        if (span.enter.t <= 0.0f && span.exit.t >= 0.0f) return true;
    }
    return false;
}

// ---------------------------------------------------------------------------------------
namespace quadric_forms {
namespace {
glm::dmat4 diagonal(double x, double y, double z, double w) {
    glm::dmat4 q(0.0);
    q[0][0] = x;
    q[1][1] = y;
    q[2][2] = z;
    q[3][3] = w;
    return q;
}
// Adds the linear term -y (the paraboloids open towards +y).
glm::dmat4 with_minus_y(glm::dmat4 q) {
    q[1][3] = q[3][1] = -0.5;
    return q;
}
}  // namespace

glm::dmat4 ellipsoid(double a, double b, double c) {
    return diagonal(1 / (a * a), 1 / (b * b), 1 / (c * c), -1);
}
glm::dmat4 hyperboloid_one_sheet(double a, double b, double c) {
    return diagonal(1 / (a * a), -1 / (b * b), 1 / (c * c), -1);
}
glm::dmat4 hyperboloid_two_sheets(double a, double b, double c) {
    return diagonal(1 / (a * a), -1 / (b * b), 1 / (c * c), 1);
}
glm::dmat4 elliptic_cone(double a, double b, double c) {
    return diagonal(1 / (a * a), -1 / (b * b), 1 / (c * c), 0);
}
glm::dmat4 elliptic_paraboloid(double a, double c) {
    return with_minus_y(diagonal(1 / (a * a), 0, 1 / (c * c), 0));
}
glm::dmat4 hyperbolic_paraboloid(double a, double c) {
    return with_minus_y(diagonal(1 / (a * a), 0, -1 / (c * c), 0));
}
glm::dmat4 elliptic_cylinder(double a, double c) {
    return diagonal(1 / (a * a), 0, 1 / (c * c), -1);
}
glm::dmat4 hyperbolic_cylinder(double a, double c) {
    return diagonal(1 / (a * a), 0, -1 / (c * c), -1);
}
glm::dmat4 parabolic_cylinder(double a) {
    return with_minus_y(diagonal(1 / (a * a), 0, 0, 0));
}
}  // namespace quadric_forms

}  // namespace glint
