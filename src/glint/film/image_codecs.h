#pragma once
// The file formats behind image_io.h, one third-party library to a file: exr_codec.cpp
// (OpenEXR), stb_codec.cpp (stb_image and stb_image_write: PNG, JPEG, Radiance HDR, TGA,
// BMP, PNM, PSD, GIF) and pfm_codec.cpp (glint's own, for the Portable Float Maps pbrt
// scenes use). Each reader checks the header (core/memory.h, check_image_header) before it
// allocates the pixels, and throws glint::Error with the reason; image_io.cpp adds the path
// and chooses the reader by the file's first bytes.
#include <glint/film/image_io.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

/// Reads an OpenEXR file (scan lines or tiles; the first part, level 0, data window): every
/// channel as float under its file name, in the file's order (sorted by name), and the
/// header's string attributes named "glint:*".
StoredImage read_exr(const std::string& path, uint64_t file_bytes);

/// Writes every channel of `image` as 32-bit float (16-bit half with `half`), ZIP
/// compressed, with its attributes as "glint:<name>" strings; no time stamp, so a render
/// writes the same bytes every run.
void write_exr(const std::string& path, const Image& image, bool half);

/// Reads the formats stb_image decodes. Integer files come back as code values / 255 (or
/// / 65535), named Y, YA, RGB or RGBA; Radiance HDR as linear float RGB.
/// With `eight_bit_codes`, an 8-bit file's values are kept as StoredImage::codes.
StoredImage read_stb(const std::string& path, uint64_t file_bytes, bool eight_bit_codes);

/// Writes 8-bit code values, `channels` (1 to 4) per pixel, row 0 at the top, as PNG.
void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& codes);

/// Reads a Portable Float Map ("PF" colour, "Pf" grey; rows stored bottom-up, the scale's
/// sign giving the byte order).
StoredImage read_pfm(const std::string& path, uint64_t file_bytes);

}  // namespace glint
