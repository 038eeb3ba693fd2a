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

// `text` fit to quote in a message: control characters (other than newline and tab) and
// bytes that do not form valid UTF-8 become '?'. Decoders' messages can quote bytes of the
// damaged file they read (a chunk type, a channel name).
inline std::string printable_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        // The length of the UTF-8 sequence this byte starts, 0 for one that starts none.
        const size_t length = byte < 0x80           ? 1
                              : (byte >> 5) == 0x6  ? 2
                              : (byte >> 4) == 0xe  ? 3
                              : (byte >> 3) == 0x1e ? 4
                                                    : 0;
        bool valid = length > 0 && i + length <= text.size();
        for (size_t k = 1; valid && k < length; ++k)
            valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
        if (!valid ||
            (length == 1 && ((byte < 0x20 && byte != '\n' && byte != '\t') || byte == 0x7f))) {
            out.push_back('?');
            ++i;
        } else {
            out.append(text.substr(i, length));
            i += length;
        }
    }
    return out;
}

}  // namespace glint
