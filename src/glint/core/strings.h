#pragma once
// ASCII text helpers shared by the parsers, the format detection and the name lookups.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace glint {

// `text` with A–Z as a–z (other bytes unchanged): names and extensions compare without case.
inline std::string to_lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// The extension of `path` with its dot, in lower case (".exr"), or "" when it has none.
inline std::string lower_extension(const std::filesystem::path& path) {
    return to_lower(path.extension().string());
}

}  // namespace glint
