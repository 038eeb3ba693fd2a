#pragma once
#include <glint/geometry/mesh.h>

#include <string>

namespace glint {

// Reads a Wavefront OBJ file into one triangle mesh (all objects merged, polygons
// triangulated). Throws glint::Error naming the file when it cannot be read.
MeshData load_obj(const std::string& path);

}  // namespace glint
