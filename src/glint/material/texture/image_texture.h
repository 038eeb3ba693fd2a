#pragma once
// Image textures through OpenImageIO's TextureSystem: mipmaps are built on first use
// (automip), lookups are trilinear or anisotropic, sized by the pixel footprint the ray
// differentials give, with repeat / clamp / mirror wrapping.
#include <glint/core/params.h>
#include <glint/material/texture/mapping.h>
#include <glint/material/texture/texture.h>

#include <memory>
#include <string>

namespace glint {

class TextureTable;

// Owns OpenImageIO's texture system for one scene; thread-safe.
class ImageTextureSystem {
public:
    ImageTextureSystem();
    ~ImageTextureSystem();
    ImageTextureSystem(const ImageTextureSystem&) = delete;
    ImageTextureSystem& operator=(const ImageTextureSystem&) = delete;

    void* system() const { return m_system; }  // OIIO::TextureSystem*

private:
    void* m_system;
};

enum class TextureEncoding { kAuto, kSrgb, kLinear };

struct ImageTextureOptions {
    std::string wrap = "repeat";         // repeat, clamp, mirror, black
    std::string filter = "anisotropic";  // anisotropic, trilinear, none (bilinear, no mipmap)
    TextureEncoding encoding = TextureEncoding::kAuto;  // auto: 8-bit files are sRGB
};

// Opens `path` (checking it exists and is readable) and returns the texture; throws
// glint::Error naming the file otherwise.
std::unique_ptr<Texture> load_image_texture(const std::string& path,
                                            const ImageTextureOptions& options,
                                            const TextureMapping2D& mapping, TextureTable& table);

// glint.texture.image{file = ..., wrap, filter, encoding, mapping, scale, offset, ...}.
std::unique_ptr<Texture> make_image_texture(const Params& params, TextureTable& table);

}  // namespace glint
