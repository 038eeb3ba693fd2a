#pragma once
// Scene-language names of the shapes and their factories.
#include <glint/core/params.h>
#include <glint/geometry/shape.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

std::vector<std::string> shape_types();
// Builds the shape named by params.type(); relative file names start at `directory`.
// The caller has already read the 'material' parameter.
std::unique_ptr<Shape> make_shape(const Params& params, const std::string& directory);

}  // namespace glint
