#pragma once
// An image texture's pyramid: the image and its halvings down to one texel, each averaged
// from the one above in linear values (a box filter, exact for odd sizes too), with
// bilinear, trilinear and anisotropic lookups sized by a pixel's footprint.
//
// 8-bit images keep their code values, a byte a channel as in the file, and decode them
// through a table on each fetch (sRGB or linear), so that filtering happens in linear
// values at a quarter of a float image's memory; 16-bit and float images are kept as float.
// Read-only once built, so lookups from many threads need no lock.
#include <glint/core/rgb.h>
#include <glint/film/image_io.h>
#include <glint/math/vector.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glint {

enum class TextureWrap { kRepeat, kClamp, kMirror, kBlack };

enum class TextureFilter {
    kBilinear,     // the full-resolution image only: no prefiltering
    kTrilinear,    // one level by the footprint's larger side: blurs along its shorter one
    kAnisotropic,  // a level by the footprint's shorter side, probed along its longer one
};

class MipMap {
public:
    /// The colour channels of `stored` (R, G, B by name; else Y or the first channel as
    /// grey; alpha dropped); `srgb` decodes them from sRGB. Throws glint::Error naming
    /// `name` when the pyramid would not fit the memory budget.
    MipMap(StoredImage stored, bool srgb, const std::string& name);

    /// The filtered value at (s, t), t = 0 at the image's top row, with the pixel's
    /// footprint given by the derivatives of (s, t) along the image's x and y.
    Rgb lookup(Vec2 st, Vec2 dst_dx, Vec2 dst_dy, TextureFilter filter, TextureWrap wrap) const;

    int levels() const { return static_cast<int>(m_levels.size()); }
    int width() const { return m_levels.front().width; }
    int height() const { return m_levels.front().height; }
    int channels() const { return m_channels; }

    /// Most texels an anisotropic lookup averages along the footprint's longer side.
    static constexpr int kMaxAnisotropy = 16;

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<uint8_t> codes;  // 8-bit images
        std::vector<float> values;   // the others
    };

    Level encoded(int width, int height, const std::vector<float>& values) const;
    Rgb texel(const Level& level, int x, int y, TextureWrap wrap) const;
    Rgb bilinear(int level, Vec2 st, TextureWrap wrap) const;
    Rgb trilinear(float level, Vec2 st, TextureWrap wrap) const;

    std::vector<Level> m_levels;
    int m_channels = 3;  // 1 or 3
    bool m_bytes = false;
    bool m_srgb = false;
    std::array<float, 256> m_decode{};  // code -> linear value, for 8-bit images
};

}  // namespace glint
