#pragma once
// PLY (Stanford polygon file) import: ASCII and binary (little and big endian) meshes with
// positions, normals, uvs and vertex colours, read by glint's own reader.
#include <glint/geometry/mesh.h>

#include <string>
#include <string_view>
#include <vector>

namespace glint {

/// What a PLY file holds that glint reads.
struct PlyMesh {
    MeshData mesh;
    /// Linear RGB per vertex in [0, 1] (`red green blue`: uchar / 255, or floats as given);
    /// empty when the file has none. Read and checked, not yet used for shading.
    std::vector<Vec3> colors;
};

/// Reads a PLY file: element `vertex` with `x y z` and optionally `nx ny nz`, uvs as `u v`,
/// `s t`, `texture_u texture_v` or `texture_s texture_t`, and `red green blue`; element
/// `face` with a list property `vertex_indices` (or `vertex_index`), whose polygons are
/// split into fans of triangles. Other elements and properties are skipped. Any scalar type
/// (char/int8 ... double/float64) is accepted for any property; list counts and indices must
/// be integers. Throws glint::Error naming the file and the line (ASCII) or byte offset
/// (binary) of a malformed header, a truncated body, a value that is not a finite number,
/// an index out of range, a face with fewer than 3 corners, or no faces at all.
PlyMesh load_ply(const std::string& path);

/// As load_ply, from the bytes of a file; `name` stands for the file in messages.
PlyMesh parse_ply(std::string_view bytes, const std::string& name);

}  // namespace glint
