#include <glint/core/file_access.h>
#include <glint/scene/import/file_bytes.h>

#include <fmt/format.h>

namespace glint {

std::string read_file_bytes(const std::string& path, const char* kind) {
    return read_regular_file(path, fmt::format("{} file", kind));
}

}  // namespace glint
