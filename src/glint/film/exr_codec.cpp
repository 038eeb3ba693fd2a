// OpenEXR files through the OpenEXR library (image_codecs.h). The only file that uses it.
#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/film/image_codecs.h>

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>
#include <half.h>

#include <exception>
#include <vector>

namespace glint {

StoredImage read_exr(const std::string& path, uint64_t file_bytes) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const int64_t width = int64_t{window.max.x} - window.min.x + 1;
        const int64_t height = int64_t{window.max.y} - window.min.y + 1;
        int64_t channel_count = 0;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
                throw Error(fmt::format("channel '{}' is subsampled, which glint does not read",
                                        it.name()));
            }
            ++channel_count;
        }
        check_image_header(path, width, height, channel_count, sizeof(float), file_bytes);
        if (!file.isComplete()) throw Error("the file ends early: its pixel data is incomplete");

        StoredImage stored;
        Image& image = stored.image;
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
            image.channels.emplace_back(it.name());
        image.pixels.resize(image.index(0, image.height, 0));
        const size_t pixel_stride = sizeof(float) * image.channels.size();
        const size_t row_stride = pixel_stride * static_cast<size_t>(width);
        Imf::FrameBuffer frame;
        for (size_t c = 0; c < image.channels.size(); ++c) {
            // Slice::Make offsets the base so that the data window's corner lands on it.
            frame.insert(image.channels[c], Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c,
                                                             window, pixel_stride, row_stride));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);

        for (auto it = header.begin(); it != header.end(); ++it) {
            const std::string name = it.name();
            const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute());
            if (text && name.rfind("glint:", 0) == 0)
                image.attributes.emplace_back(name.substr(6), text->value());
        }
        stored.bits_per_value = 32;
        stored.alpha = image.channel_index("A");
        return stored;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        // OpenEXR's exceptions (Iex) read "Cannot read ...: <reason>"; the caller adds the path.
        throw Error(e.what());
    }
}

void write_exr(const std::string& path, const Image& image, bool half) {
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        const Imf::PixelType stored = half ? Imf::HALF : Imf::FLOAT;
        for (const std::string& name : image.channels)
            header.channels().insert(name, Imf::Channel(stored));
        for (const auto& [name, value] : image.attributes)
            header.insert("glint:" + name, Imf::StringAttribute(value));

        // OpenEXR converts between a file's and a frame buffer's pixel types when reading
        // but not when writing: half files are written from a half copy.
        std::vector<Imath::half> halves;
        if (half) halves.assign(image.pixels.begin(), image.pixels.end());
        const size_t value_size = half ? sizeof(Imath::half) : sizeof(float);
        const size_t pixel_stride = value_size * image.channels.size();
        const size_t row_stride = pixel_stride * static_cast<size_t>(image.width);
        Imf::FrameBuffer frame;
        for (size_t c = 0; c < image.channels.size(); ++c) {
            // OpenEXR takes a non-const pointer, but only reads through it when writing.
            char* base = half
                             ? reinterpret_cast<char*>(halves.data() + c)
                             : reinterpret_cast<char*>(const_cast<float*>(image.pixels.data() + c));
            frame.insert(image.channels[c], Imf::Slice(stored, base, pixel_stride, row_stride));
        }
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        throw Error(e.what());
    }
}

}  // namespace glint
