#pragma once
// A plain multichannel float image: what the film resolves to and what image I/O reads
// and writes. Channel names follow OpenEXR layer naming ("R", "albedo.R", "depth.Z").
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace glint {

struct Image {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    /// Interleaved channels, row-major, top row first: (y * width + x) * channels + c.
    std::vector<float> pixels;
    /// Text attributes (name, value) kept in an EXR file's header as "glint:<name>", e.g.
    /// a partial render's sample range; other formats drop them.
    std::vector<std::pair<std::string, std::string>> attributes;

    int num_channels() const { return static_cast<int>(channels.size()); }
    std::size_t index(int x, int y, int c) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)) *
                   channels.size() +
               static_cast<std::size_t>(c);
    }
    float& at(int x, int y, int c) { return pixels[index(x, y, c)]; }
    float at(int x, int y, int c) const { return pixels[index(x, y, c)]; }
    /// Position of the channel called `name`, or -1 if the image has none.
    int channel_index(const std::string& name) const;
    /// The value of attribute `name`, or null if the image has none.
    const std::string* attribute(const std::string& name) const;
};

/// A zero-filled image; throws glint::Error for negative sizes or no channels.
Image make_image(int width, int height, std::vector<std::string> channels);

// A copy of `image` with one more channel; `values` holds width * height floats.
Image with_channel(const Image& image, const std::string& name, const std::vector<float>& values);

// A copy of `image` without the channels whose names start with one of `prefixes`
// (e.g. {"albedo.", "normal.", "depth."} drops the AOVs).
Image without_channels(const Image& image, const std::vector<std::string>& prefixes);

// A single-channel image of `values` replicated into R, G, B (for writing masks as PNG).
Image grey_image(int width, int height, const std::vector<float>& values);

}  // namespace glint
