#pragma once
// Loop subdivision of triangle meshes (Loop 1987), for pbrt's "loopsubdiv" shape: each level
// splits every triangle into four and smooths the vertices; after the last level the
// vertices are moved to their limit positions, and smooth normals are computed.
#include <glint/geometry/mesh.h>

namespace glint {

/// `levels` levels of Loop subdivision of `mesh` (positions and indices; other attributes
/// are dropped, normals are recomputed). Boundary edges follow the cubic B-spline rules
/// (their curve depends only on boundary vertices). Throws glint::Error for levels outside
/// [0, 8] (each level multiplies the triangles by four).
MeshData loop_subdivide(const MeshData& mesh, int levels);

}  // namespace glint
