#pragma once
// Scene-language names of the shapes -> create from Params. Each shape's parameters are
// read once, here: the CSG builder (scene/solids.cpp) reads its sphere and box primitives
// with the same read_sphere() and read_box().
#include <glint/core/params.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/shape.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

/// Where a shape's data may come from besides its parameters.
struct ShapeSources {
    /// Relative file names start here.
    std::string directory;
    /// Imported geometry: a mesh with data = ObjectRef{"mesh_data", i} takes meshes[i].
    const std::vector<std::shared_ptr<const MeshData>>* meshes = nullptr;
    /// Reads a mesh file (.obj, .ply); throws glint::Error.
    MeshData (*load_mesh_file)(const std::string& path) = nullptr;
};

std::vector<std::string> shape_types();

/// Builds the shape named by params.type() and checks every key was read. The caller has
/// already read the 'material' parameter.
std::unique_ptr<Shape> make_shape(const Params& params, const ShapeSources& sources);

/// A sphere's `center` and `radius` (validated).
struct SphereParams {
    Vec3 center;
    float radius;
};
SphereParams read_sphere(const Params& params);

/// A box's `min` and `max` corners (validated).
struct BoxParams {
    Vec3 lo, hi;
};
BoxParams read_box(const Params& params);

}  // namespace glint
