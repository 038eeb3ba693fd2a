#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/material/texture/mipmap.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

// Which of the stored channels hold the colour: R, G, B by name, else a grey one.
std::vector<int> colour_channels(const Image& image) {
    const int r = image.channel_index("R"), g = image.channel_index("G"),
              b = image.channel_index("B");
    if (r >= 0 && g >= 0 && b >= 0) return {r, g, b};
    const int y = image.channel_index("Y");
    if (y >= 0) return {y};
    if (image.num_channels() >= 3 && image.channel_index("A") < 0) return {0, 1, 2};
    return {0};
}

// Halves `count` samples along one axis (stride `step` floats between them, `channels`
// interleaved at each) into `count / 2` (at least 1), each the average of the area it
// covers: for an even count two samples, for an odd one three with weights that sum the
// overlapped parts (the output texel spans 2 + 1/m input texels).
void halve_axis(const float* in, float* out, int count, size_t step, int channels) {
    if (count == 1) {
        for (int c = 0; c < channels; ++c) out[c] = in[c];
        return;
    }
    const int half = count / 2;
    for (int i = 0; i < half; ++i) {
        float* o = out + static_cast<size_t>(i) * step;
        const float* a = in + static_cast<size_t>(2 * i) * step;
        if (count % 2 == 0) {
            for (int c = 0; c < channels; ++c) o[c] = 0.5f * (a[c] + a[step + c]);
        } else {
            const float norm = 1.0f / static_cast<float>(2 * half + 1);
            const float w0 = static_cast<float>(half - i) * norm,
                        w1 = static_cast<float>(half) * norm, w2 = static_cast<float>(i + 1) * norm;
            for (int c = 0; c < channels; ++c)
                o[c] = w0 * a[c] + w1 * a[step + c] + w2 * a[2 * step + c];
        }
    }
}

// The next level, a row at a time: each output row from the two (or, for an odd height,
// three) input rows it covers, each input row halved along x first. `row_of(y, out)` writes
// input row y's linear values, so the level above need not be held in floats whole.
template <class RowOf>
std::vector<float> halve(RowOf&& row_of, int width, int height, int channels, int& next_width,
                         int& next_height) {
    next_width = std::max(1, width / 2);
    next_height = std::max(1, height / 2);
    const size_t nc = static_cast<size_t>(channels);
    const size_t out_row = static_cast<size_t>(next_width) * nc;
    std::vector<float> out(out_row * static_cast<size_t>(next_height));
    std::vector<float> input(static_cast<size_t>(width) * nc);
    std::vector<float> halved[3] = {std::vector<float>(out_row), std::vector<float>(out_row),
                                    std::vector<float>(out_row)};
    auto halved_row = [&](int y, std::vector<float>& into) {
        row_of(y, input.data());
        halve_axis(input.data(), into.data(), width, nc, channels);
    };
    const int taps = height == 1 ? 1 : height % 2 == 0 ? 2 : 3;
    for (int j = 0; j < next_height; ++j) {
        // The same weights, and sums in the same order, as halve_axis along y.
        for (int k = 0; k < taps; ++k) halved_row(2 * j + k, halved[k]);
        float* o = out.data() + static_cast<size_t>(j) * out_row;
        const float *a = halved[0].data(), *b = halved[1].data(), *c = halved[2].data();
        if (taps == 1) {
            std::copy(a, a + out_row, o);
        } else if (taps == 2) {
            for (size_t i = 0; i < out_row; ++i) o[i] = 0.5f * (a[i] + b[i]);
        } else {
            const int half = next_height;
            const float norm = 1.0f / static_cast<float>(2 * half + 1);
            const float w0 = static_cast<float>(half - j) * norm,
                        w1 = static_cast<float>(half) * norm, w2 = static_cast<float>(j + 1) * norm;
            for (size_t i = 0; i < out_row; ++i) o[i] = w0 * a[i] + w1 * b[i] + w2 * c[i];
        }
    }
    return out;
}

// Texel index `i` of a level `size` texels wide, wrapped; -1 when outside a black border.
int wrap_index(int i, int size, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::kRepeat: {
            const int m = i % size;
            return m < 0 ? m + size : m;
        }
        case TextureWrap::kClamp:
            return std::clamp(i, 0, size - 1);
        case TextureWrap::kMirror: {
            int m = i % (2 * size);
            if (m < 0) m += 2 * size;
            return m < size ? m : 2 * size - 1 - m;
        }
        case TextureWrap::kBlack:
            return i >= 0 && i < size ? i : -1;
    }
    return -1;
}

// A texture coordinate moved by whole periods of the wrap (which changes no lookup), so
// that texel indices stay small whatever the coordinate.
float reduce_coordinate(float s, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::kRepeat:
            return s - std::floor(s);
        case TextureWrap::kMirror:
            return s - 2.0f * std::floor(0.5f * s);
        case TextureWrap::kClamp:
        case TextureWrap::kBlack:
            return std::clamp(s, -1.0f, 2.0f);
    }
    return s;
}

}  // namespace

MipMap::MipMap(StoredImage stored, bool srgb, const std::string& name) : m_srgb(srgb) {
    Image& image = stored.image;
    const std::vector<int> source = colour_channels(image);
    m_channels = static_cast<int>(source.size());
    m_bytes = stored.integer && stored.bits_per_value == 8;
    const size_t width = static_cast<size_t>(image.width),
                 height = static_cast<size_t>(image.height);
    const size_t nc = static_cast<size_t>(m_channels), stored_nc = image.channels.size();
    // The pyramid (4/3 of the image) and, while it is built, the second level in floats.
    const uint64_t values = static_cast<uint64_t>(width) * height * nc;
    check_memory(
        saturating_product(values, (m_bytes ? 1 : sizeof(float)) * 4 / 3 + 2),
        fmt::format("texture '{}' ({}x{}) with its mipmaps", name, image.width, image.height));
    for (int code = 0; code < 256; ++code) {
        const float value = static_cast<float>(code) / 255.0f;
        m_decode[static_cast<size_t>(code)] = srgb ? srgb_to_linear(value) : value;
    }

    // The full-resolution level as stored: the file's codes, or floats (decoded if sRGB).
    Level top;
    top.width = image.width;
    top.height = image.height;
    // Taken over whole when the file holds just the colour channels, in order.
    bool as_stored = stored_nc == nc;
    for (size_t c = 0; c < nc; ++c) as_stored = as_stored && source[c] == static_cast<int>(c);
    if (m_bytes && as_stored && !stored.codes.empty()) {
        top.codes = std::move(stored.codes);
    } else if (!m_bytes && as_stored && !srgb) {
        top.values = std::move(image.pixels);
    } else if (m_bytes) {
        top.codes.resize(width * height * nc);
        for (size_t p = 0; p < width * height; ++p) {
            for (size_t c = 0; c < nc; ++c) {
                const size_t from = p * stored_nc + static_cast<size_t>(source[c]);
                top.codes[p * nc + c] =
                    stored.codes.empty() ? static_cast<uint8_t>(std::lround(
                                               std::clamp(image.pixels[from], 0.0f, 1.0f) * 255.0f))
                                         : stored.codes[from];
            }
        }
    } else {
        top.values.resize(width * height * nc);
        for (size_t p = 0; p < width * height; ++p) {
            for (size_t c = 0; c < nc; ++c) {
                const float v = image.pixels[p * stored_nc + static_cast<size_t>(source[c])];
                top.values[p * nc + c] = srgb ? srgb_to_linear(v) : v;
            }
        }
    }
    m_levels.push_back(std::move(top));

    // Each level from the linear values of the one above: the top level's decoded a row at
    // a time, the others' kept in floats until the next is made.
    std::vector<float> linear;
    int w = image.width, h = image.height;
    while (w > 1 || h > 1) {
        int next_w = 0, next_h = 0;
        const Level& above = m_levels.back();
        const size_t row = static_cast<size_t>(w) * nc;
        std::vector<float> next;
        if (m_levels.size() == 1) {
            next = halve(
                [&](int y, float* out) {
                    const size_t at = static_cast<size_t>(y) * row;
                    for (size_t i = 0; i < row; ++i)
                        out[i] = m_bytes ? m_decode[above.codes[at + i]] : above.values[at + i];
                },
                w, h, m_channels, next_w, next_h);
        } else {
            next = halve(
                [&](int y, float* out) {
                    std::copy_n(linear.data() + static_cast<size_t>(y) * row, row, out);
                },
                w, h, m_channels, next_w, next_h);
        }
        linear = std::move(next);
        w = next_w;
        h = next_h;
        m_levels.push_back(encoded(w, h, linear));
    }
}

// A level's storage from linear values: 8-bit codes (through the inverse of the decode
// table) or the floats themselves.
MipMap::Level MipMap::encoded(int width, int height, const std::vector<float>& values) const {
    Level level;
    level.width = width;
    level.height = height;
    if (!m_bytes) {
        level.values = values;
        return level;
    }
    level.codes.resize(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const double v = std::clamp(static_cast<double>(values[i]), 0.0, 1.0);
        const double encoded_value = m_srgb ? linear_to_srgb(v) : v;
        level.codes[i] = static_cast<uint8_t>(std::lround(encoded_value * 255.0));
    }
    return level;
}

Rgb MipMap::texel(const Level& level, int x, int y, TextureWrap wrap) const {
    const int ix = wrap_index(x, level.width, wrap), iy = wrap_index(y, level.height, wrap);
    if (ix < 0 || iy < 0) return Rgb(0.0f);
    const size_t at =
        (static_cast<size_t>(iy) * static_cast<size_t>(level.width) + static_cast<size_t>(ix)) *
        static_cast<size_t>(m_channels);
    if (m_bytes) {
        if (m_channels == 1) return Rgb(m_decode[level.codes[at]]);
        return Rgb(m_decode[level.codes[at]], m_decode[level.codes[at + 1]],
                   m_decode[level.codes[at + 2]]);
    }
    if (m_channels == 1) return Rgb(level.values[at]);
    return Rgb(level.values[at], level.values[at + 1], level.values[at + 2]);
}

Rgb MipMap::bilinear(int index, Vec2 st, TextureWrap wrap) const {
    const Level& level = m_levels[static_cast<size_t>(index)];
    // Texel i covers [i, i + 1) / size; its centre is at (i + 0.5) / size.
    const float x = reduce_coordinate(st.x, wrap) * static_cast<float>(level.width) - 0.5f;
    const float y = reduce_coordinate(st.y, wrap) * static_cast<float>(level.height) - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
    const float dx = x - fx0, dy = y - fy0;
    return (1.0f - dx) * (1.0f - dy) * texel(level, x0, y0, wrap) +
           dx * (1.0f - dy) * texel(level, x0 + 1, y0, wrap) +
           (1.0f - dx) * dy * texel(level, x0, y0 + 1, wrap) +
           dx * dy * texel(level, x0 + 1, y0 + 1, wrap);
}

Rgb MipMap::trilinear(float level, Vec2 st, TextureWrap wrap) const {
    const float last = static_cast<float>(levels() - 1);
    if (!(level > 0.0f)) return bilinear(0, st, wrap);
    if (level >= last) return bilinear(levels() - 1, st, wrap);
    const float lower = std::floor(level);
    const float t = level - lower;
    const int i = static_cast<int>(lower);
    return (1.0f - t) * bilinear(i, st, wrap) + t * bilinear(i + 1, st, wrap);
}

Rgb MipMap::lookup(Vec2 st, Vec2 dst_dx, Vec2 dst_dy, TextureFilter filter,
                   TextureWrap wrap) const {
    if (!std::isfinite(st.x) || !std::isfinite(st.y)) return Rgb(0.0f);
    if (filter == TextureFilter::kBilinear) return bilinear(0, st, wrap);
    // The footprint's two sides in texels of the full-resolution level.
    const Vec2 size(static_cast<float>(width()), static_cast<float>(height()));
    const float len_x = glm::length(dst_dx * size), len_y = glm::length(dst_dy * size);
    if (!std::isfinite(len_x) || !std::isfinite(len_y)) return bilinear(0, st, wrap);
    if (filter == TextureFilter::kTrilinear)
        return trilinear(std::log2(std::max(std::max(len_x, len_y), 1e-8f)), st, wrap);

    const bool x_longer = len_x >= len_y;
    const Vec2 major = x_longer ? dst_dx : dst_dy;
    const float major_length = std::max(len_x, len_y);
    const float minor_length =
        std::max(std::min(len_x, len_y), major_length / static_cast<float>(kMaxAnisotropy));
    // Probes no farther apart than a texel of the level read (at least a full-resolution one).
    const float spacing = std::max(minor_length, 1.0f);
    const int probes =
        std::clamp(static_cast<int>(std::ceil(major_length / spacing)), 1, kMaxAnisotropy);
    const float level = std::log2(std::max(minor_length, 1e-8f));
    if (probes == 1) return trilinear(level, st, wrap);
    Rgb sum(0.0f);
    for (int i = 0; i < probes; ++i) {
        const float offset = (static_cast<float>(i) + 0.5f) / static_cast<float>(probes) - 0.5f;
        sum += trilinear(level, st + offset * major, wrap);
    }
    return sum / static_cast<float>(probes);
}

}  // namespace glint
