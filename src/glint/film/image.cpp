#include <glint/film/image.h>

#include <glint/core/error.h>

#include <fmt/format.h>

namespace glint {

int Image::channel_index(const std::string& name) const {
    for (std::size_t i = 0; i < channels.size(); ++i) {
        if (channels[i] == name) return static_cast<int>(i);
    }
    return -1;
}

Image make_image(int width, int height, std::vector<std::string> channels) {
    if (width < 0 || height < 0) {
        throw Error(fmt::format("image size {}x{}; expected non-negative sizes", width, height));
    }
    if (channels.empty()) throw Error("image needs at least one channel");
    Image image;
    image.width = width;
    image.height = height;
    image.channels = std::move(channels);
    image.pixels.assign(
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * image.channels.size(),
        0.0f);
    return image;
}

}  // namespace glint
