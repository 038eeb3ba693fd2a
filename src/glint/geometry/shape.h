#pragma once
// The Shape interface. A shape lives in the space of the group that holds it; the scene
// places groups in the world. Ray queries go through Embree (geometry/accel.h): meshes
// natively, analytic shapes as Embree user geometry.
#include <glint/core/interaction.h>
#include <glint/math/bounds.h>
#include <glint/math/direction_cone.h>

#include <embree3/rtcore.h>

#include <memory>
#include <string>

namespace glint {

// What Embree reported for a hit, enough for the shape to rebuild the full interaction.
// Accel writes every field of a record when its ray hits, and nothing reads a record of a
// miss, so the fields have no initialisers: the path tracer declares eight per packet and
// bounce, and initialising them (288 bytes from a constant, a `rep movs`) cost more than
// the rest of the packet's setup. Write HitRecord{} for a zeroed one.
struct HitRecord {
    float t;
    unsigned top_geometry;    // geometry id in the world scene
    unsigned local_geometry;  // geometry id inside an instance; RTC_INVALID_GEOMETRY_ID if none
    unsigned primitive;
    Vec2 barycentric;
    Vec3 normal;  // as the geometry reported it (user geometry uses it to pass data)
    bool instanced() const { return local_geometry != RTC_INVALID_GEOMETRY_ID; }
};

// A point drawn on an emitting surface, in world space.
struct ShapeSample {
    Vec3 p;
    Vec3 n;            // unit surface normal at p (outward)
    float pdf = 0.0f;  // solid-angle density with respect to the reference point
    // The unit direction from the reference point to p, where the sampler drew it (a
    // sphere's cone): the light takes it instead of normalising p - ref, a square root and
    // a division that every light sample waited on. Zero where the sampler has none.
    Vec3 direction{0.0f};
};

// World-space sampling of a placed shape, used by area lights. Densities are in solid
// angle as seen from `ref`; every implementation is chi-square tested.
class ShapeSampler {
public:
    virtual ~ShapeSampler() = default;
    virtual ShapeSample sample(const Vec3& ref, const Vec2& u, float u_select) const = 0;
    // Density of sampling the point `p` with normal `n` from `ref`.
    virtual float pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const = 0;
    virtual float area() const = 0;
    // A point uniform over the surface (pdf = 1 / area), for emitting photons.
    virtual ShapeSample sample_area(const Vec2& u, float u_select) const = 0;
    // World-space box and the cone holding every outward normal, for the light tree.
    virtual Bounds3 bounds() const = 0;
    virtual DirectionCone normal_cone() const { return DirectionCone::whole_sphere(); }

    // Pieces: parts of the shape that the light tree chooses among one by one (the triangles
    // of an emitting mesh), so that a large emitter's near parts get its samples. A shape
    // sampled whole (a sphere, a rectangle) is one piece, and the calls below are then
    // those above. A piece's index is the primitive index of its hits (HitRecord).
    virtual uint32_t piece_count() const { return 1; }
    // The box, normals and area of one piece.
    virtual Bounds3 piece_bounds(uint32_t) const { return bounds(); }
    virtual DirectionCone piece_normal_cone(uint32_t) const { return normal_cone(); }
    virtual float piece_area(uint32_t) const { return area(); }
    // sample() within one piece: the density is the point's given that piece.
    virtual ShapeSample sample_piece(const Vec3& ref, const Vec2& u, float u_select,
                                     uint32_t) const {
        return sample(ref, u, u_select);
    }
    // The density of sample_piece choosing `p` (normal `n`) on `piece`.
    virtual float pdf_piece(const Vec3& ref, const Vec3& p, const Vec3& n, uint32_t) const {
        return pdf(ref, p, n);
    }
};

class Shape {
public:
    virtual ~Shape() = default;

    virtual std::string name() const = 0;
    virtual Bounds3 bounds() const = 0;
    virtual size_t triangle_count() const { return 0; }
    /// Whether the shape changes its form over the scene times [0, 1] (deformation blur: a
    /// mesh with vertex keys); its hits then depend on the ray's time.
    virtual bool deforms() const { return false; }
    /// Bytes of the shape's own arrays (vertices, indices, per-triangle data), for `glint
    /// info`; what Embree holds is counted by Accel::embree_bytes().
    virtual size_t memory_bytes() const { return 0; }

    // A committed Embree geometry for this shape; the shape must outlive it.
    virtual RTCGeometry create_embree_geometry(RTCDevice device) const = 0;

    // Fills position, normals, shading frame, uv and derivatives in the shape's space.
    // `ray` is the ray in that space and `hit` what Embree reported.
    virtual void fill_interaction(const Ray& ray, const HitRecord& hit,
                                  SurfaceInteraction& si) const = 0;
    // The unit geometric normal fill_interaction() gives at `hit` (its si.ng), for a walk
    // that only asks which side of the surface it crosses to. Shapes whose full interaction
    // costs much more override it.
    virtual Vec3 geometric_normal(const Ray& ray, const HitRecord& hit) const {
        SurfaceInteraction si;
        fill_interaction(ray, hit, si);
        return si.ng;
    }
    // Whether the normal in this shape's hit records (Embree's, not unit) always lies on the
    // side of geometric_normal(): a walk that asks only which side it crosses to may then
    // read it from the record.
    virtual bool hit_normal_sides_as_geometric() const { return false; }

    // Sampling of this shape placed in the world by `to_world`, for area lights.
    virtual std::unique_ptr<ShapeSampler> make_sampler(const Transform& to_world) const = 0;
};

// Converts an area density at `p` (normal `n`) into a solid-angle density seen from `ref`.
inline float area_to_solid_angle_pdf(float pdf_area, const Vec3& ref, const Vec3& p,
                                     const Vec3& n) {
    // pdf_area * dist^2 / cos_light with cos_light = |n.d| / dist: one division, and the
    // square root does not wait for it.
    const Vec3 d = p - ref;
    const float dist2 = glm::dot(d, d);
    const float n_dot_d = std::abs(glm::dot(n, d));
    if (!(n_dot_d > 0.0f) || !(dist2 > 0.0f)) return 0.0f;
    return pdf_area * dist2 * std::sqrt(dist2) / n_dot_d;
}

}  // namespace glint
