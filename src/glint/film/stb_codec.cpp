// PNG, JPEG, Radiance HDR, TGA, BMP, PNM, PSD and GIF through stb_image, and PNG output
// through stb_image_write (image_codecs.h). The only file that uses stb.
#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/film/image_codecs.h>

#include <fmt/format.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <cstdio>
#include <cstring>
#include <memory>

namespace glint {
namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// The names OpenEXR and most tools give 1 to 4 channels.
std::vector<std::string> channel_names(int channels) {
    switch (channels) {
        case 1:
            return {"Y"};
        case 2:
            return {"Y", "A"};
        case 3:
            return {"R", "G", "B"};
        default:
            return {"R", "G", "B", "A"};
    }
}

std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "unknown error";
}

// stb refuses a PNG header that claims more than 2^30 bytes without saying what it
// claimed; this reads the claim itself (the IHDR chunk right after the signature) so that
// check_image_header can name it.
void check_png_claim(std::FILE* file, const std::string& path, uint64_t file_bytes) {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char head[26];
    std::rewind(file);
    const size_t got = std::fread(head, 1, sizeof head, file);
    std::rewind(file);
    if (got < sizeof head || std::memcmp(head, kSignature, 8) != 0) return;
    auto big_endian = [&](int at) {
        return (uint32_t{head[at]} << 24) | (uint32_t{head[at + 1]} << 16) |
               (uint32_t{head[at + 2]} << 8) | uint32_t{head[at + 3]};
    };
    const int colour_type = head[25];
    const int channels = colour_type == 0 ? 1 : colour_type == 4 ? 2 : colour_type == 6 ? 4 : 3;
    check_image_header(path, big_endian(16), big_endian(20), channels, head[24] > 8 ? 2 : 1,
                       file_bytes);
}

}  // namespace

StoredImage read_stb(const std::string& path, uint64_t file_bytes, bool eight_bit_codes) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw Error("cannot open the file");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_file(file.get(), &width, &height, &channels)) {
        check_png_claim(file.get(), path, file_bytes);
        throw Error(fmt::format(
            "not an image glint reads ({}); glint reads OpenEXR, PNG, JPEG, Radiance HDR, TGA, "
            "BMP, PNM, PFM, PSD and GIF",
            stb_reason()));
    }
    const bool is_hdr = stbi_is_hdr_from_file(file.get()) != 0;
    const bool is_16_bit = !is_hdr && stbi_is_16_bit_from_file(file.get()) != 0;
    const uint64_t bytes_per_value = is_hdr ? 4 : is_16_bit ? 2 : 1;
    check_image_header(path, width, height, channels, bytes_per_value, file_bytes);

    StoredImage stored;
    Image& image = stored.image;
    int loaded_channels = 0;
    std::unique_ptr<void, StbFree> pixels;
    if (is_hdr) {
        pixels.reset(stbi_loadf_from_file(file.get(), &width, &height, &loaded_channels, 0));
    } else if (is_16_bit) {
        pixels.reset(stbi_load_from_file_16(file.get(), &width, &height, &loaded_channels, 0));
    } else {
        pixels.reset(stbi_load_from_file(file.get(), &width, &height, &loaded_channels, 0));
    }
    if (!pixels) throw Error(fmt::format("the file is damaged or ends early ({})", stb_reason()));
    if (loaded_channels < 1 || loaded_channels > 4)
        throw Error(fmt::format("the file decodes to {} channels", loaded_channels));

    image.width = width;
    image.height = height;
    image.channels = channel_names(loaded_channels);
    const size_t count = image.index(0, height, 0);
    if (!is_hdr && !is_16_bit && eight_bit_codes) {
        const uint8_t* codes = static_cast<const uint8_t*>(pixels.get());
        stored.codes.assign(codes, codes + count);
        stored.integer = true;
        stored.bits_per_value = 8;
        stored.alpha = loaded_channels == 2 || loaded_channels == 4 ? loaded_channels - 1 : -1;
        return stored;
    }
    image.pixels.resize(count);
    if (is_hdr) {
        const float* values = static_cast<const float*>(pixels.get());
        image.pixels.assign(values, values + count);
        stored.bits_per_value = 32;
    } else if (is_16_bit) {
        const uint16_t* codes = static_cast<const uint16_t*>(pixels.get());
        for (size_t i = 0; i < count; ++i) image.pixels[i] = codes[i] / 65535.0f;
        stored.integer = true;
        stored.bits_per_value = 16;
    } else {
        const uint8_t* codes = static_cast<const uint8_t*>(pixels.get());
        for (size_t i = 0; i < count; ++i) image.pixels[i] = codes[i] / 255.0f;
        stored.integer = true;
        stored.bits_per_value = 8;
    }
    stored.alpha = loaded_channels == 2 || loaded_channels == 4 ? loaded_channels - 1 : -1;
    return stored;
}

void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& codes) {
    const int row_bytes = width * channels;
    if (!stbi_write_png(path.c_str(), width, height, channels, codes.data(), row_bytes))
        throw Error("the PNG encoder could not write the file");
}

}  // namespace glint
