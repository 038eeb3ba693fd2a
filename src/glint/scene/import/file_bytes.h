#pragma once
// Whole-file reads for the importers: one allocation and one read, which is what makes a
// million-triangle mesh load in a fraction of a second.
#include <string>

namespace glint {

/// The bytes of the regular file at `path`. `kind` ("PLY", "OBJ", ...) names the format in
/// messages. Throws glint::Error when the file is missing, not a regular file, or unreadable.
std::string read_file_bytes(const std::string& path, const char* kind);

}  // namespace glint
