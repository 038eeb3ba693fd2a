#include <glint/core/error.h>
#include <glint/scene/import/file_bytes.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <system_error>

namespace glint {

std::string read_file_bytes(const std::string& path, const char* kind) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(fmt::format("cannot open {} file '{}'", kind, path));
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error(fmt::format("cannot read {} file '{}': {}", kind, path, ec.message()));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("cannot open {} file '{}'", kind, path));
    std::string bytes(size, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    // A file that shrank while it was read is as bad as an unreadable one.
    if (in.gcount() != static_cast<std::streamsize>(size))
        throw Error(fmt::format("cannot read {} file '{}': read error", kind, path));
    return bytes;
}

}  // namespace glint
