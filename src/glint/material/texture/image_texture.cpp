#include <glint/core/error.h>
#include <glint/film/image_io.h>
#include <glint/material/texture/image_texture.h>
#include <glint/material/texture/mipmap.h>
#include <glint/material/texture/texture_table.h>

#include <fmt/format.h>

#include <filesystem>

namespace glint {
namespace {

class ImageTexture final : public Texture {
public:
    ImageTexture(std::shared_ptr<const MipMap> mipmap, TextureFilter filter, TextureWrap wrap,
                 TextureMapping2D mapping)
        : m_mipmap(std::move(mipmap)), m_filter(filter), m_wrap(wrap), m_mapping(mapping) {}

    Rgb eval(const TextureContext& ctx) const override {
        const TexCoord2D tc = m_mapping.map(ctx);
        // The pyramid puts t = 0 at the top row, as files store them; uv has v = 0 at the
        // bottom.
        return m_mipmap->lookup(Vec2(tc.st.x, 1.0f - tc.st.y), Vec2(tc.dsdx, -tc.dtdx),
                                Vec2(tc.dsdy, -tc.dtdy), m_filter, m_wrap);
    }

private:
    std::shared_ptr<const MipMap> m_mipmap;
    TextureFilter m_filter;
    TextureWrap m_wrap;
    TextureMapping2D m_mapping;
};

TextureWrap parse_wrap(const std::string& wrap) {
    if (wrap == "repeat") return TextureWrap::kRepeat;
    if (wrap == "clamp") return TextureWrap::kClamp;
    if (wrap == "mirror") return TextureWrap::kMirror;
    if (wrap == "black") return TextureWrap::kBlack;
    throw Error(fmt::format(
        "'wrap' must be \"repeat\", \"clamp\", \"mirror\" or \"black\", not \"{}\"", wrap));
}

TextureFilter parse_filter(const std::string& filter, bool mipmapping) {
    if (filter != "anisotropic" && filter != "trilinear" && filter != "none") {
        throw Error(fmt::format(
            "'filter' must be \"anisotropic\", \"trilinear\" or \"none\", not \"{}\"", filter));
    }
    if (!mipmapping || filter == "none") return TextureFilter::kBilinear;
    return filter == "anisotropic" ? TextureFilter::kAnisotropic : TextureFilter::kTrilinear;
}

}  // namespace

MipMapCache::MipMapCache() = default;
MipMapCache::~MipMapCache() = default;

std::shared_ptr<const MipMap> MipMapCache::get(const std::string& path, TextureEncoding encoding) {
    const std::lock_guard<std::mutex> lock(m_mutex);
    auto& slot = m_built[{path, encoding}];
    if (slot) return slot;
    if (!std::filesystem::is_regular_file(path))
        throw Error(fmt::format("texture file '{}' does not exist", path));
    // The whole file is decoded now, so that a lying header or a truncated file is an
    // error here rather than black texels in the middle of the render.
    StoredImage stored = read_stored_image(path, /*eight_bit_codes=*/true);
    const bool srgb = encoding == TextureEncoding::kSrgb ||
                      (encoding == TextureEncoding::kAuto && stored.integer);
    slot = std::make_shared<const MipMap>(std::move(stored), srgb, path);
    return slot;
}

std::unique_ptr<Texture> load_image_texture(const std::string& path,
                                            const ImageTextureOptions& options,
                                            const TextureMapping2D& mapping, TextureTable& table) {
    const TextureWrap wrap = parse_wrap(options.wrap);
    const TextureFilter filter = parse_filter(options.filter, table.mipmapping());
    return std::make_unique<ImageTexture>(table.mipmaps().get(path, options.encoding), filter, wrap,
                                          mapping);
}

std::unique_ptr<Texture> make_image_texture(const Params& params, TextureTable& table) {
    std::filesystem::path path = params.get_string("file");
    if (path.is_relative()) path = std::filesystem::path(table.directory()) / path;
    ImageTextureOptions options;
    options.wrap = params.get_string("wrap", options.wrap);
    options.filter = params.get_string("filter", options.filter);
    if (!params.get_bool("mipmap", true)) options.filter = "none";
    const std::string encoding = params.get_string("encoding", "auto");
    if (encoding == "srgb")
        options.encoding = TextureEncoding::kSrgb;
    else if (encoding == "linear")
        options.encoding = TextureEncoding::kLinear;
    else if (encoding != "auto")
        params.fail("'encoding' must be \"auto\", \"srgb\" or \"linear\"");
    const TextureMapping2D mapping = read_mapping_2d(params);
    try {
        return load_image_texture(path.string(), options, mapping, table);
    } catch (const Error& e) {
        params.fail(e.what());
    }
}

}  // namespace glint
