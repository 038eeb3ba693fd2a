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

/// What an editor (the viewer's light panel) may change in a light's description, by type.
struct LightEditing {
    /// The key of its strength (intensity, irradiance), a spectrum that defaults to 1.
    std::string power_key;
    /// The points that move with it (position, look_at); empty for a light that has no
    /// place (directional, environment).
    std::vector<std::string> position_keys;
};
/// How a light of `type` is edited; throws glint::Error for unknown types.
LightEditing light_editing(const std::string& type);
// Builds the light named by params.type(); relative file names start at `directory`.
std::unique_ptr<Light> make_light(const Params& params, const std::string& directory);

}  // namespace glint
