#pragma once
// Image textures: a file's mipmap pyramid (mipmap.h), looked up bilinearly, trilinearly or
// anisotropically by the pixel footprint the ray differentials give, with repeat / clamp /
// mirror / black wrapping.
#include <glint/core/params.h>
#include <glint/material/texture/mapping.h>
#include <glint/material/texture/texture.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

namespace glint {

class MipMap;
class TextureTable;

enum class TextureEncoding { kAuto, kSrgb, kLinear };

struct ImageTextureOptions {
    std::string wrap = "repeat";         // repeat, clamp, mirror, black
    std::string filter = "anisotropic";  // anisotropic, trilinear, none (bilinear, no mipmap)
    TextureEncoding encoding = TextureEncoding::kAuto;  // auto: integer files are sRGB
};

// The pyramids of a scene's image files, each built once however many textures use it.
class MipMapCache {
public:
    MipMapCache();
    ~MipMapCache();
    MipMapCache(const MipMapCache&) = delete;
    MipMapCache& operator=(const MipMapCache&) = delete;

    // Reads `path` (throwing glint::Error naming it when it cannot) and builds its pyramid,
    // or returns the one built before for the same file and encoding.
    std::shared_ptr<const MipMap> get(const std::string& path, TextureEncoding encoding);

private:
    std::mutex m_mutex;
    std::map<std::pair<std::string, TextureEncoding>, std::shared_ptr<const MipMap>> m_built;
};

// Opens `path` (checking it exists and is readable) and returns the texture; throws
// glint::Error naming the file otherwise.
std::unique_ptr<Texture> load_image_texture(const std::string& path,
                                            const ImageTextureOptions& options,
                                            const TextureMapping2D& mapping, TextureTable& table);

// glint.texture.image{file = ..., wrap, filter, encoding, mapping, scale, offset, ...}.
std::unique_ptr<Texture> make_image_texture(const Params& params, TextureTable& table);

}  // namespace glint
