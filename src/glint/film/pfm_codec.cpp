// Portable Float Maps (image_codecs.h): a text header "PF" (RGB) or "Pf" (grey), width,
// height and a scale whose sign gives the byte order (negative: little-endian), then the
// rows as 32-bit floats from the bottom row up.
#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/film/image_codecs.h>

#include <fmt/format.h>

#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

namespace glint {
namespace {

// The next whitespace-separated word of the header; exactly one whitespace byte ends it.
std::string header_word(std::istream& in) {
    std::string word;
    int c = in.get();
    while (c != EOF && std::isspace(c)) c = in.get();
    while (c != EOF && !std::isspace(c) && word.size() < 64) {
        word.push_back(static_cast<char>(c));
        c = in.get();
    }
    if (word.empty() || c == EOF) throw Error("the PFM header ends early");
    return word;
}

int64_t header_integer(std::istream& in, const char* what) {
    const std::string word = header_word(in);
    try {
        size_t used = 0;
        const long long value = std::stoll(word, &used);
        if (used == word.size()) return value;
    } catch (const std::exception&) {
    }
    throw Error(fmt::format("the PFM header's {} is not a whole number: '{}'", what, word));
}

}  // namespace

StoredImage read_pfm(const std::string& path, uint64_t file_bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open the file");
    const std::string kind = header_word(in);
    if (kind != "PF" && kind != "Pf") throw Error("not a PFM file (it must start with PF or Pf)");
    const int channels = kind == "PF" ? 3 : 1;
    const int64_t width = header_integer(in, "width");
    const int64_t height = header_integer(in, "height");
    const std::string scale_word = header_word(in);
    float scale = 0.0f;
    try {
        scale = std::stof(scale_word);
    } catch (const std::exception&) {
        throw Error(fmt::format("the PFM header's scale is not a number: '{}'", scale_word));
    }
    if (!(scale != 0.0f)) throw Error("the PFM header's scale must be a non-zero number");
    check_image_header(path, width, height, channels, sizeof(float), file_bytes);

    StoredImage stored;
    Image& image = stored.image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.channels =
        channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
    image.pixels.resize(image.index(0, image.height, 0));
    const bool file_little_endian = scale < 0.0f;
    const bool swap = file_little_endian != (std::endian::native == std::endian::little);
    const size_t row_values = static_cast<size_t>(width) * static_cast<size_t>(channels);
    for (int64_t row = 0; row < height; ++row) {
        // The file's first row is the image's bottom one.
        float* out = image.pixels.data() + static_cast<size_t>(height - 1 - row) * row_values;
        in.read(reinterpret_cast<char*>(out),
                static_cast<std::streamsize>(row_values * sizeof(float)));
        if (!in) throw Error("the file ends early: its pixel data is incomplete");
        if (swap) {
            for (size_t i = 0; i < row_values; ++i) {
                uint32_t bits;
                std::memcpy(&bits, &out[i], sizeof bits);
                bits = __builtin_bswap32(bits);
                std::memcpy(&out[i], &bits, sizeof bits);
            }
        }
    }
    // The scale's magnitude multiplies the values (1 in nearly every file).
    const float magnitude = std::abs(scale);
    if (magnitude != 1.0f) {
        for (float& value : image.pixels) value *= magnitude;
    }
    stored.bits_per_value = 32;
    return stored;
}

}  // namespace glint
