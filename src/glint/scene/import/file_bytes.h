#pragma once
// Whole-file reads for the importers: one allocation and one read, which is what makes a
// million-triangle mesh load in a fraction of a second.
#include <glint/core/cancel.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace glint {

/// The bytes of the regular file at `path`. `kind` ("PLY", "OBJ", ...) names the format in
/// messages. Throws glint::Error when the file is missing, not a regular file, or unreadable.
std::string read_file_bytes(const std::string& path, const char* kind);

/// Calls parse(line, number) for each line of `text` (numbered from 1, without its '\n'),
/// for the line-based formats (OBJ, MTL).
template <typename Parse>
void for_each_line(std::string_view text, Parse&& parse) {
    uint64_t number = 0;
    while (!text.empty()) {
        // A model of millions of lines takes seconds: SIGINT is looked at every 2^16 lines.
        if ((number & 0xffff) == 0) throw_if_cancelled();
        const size_t end = text.find('\n');
        parse(text.substr(0, end), ++number);
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
}

}  // namespace glint
