#pragma once
// Scene-language names of the shapes and their factories.
#include <glint/core/params.h>
#include <glint/geometry/shape.h>
#include <glint/scene/scene_desc.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

std::vector<std::string> shape_types();
// Builds the shape named by params.type(); relative file names start at desc.directory,
// and a mesh with data = ObjectRef{"mesh_data", i} takes desc.meshes[i] (imported).
// The caller has already read the 'material' parameter.
std::unique_ptr<Shape> make_shape(const Params& params, const SceneDesc& desc);

}  // namespace glint
