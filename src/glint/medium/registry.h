#pragma once
// Media from scene parameters (glint.medium{...}).
#include <glint/core/medium.h>
#include <glint/core/params.h>

#include <memory>

namespace glint {

/// The medium `params` describes; throws glint::Error naming the script line for a bad or
/// unknown parameter.
std::unique_ptr<Medium> make_medium(const Params& params);

}  // namespace glint
