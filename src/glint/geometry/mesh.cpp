#include <glint/core/error.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/mesh_sampler.h>
#include <glint/math/warp.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace glint {
namespace {

Vec3 triangle_cross(const Vec3& a, const Vec3& b, const Vec3& c) {
    return glm::cross(b - a, c - a);
}

}  // namespace

TriangleMesh::TriangleMesh(std::string name, MeshData data) : m_name(std::move(name)) {
    const size_t vertex_count = data.positions.size();
    if (data.indices.size() % 3 != 0) {
        throw Error(fmt::format("mesh '{}': index count {} is not a multiple of 3", m_name,
                                data.indices.size()));
    }
    if (!data.normals.empty() && data.normals.size() != vertex_count) {
        throw Error(fmt::format("mesh '{}': {} normals for {} vertices", m_name,
                                data.normals.size(), vertex_count));
    }
    if (!data.uvs.empty() && data.uvs.size() != vertex_count) {
        throw Error(fmt::format("mesh '{}': {} uvs for {} vertices", m_name, data.uvs.size(),
                                vertex_count));
    }
    for (size_t i = 0; i < vertex_count; ++i) {
        if (!is_finite(data.positions[i])) {
            throw Error(fmt::format("mesh '{}': vertex {} is not finite", m_name, i + 1));
        }
        m_bounds.expand(data.positions[i]);
    }
    if (!data.position_keys.empty() && !data.normals.empty()) {
        throw Error(
            fmt::format("mesh '{}': a deforming mesh takes no normals (it is shaded by "
                        "its triangles' own normals at each time)",
                        m_name));
    }
    for (size_t k = 0; k < data.position_keys.size(); ++k) {
        const std::vector<Vec3>& key = data.position_keys[k];
        if (key.size() != vertex_count) {
            throw Error(fmt::format("mesh '{}': vertex key {} has {} vertices, the mesh {}", m_name,
                                    k + 2, key.size(), vertex_count));
        }
        for (size_t i = 0; i < key.size(); ++i) {
            if (!is_finite(key[i])) {
                throw Error(fmt::format("mesh '{}': vertex {} of key {} is not finite", m_name,
                                        i + 1, k + 2));
            }
            m_bounds.expand(key[i]);
        }
    }
    for (auto& n : data.normals) {
        const float len = glm::length(n);
        n = (std::isfinite(len) && len > 0.0f) ? n / len : Vec3(0.0f);
    }
    std::vector<uint32_t> kept;
    kept.reserve(data.indices.size());
    for (size_t t = 0; t < data.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            if (data.indices[t + k] >= vertex_count) {
                throw Error(fmt::format("mesh '{}': triangle {} uses vertex {} but there are {}",
                                        m_name, t / 3 + 1, data.indices[t + k] + 1, vertex_count));
            }
        }
        const Vec3 n =
            triangle_cross(data.positions[data.indices[t]], data.positions[data.indices[t + 1]],
                           data.positions[data.indices[t + 2]]);
        const float len2 = glm::dot(n, n);
        if (!(len2 > 0.0f) || !std::isfinite(len2)) continue;  // degenerate: no normal
        kept.insert(kept.end(), data.indices.begin() + t, data.indices.begin() + t + 3);
    }
    data.indices = std::move(kept);
    m_data = std::move(data);
    m_placed_by_transform = !m_data.to_object.is_identity();
    m_frames.reserve(m_data.indices.size() / 3);
    for (size_t t = 0; t < m_data.indices.size(); t += 3) m_frames.push_back(triangle_frame(t));
    if (m_data.normals.empty()) {
        m_flat_shading.reserve(m_frames.size());
        for (const TriangleFrame& frame : m_frames) {
            m_flat_shading.push_back(Frame::from_normal_tangent(frame.ng, frame.dpdu));
        }
    }
}

TriangleMesh::TriangleFrame TriangleMesh::triangle_frame(size_t first_index) const {
    const uint32_t* idx = &m_data.indices[first_index];
    return frame_of(m_data.positions[idx[0]], m_data.positions[idx[1]], m_data.positions[idx[2]],
                    first_index);
}

TriangleMesh::TriangleFrame TriangleMesh::frame_of(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                                   size_t first_index) const {
    const uint32_t* idx = &m_data.indices[first_index];
    TriangleFrame frame;
    frame.ng = glm::normalize(triangle_cross(p0, p1, p2));
    Vec2 uv0(0, 0), uv1(1, 0), uv2(1, 1);
    if (!m_data.uvs.empty()) {
        uv0 = m_data.uvs[idx[0]];
        uv1 = m_data.uvs[idx[1]];
        uv2 = m_data.uvs[idx[2]];
    }
    const Vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    const Vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    const float det = duv02.x * duv12.y - duv02.y * duv12.x;
    if (std::abs(det) > 1e-12f) {
        const float inv = 1.0f / det;
        frame.dpdu = (duv12.y * dp02 - duv02.y * dp12) * inv;
        frame.dpdv = (duv02.x * dp12 - duv12.x * dp02) * inv;
    } else {
        const Frame f = Frame::from_normal(frame.ng);
        frame.dpdu = f.s();
        frame.dpdv = f.t();
    }
    return frame;
}

size_t TriangleMesh::memory_bytes() const {
    return m_data.positions.capacity() * sizeof(Vec3) + m_data.normals.capacity() * sizeof(Vec3) +
           m_data.uvs.capacity() * sizeof(Vec2) + m_data.indices.capacity() * sizeof(uint32_t) +
           m_frames.capacity() * sizeof(TriangleFrame) + m_flat_shading.capacity() * sizeof(Frame) +
           m_data.position_keys.size() * m_data.positions.size() * sizeof(Vec3);
}

RTCGeometry TriangleMesh::create_embree_geometry(RTCDevice device) const {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // A deforming mesh is one of Embree's multi-segment motion-blur geometries: a vertex
    // buffer per key, which Embree interpolates linearly at each ray's time.
    const unsigned keys = 1 + static_cast<unsigned>(m_data.position_keys.size());
    if (keys > 1) rtcSetGeometryTimeStepCount(geometry, keys);
    for (unsigned key = 0; key < keys; ++key) {
        const std::vector<Vec3>& positions =
            key == 0 ? m_data.positions : m_data.position_keys[key - 1];
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, key, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), positions.size()));
        for (size_t i = 0; i < positions.size(); ++i)
            std::memcpy(vertices + 3 * i, &positions[i], 3 * sizeof(float));
    }
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), m_data.indices.size() / 3));
    std::copy(m_data.indices.begin(), m_data.indices.end(), indices);
    rtcCommitGeometry(geometry);
    return geometry;
}

// Everything is computed in locals and stored once: reading back a vector just stored
// component by component into `si` (as copying si.p to si.p_object did) makes the CPU wait
// for the stores to land, at every hit.
void TriangleMesh::fill_interaction(const Ray& ray, const HitRecord& hit,
                                    SurfaceInteraction& si) const {
    if (!m_data.position_keys.empty()) [[unlikely]] {
        fill_deformed(ray.time, hit, si);
        return;
    }
    const uint32_t* idx = &m_data.indices[3 * hit.primitive];
    const float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1.0f - b1 - b2;
    const Vec3 p = b0 * m_data.positions[idx[0]] + b1 * m_data.positions[idx[1]] +
                   b2 * m_data.positions[idx[2]];
    const TriangleFrame& frame = m_frames[hit.primitive];
    Vec3 ng = frame.ng;
    const Vec3& dpdu = frame.dpdu;
    const Vec3& dpdv = frame.dpdv;
    Vec2 uv0(0, 0), uv1(1, 0), uv2(1, 1);
    if (!m_data.uvs.empty()) {
        uv0 = m_data.uvs[idx[0]];
        uv1 = m_data.uvs[idx[1]];
        uv2 = m_data.uvs[idx[2]];
    }

    if (m_data.normals.empty()) {
        si.shading = m_flat_shading[hit.primitive];  // its normal is ng
    } else {
        Vec3 ns = ng;
        const Vec3 interpolated =
            b0 * m_data.normals[idx[0]] + b1 * m_data.normals[idx[1]] + b2 * m_data.normals[idx[2]];
        const float len2 = glm::dot(interpolated, interpolated);
        if (len2 > 0.0f) {
            ns = interpolated / std::sqrt(len2);
            // The artist's normals define the outside when they disagree with the winding.
            if (glm::dot(ng, ns) < 0.0f) ng = -ng;
        }
        si.shading = Frame::from_normal_tangent(ns, dpdu);
    }
    si.p = p;
    si.p_object = m_placed_by_transform ? m_data.to_object.point(p) : p;
    si.ng = ng;
    si.uv = b0 * uv0 + b1 * uv1 + b2 * uv2;
    si.dpdu = dpdu;
    si.dpdv = dpdv;
}

Vec3 TriangleMesh::geometric_normal(const Ray& ray, const HitRecord& hit) const {
    if (!m_data.position_keys.empty()) [[unlikely]]
        return Shape::geometric_normal(ray, hit);
    // As fill_interaction(): the winding's normal, turned to the artist's normals' side.
    const Vec3 ng = m_frames[hit.primitive].ng;
    if (m_data.normals.empty()) return ng;
    const uint32_t* idx = &m_data.indices[3 * hit.primitive];
    const float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1.0f - b1 - b2;
    const Vec3 interpolated =
        b0 * m_data.normals[idx[0]] + b1 * m_data.normals[idx[1]] + b2 * m_data.normals[idx[2]];
    return glm::dot(interpolated, interpolated) > 0.0f && glm::dot(ng, interpolated) < 0.0f ? -ng
                                                                                            : ng;
}

void TriangleMesh::fill_deformed(float time, const HitRecord& hit, SurfaceInteraction& si) const {
    // Between the two keys around `time`, linearly, as Embree interpolates them.
    const size_t segments = m_data.position_keys.size();
    const float f = std::clamp(time, 0.0f, 1.0f) * static_cast<float>(segments);
    const size_t first = std::min(static_cast<size_t>(f), segments - 1);
    const float w = f - static_cast<float>(first);
    const std::vector<Vec3>& a = first == 0 ? m_data.positions : m_data.position_keys[first - 1];
    const std::vector<Vec3>& b = m_data.position_keys[first];
    const uint32_t* idx = &m_data.indices[3 * hit.primitive];
    Vec3 corner[3];
    for (int k = 0; k < 3; ++k) corner[k] = (1.0f - w) * a[idx[k]] + w * b[idx[k]];
    // A triangle that collapses at this time keeps the frame it has at rest.
    const bool collapsed = !(glm::length(triangle_cross(corner[0], corner[1], corner[2])) > 0.0f);
    const TriangleFrame frame = collapsed
                                    ? m_frames[hit.primitive]
                                    : frame_of(corner[0], corner[1], corner[2], 3 * hit.primitive);
    const float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1.0f - b1 - b2;
    const Vec3 p = b0 * corner[0] + b1 * corner[1] + b2 * corner[2];
    Vec2 uv0(0, 0), uv1(1, 0), uv2(1, 1);
    if (!m_data.uvs.empty()) {
        uv0 = m_data.uvs[idx[0]];
        uv1 = m_data.uvs[idx[1]];
        uv2 = m_data.uvs[idx[2]];
    }
    si.shading = Frame::from_normal_tangent(frame.ng, frame.dpdu);
    si.p = p;
    si.p_object = m_placed_by_transform ? m_data.to_object.point(p) : p;
    si.ng = frame.ng;
    si.uv = b0 * uv0 + b1 * uv1 + b2 * uv2;
    si.dpdu = frame.dpdu;
    si.dpdv = frame.dpdv;
}

std::unique_ptr<ShapeSampler> TriangleMesh::make_sampler(const Transform& to_world) const {
    if (m_data.indices.empty())
        throw Error(fmt::format("mesh '{}' has no triangles to emit from", m_name));
    return std::make_unique<MeshSampler>(m_data, to_world);
}

MeshData make_quad_mesh(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    MeshData mesh;
    mesh.positions = {p0, p1, p2, p3};
    mesh.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

MeshData make_box_mesh(const Vec3& lo, const Vec3& hi) {
    MeshData mesh;
    // Each face: an axis, the side, and two in-plane axes ordered so the normal points out.
    auto add_face = [&](int axis, bool positive) {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        const float w = positive ? hi[axis] : lo[axis];
        auto corner = [&](float s, float t) {
            Vec3 p;
            p[axis] = w;
            p[a] = s;
            p[b] = t;
            return p;
        };
        const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
        if (positive) {
            mesh.positions.insert(mesh.positions.end(),
                                  {corner(lo[a], lo[b]), corner(hi[a], lo[b]), corner(hi[a], hi[b]),
                                   corner(lo[a], hi[b])});
        } else {
            mesh.positions.insert(mesh.positions.end(),
                                  {corner(lo[a], lo[b]), corner(lo[a], hi[b]), corner(hi[a], hi[b]),
                                   corner(hi[a], lo[b])});
        }
        mesh.uvs.insert(mesh.uvs.end(), {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    };
    for (int axis = 0; axis < 3; ++axis) {
        add_face(axis, false);
        add_face(axis, true);
    }
    return mesh;
}

void transform_mesh(MeshData& mesh, const Transform& xf) {
    if (xf.is_identity()) return;
    mesh.to_object = mesh.to_object * xf.inverse();
    for (auto& p : mesh.positions) p = xf.point(p);
    for (auto& key : mesh.position_keys)
        for (auto& p : key) p = xf.point(p);
    for (auto& n : mesh.normals) n = glm::normalize(xf.normal(n));
    // A mirroring transform reverses the winding; restore it so normals still point out.
    if (xf.swaps_handedness()) {
        for (size_t t = 0; t < mesh.indices.size(); t += 3)
            std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
}

}  // namespace glint
