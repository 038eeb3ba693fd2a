#pragma once
// The leaf solids of CSG. Each carries the index of its "part", which selects its material
// and tells which surface a crossing belongs to.
#include <glint/geometry/csg/solid.h>
#include <glint/geometry/mesh.h>

namespace glint {

class SphereSolid final : public Solid {
public:
    SphereSolid(const Vec3& center, float radius, int part);
    void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const override;
    bool contains(const Vec3& p) const override;
    Bounds3 bounds() const override;
    std::string describe() const override { return "sphere"; }

private:
    Vec3 m_center;
    float m_radius;
    int m_part;
};

class BoxSolid final : public Solid {
public:
    BoxSolid(const Vec3& min, const Vec3& max, int part);
    void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const override;
    bool contains(const Vec3& p) const override;
    Bounds3 bounds() const override { return m_box; }
    std::string describe() const override { return "box"; }

private:
    Bounds3 m_box;
    int m_part;
};

// The solid x^T Q x <= 0 for a symmetric 4x4 matrix Q in homogeneous coordinates; its
// gradient Q x is the outward normal. Roots are computed in double precision with the
// cancellation-free form of the quadratic formula, so nearly tangent rays and rays along
// an asymptote (where the quadratic term vanishes) stay accurate.
class QuadricSolid final : public Solid {
public:
    QuadricSolid(const glm::dmat4& q, std::string name, int part);
    void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const override;
    bool contains(const Vec3& p) const override;
    Bounds3 bounds() const override;  // infinite except for ellipsoids
    std::string describe() const override { return m_name; }
    double value(const glm::dvec3& p) const;  // x^T Q x

private:
    Crossing crossing(const Ray& ray, double t) const;

    glm::dmat4 m_q;
    std::string m_name;
    int m_part;
};

// A closed, consistently oriented triangle mesh as a solid; rays are intersected with every
// triangle after a bounding-box test, which suits the small meshes CSG is used with.
class MeshSolid final : public Solid {
public:
    // Throws glint::Error when the mesh is not closed (an edge not shared by exactly two
    // triangles) or not consistently oriented.
    MeshSolid(const MeshData& mesh, int part);
    void intervals(const Ray& ray, IntervalList& out, IntervalScratch& scratch) const override;
    bool contains(const Vec3& p) const override;
    Bounds3 bounds() const override { return m_bounds; }
    float cost() const override {
        return 1.0f + 0.05f * static_cast<float>(m_triangles.size() / 3);
    }
    std::string describe() const override { return "mesh"; }

private:
    std::vector<Vec3> m_triangles;  // three vertices per triangle
    Bounds3 m_bounds;
    int m_part;
};

// The matrices of the nine nondegenerate quadric forms, axis along y (see docs).
namespace quadric_forms {
glm::dmat4 ellipsoid(double a, double b, double c);
glm::dmat4 hyperboloid_one_sheet(double a, double b, double c);
glm::dmat4 hyperboloid_two_sheets(double a, double b, double c);
glm::dmat4 elliptic_cone(double a, double b, double c);
glm::dmat4 elliptic_paraboloid(double a, double c);
glm::dmat4 hyperbolic_paraboloid(double a, double c);
glm::dmat4 elliptic_cylinder(double a, double c);
glm::dmat4 hyperbolic_cylinder(double a, double c);
glm::dmat4 parabolic_cylinder(double a);
}  // namespace quadric_forms

}  // namespace glint
