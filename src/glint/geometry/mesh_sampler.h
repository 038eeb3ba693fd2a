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
    /// Below this solid angle (sr, as estimated by area |cos| / dist^2 from the light's
    /// centre) area sampling is used. Area sampling's density, dist^2 / cos over the area,
    /// varies across a light by little when the light subtends little, so spherical sampling
    /// gains little there and costs more (its trigonometry in double). Measured on the
    /// Cornell box (256x256, 32 spp, processor time): with pbrt-v4's limit of 3e-4 sr or
    /// with 0.05 sr (about the lamp seen from the floor's centre) the render took 20 % more
    /// time for 5 % less error, a net loss; only points close to a light profit. A point
    /// nearly in the light's plane, outside it, sees a vanishing solid angle and also falls
    /// here.
    static constexpr double kMinSphericalSolidAngle = 0.5;
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

    /// Every triangle is a piece, except in a rectangle, which is sampled whole.
    uint32_t piece_count() const override {
        return m_rectangle ? 1u : static_cast<uint32_t>(m_normals.size());
    }
    Bounds3 piece_bounds(uint32_t piece) const override;
    DirectionCone piece_normal_cone(uint32_t piece) const override;
    float piece_area(uint32_t piece) const override;
    /// The triangle in solid angle where that pays (the same limits as sample()), by area
    /// otherwise.
    ShapeSample sample_piece(const Vec3& ref, const Vec2& u, float u_select,
                             uint32_t piece) const override;
    float pdf_piece(const Vec3& ref, const Vec3& p, const Vec3& n, uint32_t piece) const override;

private:
    struct Rectangle {
        Vec3 corner, edge_x, edge_y;
    };
    [[gnu::always_inline]] inline size_t pick_triangle(float u_select) const;
    bool is_piece(uint32_t piece) const { return !m_rectangle && piece < m_normals.size(); }
    // A point on triangle `tri` seen from `ref`, with its density given the triangle.
    ShapeSample sample_triangle(const Vec3& ref, const Vec2& u, size_t tri) const;
    float pdf_in_triangle(const Vec3& ref, const Vec3& p, const Vec3& n, size_t tri) const;
    Vec3 rectangle_centre() const {
        return m_rectangle->corner + 0.5f * (m_rectangle->edge_x + m_rectangle->edge_y);
    }
    [[gnu::always_inline]] inline Vec3 point_in(size_t tri, const Vec2& u) const;
    size_t triangle_holding(const Vec3& p) const;
    float triangle_area(size_t tri) const;
    static bool spherical_pays(double solid_angle);
    /// Whether the cheap estimate area |cos| / dist^2 of the solid angle of a light part
    /// (centre `c`, unit normal `n`, `area`) from `ref` reaches kMinSphericalSolidAngle:
    /// most points see most lights smaller than that, and skip the exact solid angle.
    static bool may_pay(const Vec3& ref, const Vec3& c, const Vec3& n, float area);
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
