#pragma once
// Wavefront OBJ import: positions, normals, uvs and polygonal faces, every value checked
// where it enters; faces grouped by the material they use (usemtl) for glint.import.
#include <glint/geometry/mesh.h>

#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

/// Reads a Wavefront OBJ file into one triangle mesh (all objects and groups merged).
/// Understands `v x y z [w]` (extra vertex-colour numbers are ignored), `vt u [v [w]]`,
/// `vn x y z` and `f` with corners `v`, `v/vt`, `v//vn` or `v/vt/vn`; indices are 1-based,
/// negative ones count back from the last element defined so far. Other statements
/// (o, g, s, usemtl, mtllib, l, p, ...) are ignored. Faces are polygons that OBJ documents
/// as convex and planar: each is split into a fan of triangles around its first corner, in
/// time linear in its corner count. Normals (uvs) are kept only when every corner has one.
/// Throws glint::Error naming the file and line for a missing file, a number that does
/// not parse or is not finite, an index that is 0, does not fit in 64 bits, or refers to
/// an element that does not exist, a face with fewer than 3 corners, or no faces at all.
MeshData load_obj(const std::string& path);

/// As load_obj, reading OBJ text from `in`; `name` stands for the file in messages.
MeshData parse_obj(std::istream& in, const std::string& name);

/// An OBJ file split by material: one mesh per `usemtl` name, in order of first use.
struct ObjScene {
    struct Part {
        std::string material;  ///< the `usemtl` name; empty for faces before any usemtl
        uint64_t line = 0;     ///< the line of the first usemtl naming it, for messages
        MeshData mesh;
    };
    std::vector<Part> parts;
    /// File names from `mtllib` statements, as written (relative to the OBJ's directory).
    std::vector<std::string> material_libraries;
};

/// As parse_obj, keeping faces of different materials apart (each part has its own
/// vertices; normals and uvs kept per part when every corner of the part has them).
ObjScene parse_obj_scene(std::string_view text, const std::string& name);
ObjScene load_obj_scene(const std::string& path);

}  // namespace glint
