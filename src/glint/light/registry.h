#pragma once
// Scene-language names of the lights that are not shapes (area lights come from shapes
// with an emissive material).
#include <glint/core/params.h>
#include <glint/light/light.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

std::vector<std::string> light_types();
// Builds the light named by params.type(); relative file names start at `directory`.
std::unique_ptr<Light> make_light(const Params& params, const std::string& directory);

}  // namespace glint
