#pragma once
// Sampling of an emitting triangle mesh placed in the world. From a receiving point, a
// small mesh (at most kSolidAngleTriangles triangles: a quad, a lamp's panel) is sampled in
// solid angle: a rectangle as a whole (spherical rectangle, Urena et al. 2013), other
// triangles one by one (spherical triangle, Arvo 1995), each chosen in proportion to its
// area. Uniform area sampling takes over where solid-angle sampling does not pay or loses
// precision (see kMinSphericalSolidAngle and kMaxSphericalSolidAngle), and for larger
// meshes, where finding the triangle a point lies on would cost more than it saves.
#include <glint/geometry/mesh.h>
#include <glint/geometry/shape.h>

#include <optional>
#include <vector>

namespace glint {

class MeshSampler final : public ShapeSampler {
public:
    /// Meshes with at most this many triangles are sampled in solid angle.
    static constexpr size_t kSolidAngleTriangles = 8;
    /// Below this solid angle (sr) area sampling is used: a light this small is nearly
    /// uniform in solid angle under area sampling already (dist^2 / cos varies by about
    /// the solid angle across it), while the spherical formulas, which take differences of
    /// nearly equal angles, lose digits. A point nearly in the light's plane, outside it,
    /// sees a vanishing solid angle and also falls here.
    static constexpr double kMinSphericalSolidAngle = 3e-4;
    /// Above this (2 pi less 0.06 sr) area sampling is used too: a point almost on the light
    /// sees nearly a hemisphere, where the spherical angles degenerate (pbrt-v4 uses the same
    /// pair of thresholds, 3e-4 and 6.22).
    static constexpr double kMaxSphericalSolidAngle = 6.22;

    MeshSampler(const MeshData& mesh, const Transform& to_world);

    ShapeSample sample(const Vec3& ref, const Vec2& u, float u_select) const override;
    float pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const override;
    ShapeSample sample_area(const Vec2& u, float u_select) const override;
    float area() const override { return m_area; }
    Bounds3 bounds() const override { return m_bounds; }
    DirectionCone normal_cone() const override { return m_normal_cone; }

private:
    struct Rectangle {
        Vec3 corner, edge_x, edge_y;
    };
    size_t pick_triangle(float u_select) const;
    Vec3 point_in(size_t tri, const Vec2& u) const;
    size_t triangle_holding(const Vec3& p) const;
    float triangle_area(size_t tri) const;
    static bool spherical_pays(double solid_angle);
    static std::optional<Rectangle> as_rectangle(const std::vector<Vec3>& vertices,
                                                 const std::vector<Vec3>& normals);

    std::vector<Vec3> m_vertices;  // three per triangle, in the world
    std::vector<Vec3> m_normals;   // unit, per triangle, on the emitting side
    std::vector<double> m_cumulative_area;
    float m_area = 0.0f;
    float m_inverse_area = 0.0f;  // the density per unit area
    Bounds3 m_bounds;
    DirectionCone m_normal_cone;
    std::optional<Rectangle> m_rectangle;  // set when the mesh is two triangles of a rectangle
};

}  // namespace glint
