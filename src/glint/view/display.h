#pragma once
// What the viewer's window shows of a linear image: exposure, a tone curve and the sRGB
// transfer, to 8 bits per channel. Kept minimal and local to the viewer; with `clip` the
// bytes are exactly those `glint render` writes to PNG (film/image_io.h).
#include <glint/film/image.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

enum class DisplayToneMap {
    clip,      ///< scale by 2^exposure, clamp to [0, 1]: as PNG output
    reinhard,  ///< x / (1 + x) on each channel after the exposure: no channel ever clips
};

/// "clip" or "reinhard"; throws glint::Error naming the valid ones otherwise.
DisplayToneMap parse_display_tone_map(const std::string& name);

/// RGBA bytes (alpha 255), row-major, top row first, of `image`'s channels R, G, B.
std::vector<uint8_t> display_pixels(const Image& image, float exposure, DisplayToneMap tone_map);

/// The linear R, G, B image whose PNG output (write_image, exposure 0) is the RGBA bytes
/// `rgba` (alpha dropped): for saving what the window shows.
Image image_from_display(const std::vector<uint8_t>& rgba, int width, int height);

}  // namespace glint
