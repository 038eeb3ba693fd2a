#pragma once
// Runs a scene script in a Lua 5.4 VM with the `glint` module and returns the scene it
// describes. This is the only place in glint that knows Lua exists.
#include <glint/scene/scene_desc.h>

#include <string>

namespace glint {

// Throws glint::Error "file:line: message" on a syntax error, a runtime error, or a
// parameter of the wrong type.
SceneDesc load_scene_file(const std::string& path);
// `chunk_name` is used in error messages in place of a file name.
SceneDesc load_scene_string(const std::string& code, const std::string& chunk_name,
                            const std::string& directory = ".");

}  // namespace glint
