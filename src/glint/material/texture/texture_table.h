#pragma once
// The textures of a scene, and the reading of material parameters that may be textures.
// A material factory asks the table for its inputs: `table.spectrum(params, "reflectance",
// ...)` accepts a number, {r, g, b} or a texture handle (glint.texture.*).
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>
#include <glint/material/texture/texture_input.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

class MipMapCache;

class TextureTable {
public:
    // Relative texture file names start at `directory`. With `mipmapping` false, image
    // textures are looked up in their full-resolution level only (bilinear), to show what
    // filtering buys.
    TextureTable(std::string directory, bool mipmapping);
    ~TextureTable();
    TextureTable(const TextureTable&) = delete;
    TextureTable& operator=(const TextureTable&) = delete;

    // The scene's declared textures, in the order of their handles.
    void add(std::unique_ptr<Texture> texture) { m_declared.push_back(std::move(texture)); }
    size_t size() const { return m_declared.size(); }

    // A constant (number or {r, g, b}) or a texture handle; texture values are clamped to
    // [lo, hi] where a constant would have been rejected outside it.
    SpectrumInput spectrum(const Params& params, const std::string& name, const Rgb& fallback,
                           float lo, float hi) const;
    FloatInput scalar(const Params& params, const std::string& name, float fallback, float lo,
                      float hi) const;
    // A texture given as a handle, or as a file name (an image read as linear values, as
    // normal and bump maps are stored); nullptr when the parameter is absent.
    const Texture* texture_or_file(const Params& params, const std::string& name);

    // How many texture inputs were handed out so far: a material whose factory raised it
    // uses textures and needs the pixel footprint.
    size_t textures_handed_out() const { return m_handed_out; }

    // The image files' mipmap pyramids, made by the first image texture.
    MipMapCache& mipmaps();
    const std::string& directory() const { return m_directory; }
    bool mipmapping() const { return m_mipmapping; }

private:
    const Texture* declared(const Params& params, const std::string& name) const;

    std::string m_directory;
    bool m_mipmapping;
    std::unique_ptr<MipMapCache> m_mipmaps;
    std::vector<std::unique_ptr<Texture>> m_declared;
    std::vector<std::unique_ptr<Texture>> m_from_files;
    mutable size_t m_handed_out = 0;
};

}  // namespace glint
