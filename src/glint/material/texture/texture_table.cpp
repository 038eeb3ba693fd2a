#include <glint/core/error.h>
#include <glint/material/texture/image_texture.h>
#include <glint/material/texture/texture_table.h>

#include <fmt/format.h>

#include <filesystem>

namespace glint {

TextureTable::TextureTable(std::string directory, bool mipmapping)
    : m_directory(std::move(directory)), m_mipmapping(mipmapping) {}

MipMapCache& TextureTable::mipmaps() {
    if (!m_mipmaps) m_mipmaps = std::make_unique<MipMapCache>();
    return *m_mipmaps;
}

TextureTable::~TextureTable() = default;  // here, where MipMapCache is complete

const Texture* TextureTable::declared(const Params& params, const std::string& name) const {
    if (!params.is_ref(name, "texture")) return nullptr;
    const ObjectRef ref = params.get_ref(name, "texture");
    if (ref.index < 0 || static_cast<size_t>(ref.index) >= m_declared.size())
        params.fail(fmt::format("'{}' names a texture that does not exist", name));
    ++m_handed_out;
    return m_declared[ref.index].get();
}

SpectrumInput TextureTable::spectrum(const Params& params, const std::string& name,
                                     const Rgb& fallback, float lo, float hi) const {
    if (const Texture* texture = declared(params, name)) return SpectrumInput(texture, lo, hi);
    if (params.has(name) && !params.is_number_or_numbers(name)) {
        params.fail(
            fmt::format("'{}' must be a colour (a number or {{r, g, b}}) or a texture "
                        "(glint.texture.*)",
                        name));
    }
    const Rgb value = params.get_rgb(name, fallback);
    if (value.min_value() < lo || value.max_value() > hi) {
        params.fail(fmt::format("'{}' must lie in [{}, {}]", name, lo, hi));
    }
    return SpectrumInput(value, hi);
}

FloatInput TextureTable::scalar(const Params& params, const std::string& name, float fallback,
                                float lo, float hi) const {
    if (const Texture* texture = declared(params, name)) return FloatInput(texture, lo, hi);
    if (params.has(name) && !params.is_number_or_numbers(name))
        params.fail(fmt::format("'{}' must be a number or a texture (glint.texture.*)", name));
    const float value = params.get_float(name, fallback);
    if (!(value >= lo && value <= hi))
        params.fail(fmt::format("'{}' must lie in [{}, {}]", name, lo, hi));
    return FloatInput(value);
}

const Texture* TextureTable::texture_or_file(const Params& params, const std::string& name) {
    if (!params.has(name)) return nullptr;
    if (const Texture* texture = declared(params, name)) return texture;
    if (!params.is_string(name)) {
        params.fail(fmt::format(
            "'{}' must be a texture (glint.texture.*) or the file name of an image", name));
    }
    std::filesystem::path path = params.get_string(name);
    if (path.is_relative()) path = std::filesystem::path(m_directory) / path;
    ImageTextureOptions options;
    options.encoding = TextureEncoding::kLinear;
    try {
        m_from_files.push_back(
            load_image_texture(path.string(), options, TextureMapping2D(), *this));
    } catch (const Error& e) {
        params.fail(e.what());
    }
    ++m_handed_out;
    return m_from_files.back().get();
}

}  // namespace glint
