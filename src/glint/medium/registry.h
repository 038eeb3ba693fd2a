#pragma once
// Media from scene parameters (glint.medium{...}).
#include <glint/core/medium.h>
#include <glint/core/params.h>

#include <memory>
#include <string>

namespace glint {

/// The medium `params` describes; `directory` is the scene's folder, which relative grid
/// file names start from (default: the working folder). Throws glint::Error naming the
/// script line for a bad or unknown parameter, or a grid file that cannot be read.
std::unique_ptr<Medium> make_medium(const Params& params, const std::string& directory = ".");

}  // namespace glint
