#pragma once
// What the viewer's window shows of a linear image: exposure and a tone curve (the same
// curves as PNG output, film/tonemap.h), then the sRGB transfer, to 8 bits per channel: the
// bytes are exactly those `glint render` writes to PNG with the same settings.
#include <glint/film/image.h>
#include <glint/film/tonemap.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

/// RGBA bytes (alpha 255), row-major, top row first, of `image`'s channels R, G, B, through
/// `mapping` (exposure and tone curve).
std::vector<uint8_t> display_pixels(const Image& image, const ToneMapping& mapping);

/// The linear R, G, B image whose PNG output (write_image, exposure 0) is the RGBA bytes
/// `rgba` (alpha dropped): for saving what the window shows.
Image image_from_display(const std::vector<uint8_t>& rgba, int width, int height);

}  // namespace glint
