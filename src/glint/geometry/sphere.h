#pragma once
// Analytic sphere as Embree user geometry: exact silhouettes and normals at any size.
// Internally a unit sphere placed by a transform, so scaled spheres become ellipsoids.
#include <glint/geometry/shape.h>

namespace glint {

class Sphere final : public Shape {
public:
    // `to_parent` places the sphere (centre, radius) further inside its group.
    Sphere(const Vec3& center, float radius, const Transform& to_parent = Transform());

    std::string name() const override { return "sphere"; }
    Bounds3 bounds() const override;
    RTCGeometry create_embree_geometry(RTCDevice device) const override;
    void fill_interaction(const Ray& ray, const HitRecord& hit,
                          SurfaceInteraction& si) const override;
    std::unique_ptr<ShapeSampler> make_sampler(const Transform& to_world) const override;

    // Ray parameters where the ray (in the sphere's parent space) enters and leaves;
    // false when it misses. Used by Embree callbacks and, later, CSG.
    bool intersect_interval(const Vec3& origin, const Vec3& direction, float& t0, float& t1) const;

private:
    Transform m_to_parent;         // unit sphere at the origin -> parent space
    Transform m_parent_to_object;  // undoes the `transform` parameter, for solid textures
    // When parent space -> unit sphere is a uniform scale and a translation (a sphere placed
    // by its centre and radius alone, the common case), that scale and translation: the
    // matrix's own entries, so intersect_interval gets the same bits without the matrix
    // products (27 % fewer of its instructions; bench/README.md, "Stop 50").
    bool m_scale_and_offset = false;
    float m_scale = 1.0f;
    Vec3 m_offset{0.0f};
};

// Sampling of a sphere with centre and radius in world space: the cone of directions it
// subtends when the reference point is outside, uniform area otherwise.
class SphereSampler final : public ShapeSampler {
public:
    SphereSampler(const Vec3& center, float radius) : m_center(center), m_radius(radius) {}
    ShapeSample sample(const Vec3& ref, const Vec2& u, float u_select) const override;
    float pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const override;
    float area() const override { return 4.0f * kPi * m_radius * m_radius; }
    ShapeSample sample_area(const Vec2& u, float u_select) const override;
    Bounds3 bounds() const override {
        Bounds3 b;
        b.expand(m_center - Vec3(m_radius));
        b.expand(m_center + Vec3(m_radius));
        return b;
    }

private:
    Vec3 m_center;
    float m_radius;
};

}  // namespace glint
