#include <glint/film/image.h>

#include <glint/core/error.h>

#include <fmt/format.h>

#include <algorithm>

namespace glint {

const std::string* Image::attribute(const std::string& name) const {
    for (const auto& [key, value] : attributes) {
        if (key == name) return &value;
    }
    return nullptr;
}

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

Image with_channel(const Image& image, const std::string& name, const std::vector<float>& values) {
    const std::size_t pixel_count = static_cast<std::size_t>(image.width) * image.height;
    if (values.size() != pixel_count) {
        throw Error(fmt::format("channel '{}' has {} values for {} pixels", name, values.size(),
                                pixel_count));
    }
    std::vector<std::string> channels = image.channels;
    channels.push_back(name);
    Image result = make_image(image.width, image.height, std::move(channels));
    const int old_count = image.num_channels();
    for (std::size_t p = 0; p < pixel_count; ++p) {
        for (int c = 0; c < old_count; ++c)
            result.pixels[p * (old_count + 1) + c] = image.pixels[p * old_count + c];
        result.pixels[p * (old_count + 1) + old_count] = values[p];
    }
    return result;
}

Image without_channels(const Image& image, const std::vector<std::string>& prefixes) {
    std::vector<int> kept;
    std::vector<std::string> names;
    for (int c = 0; c < image.num_channels(); ++c) {
        const std::string& name = image.channels[static_cast<size_t>(c)];
        const bool dropped = std::any_of(prefixes.begin(), prefixes.end(), [&](const auto& p) {
            return name.compare(0, p.size(), p) == 0;
        });
        if (!dropped) {
            kept.push_back(c);
            names.push_back(name);
        }
    }
    Image result = make_image(image.width, image.height, std::move(names));
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (size_t k = 0; k < kept.size(); ++k)
                result.at(x, y, static_cast<int>(k)) = image.at(x, y, kept[k]);
        }
    }
    return result;
}

Image grey_image(int width, int height, const std::vector<float>& values) {
    Image image = make_image(width, height, {"R", "G", "B"});
    for (std::size_t p = 0; p < values.size() && p * 3 + 2 < image.pixels.size(); ++p) {
        for (int c = 0; c < 3; ++c) image.pixels[p * 3 + c] = values[p];
    }
    return image;
}

}  // namespace glint
