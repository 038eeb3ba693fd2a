#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/material/texture/image_texture.h>
#include <glint/material/texture/texture_table.h>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>
#include <fmt/format.h>

#include <filesystem>
#include <system_error>
#include <vector>

namespace glint {
namespace {

OIIO::TextureSystem* oiio(const ImageTextureSystem& images) {
    return static_cast<OIIO::TextureSystem*>(images.system());
}

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

class ImageTexture final : public Texture {
public:
    ImageTexture(OIIO::TextureSystem* system, OIIO::TextureSystem::TextureHandle* handle,
                 OIIO::TextureOpt options, int channels, bool srgb, TextureMapping2D mapping)
        : m_system(system),
          m_handle(handle),
          m_options(options),
          m_channels(channels),
          m_srgb(srgb),
          m_mapping(mapping) {}

    Rgb eval(const TextureContext& ctx) const override {
        const TexCoord2D tc = m_mapping.map(ctx);
        // OpenImageIO puts t = 0 at the top row; uv has v = 0 at the bottom.
        float result[3] = {0.0f, 0.0f, 0.0f};
        OIIO::TextureOpt options = m_options;  // the lookup may write into it
        m_system->texture(m_handle, nullptr, options, tc.st.x, 1.0f - tc.st.y, tc.dsdx, -tc.dtdx,
                          tc.dsdy, -tc.dtdy, std::min(m_channels, 3), result);
        Rgb value = m_channels >= 3 ? Rgb(result[0], result[1], result[2]) : Rgb(result[0]);
        if (m_srgb) {
            value = {srgb_to_linear(value.r), srgb_to_linear(value.g), srgb_to_linear(value.b)};
        }
        return value;
    }

private:
    OIIO::TextureSystem* m_system;
    OIIO::TextureSystem::TextureHandle* m_handle;
    OIIO::TextureOpt m_options;
    int m_channels;
    bool m_srgb;
    TextureMapping2D m_mapping;
};

OIIO::TextureOpt::Wrap parse_wrap(const std::string& wrap) {
    if (wrap == "repeat") return OIIO::TextureOpt::WrapPeriodic;
    if (wrap == "clamp") return OIIO::TextureOpt::WrapClamp;
    if (wrap == "mirror") return OIIO::TextureOpt::WrapMirror;
    if (wrap == "black") return OIIO::TextureOpt::WrapBlack;
    throw Error(fmt::format(
        "'wrap' must be \"repeat\", \"clamp\", \"mirror\" or \"black\", not \"{}\"", wrap));
}

}  // namespace

ImageTextureSystem::ImageTextureSystem() {
    OIIO::TextureSystem* system = OIIO::TextureSystem::create(/*shared=*/false);
    // Build mipmaps for plain images on first use, and cache them in tiles.
    system->attribute("automip", 1);
    system->attribute("autotile", 64);
    system->attribute("max_memory_MB", 1024.0f);
    m_system = system;
}

ImageTextureSystem::~ImageTextureSystem() {
    OIIO::TextureSystem::destroy(static_cast<OIIO::TextureSystem*>(m_system));
}

std::unique_ptr<Texture> load_image_texture(const std::string& path,
                                            const ImageTextureOptions& options,
                                            const TextureMapping2D& mapping, TextureTable& table) {
    if (!std::filesystem::is_regular_file(path))
        throw Error(fmt::format("texture file '{}' does not exist", path));
    std::error_code ec;
    const uintmax_t file_bytes = std::filesystem::file_size(path, ec);
    if (ec) throw Error(fmt::format("cannot read texture file '{}': {}", path, ec.message()));
    auto input = OIIO::ImageInput::open(path);
    if (!input) {
        throw Error(fmt::format("cannot read texture file '{}': {}", path, OIIO::geterror()));
    }
    const OIIO::ImageSpec spec = input->spec();
    // The header is checked before anything is allocated for it, and the image decoded in
    // full once, here: the texture system decodes lazily, tile by tile, and would turn a
    // lying header or a truncated file into failed lookups (black, and libpng's complaints
    // on stderr) in the middle of the render instead of an error now.
    check_image_header(path, spec.width, spec.height, spec.nchannels, spec.format.size(),
                       file_bytes);
    {
        std::vector<unsigned char> pixels(spec.image_bytes(/*native=*/true));
        if (!input->read_image(0, 0, 0, spec.nchannels, spec.format, pixels.data())) {
            throw Error(fmt::format("texture file '{}' is damaged or truncated: {}", path,
                                    input->geterror()));
        }
    }
    input->close();

    OIIO::TextureOpt opt;
    opt.swrap = opt.twrap = parse_wrap(options.wrap);
    if (options.filter == "anisotropic" && table.mipmapping()) {
        opt.mipmode = OIIO::TextureOpt::MipModeAniso;
        opt.anisotropic = 16;
    } else if (options.filter == "trilinear" && table.mipmapping()) {
        opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    } else if (options.filter == "none" || !table.mipmapping()) {
        opt.mipmode = OIIO::TextureOpt::MipModeNoMIP;
    } else {
        throw Error(
            fmt::format("'filter' must be \"anisotropic\", \"trilinear\" or \"none\", not \"{}\"",
                        options.filter));
    }
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;

    const bool eight_bit = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                           spec.format.basetype == OIIO::TypeDesc::INT8;
    const bool srgb = options.encoding == TextureEncoding::kSrgb ||
                      (options.encoding == TextureEncoding::kAuto && eight_bit);
    OIIO::TextureSystem* system = oiio(table.images());
    OIIO::TextureSystem::TextureHandle* handle = system->get_texture_handle(OIIO::ustring(path));
    if (!handle) {
        throw Error(fmt::format("cannot open texture file '{}': {}", path, system->geterror()));
    }
    const int channels = spec.nchannels == 2 ? 1 : spec.nchannels;  // grey + alpha: grey
    return std::make_unique<ImageTexture>(system, handle, opt, channels, srgb, mapping);
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
