#pragma once
// Triangle mesh: Embree's native triangles. Quads and boxes are built as meshes too, so
// they get Embree's fastest path and watertight edges (no light leaks between triangles).
#include <glint/geometry/shape.h>
#include <glint/math/transform.h>

#include <vector>

namespace glint {

struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;      // per vertex, optional
    std::vector<Vec2> uvs;          // per vertex, optional
    std::vector<uint32_t> indices;  // three per triangle
    // Deformation blur: the positions at later times, each as many as `positions` (which is
    // the first key); n keys in all stand at the scene times i / (n - 1). Empty: the mesh
    // keeps its form.
    std::vector<std::vector<Vec3>> position_keys;
    // Undoes the transform applied by transform_mesh, so that solid textures see the mesh
    // where it was modelled.
    Transform to_object;
};

class TriangleMesh final : public Shape {
public:
    // Validates the data: indices in range, finite positions, no NaN normals. Degenerate
    // (zero-area) triangles are dropped because they have no normal. Throws glint::Error.
    TriangleMesh(std::string name, MeshData data);

    std::string name() const override { return m_name; }
    Bounds3 bounds() const override { return m_bounds; }
    size_t triangle_count() const override { return m_data.indices.size() / 3; }
    bool deforms() const override { return !m_data.position_keys.empty(); }
    size_t memory_bytes() const override;
    RTCGeometry create_embree_geometry(RTCDevice device) const override;
    void fill_interaction(const Ray& ray, const HitRecord& hit,
                          SurfaceInteraction& si) const override;
    Vec3 geometric_normal(const Ray& ray, const HitRecord& hit) const override;
    // Embree's normal is the winding's, as geometric_normal() is unless vertex normals turn
    // it (or the mesh deforms).
    bool hit_normal_sides_as_geometric() const override {
        return m_data.normals.empty() && m_data.position_keys.empty();
    }
    std::unique_ptr<ShapeSampler> make_sampler(const Transform& to_world) const override;

    const MeshData& data() const { return m_data; }

private:
    // What is constant over a triangle, computed once per triangle rather than at every
    // hit, where it was a third of glint's work per ray (36 bytes per triangle; Embree's
    // BVH takes more).
    struct TriangleFrame {
        Vec3 ng;          // unit geometric normal, by the winding
        Vec3 dpdu, dpdv;  // from the uvs, or a frame around ng where they are degenerate
    };
    TriangleFrame triangle_frame(size_t first_index) const;
    // The frame of the triangle with corners p0, p1, p2 (in index order from first_index).
    TriangleFrame frame_of(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                           size_t first_index) const;
    // A deforming mesh's hit: its triangle's corners where they stand at `time`.
    void fill_deformed(float time, const HitRecord& hit, SurfaceInteraction& si) const;

    std::string m_name;
    MeshData m_data;
    std::vector<TriangleFrame> m_frames;  // one per triangle
    // Without vertex normals the shading frame is constant over a triangle too: kept whole
    // (36 bytes per triangle, only for such meshes), so that a hit copies it from memory
    // written long before. Built from its parts at each hit, it went through a temporary
    // whose reads waited for its stores to land (1 % of the preview in fog).
    std::vector<Frame> m_flat_shading;
    Bounds3 m_bounds;
    bool m_placed_by_transform = false;  // to_object is not the identity (checked once)
};

// A planar quad with corners in counter-clockwise order seen from its front (the side its
// normal, by the right-hand rule, points to); two triangles.
MeshData make_quad_mesh(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);
// An axis-aligned box with outward normals, 12 triangles and per-face uvs.
MeshData make_box_mesh(const Vec3& min, const Vec3& max);
void transform_mesh(MeshData& mesh, const Transform& xf);

}  // namespace glint
