#pragma once
// pbrt-v4's scene format, read directive by directive into a PbrtScene: the graphics state
// (current transform, material, area light, orientation) kept on a stack by
// AttributeBegin/End, named coordinate systems, Include/Import, object definitions.
#include <glint/scene/import/pbrt/scene.h>

#include <string>

namespace glint {

/// Reads the pbrt file at `path` and every file it includes. Throws glint::Error
/// "file:line: ..." for malformed input: an unknown directive, a bad parameter declaration,
/// a missing or wrong count of numbers, an unterminated string or bracket, an unmatched
/// AttributeEnd/ObjectEnd, a missing include, an include cycle. What is well formed but not
/// supported is left to the translator or recorded in PbrtScene::warnings.
PbrtScene parse_pbrt_file(const std::string& path);

/// As parse_pbrt_file, from text; `name` stands for the file in messages and `directory`
/// is where included and referenced files are looked for.
PbrtScene parse_pbrt_text(std::string text, const std::string& name, const std::string& directory);

}  // namespace glint
