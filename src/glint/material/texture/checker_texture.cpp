#include <glint/material/texture/checker_texture.h>
#include <glint/material/texture/mapping.h>
#include <glint/material/texture/pattern_params.h>
#include <glint/material/texture/solid_mapping.h>

namespace glint {
namespace {

bool is_odd_cell(float x) {
    return std::fmod(std::floor(x), 2.0f) != 0.0f;
}

// Integral from 0 to x of the square wave that is 1 on odd cells: each period of 2 adds
// 1, and the second half of a period is the odd cell.
float odd_cells_integral(float x) {
    const float periods = std::floor(0.5f * x);
    const float rest = x - 2.0f * periods;  // in [0, 2)
    return periods + std::max(rest - 1.0f, 0.0f);
}

Rgb mix(const Rgb& a, const Rgb& b, float t) {
    return a * (1.0f - t) + b * t;
}

class Checker2DTexture final : public Texture {
public:
    Checker2DTexture(TextureMapping2D mapping, Rgb even, Rgb odd, bool filtered)
        : m_mapping(mapping), m_even(even), m_odd(odd), m_filtered(filtered) {}

    Rgb eval(const TextureContext& ctx) const override {
        return mix(m_even, m_odd, odd_fraction(ctx));
    }
    float pattern(const TextureContext& ctx) const override { return odd_fraction(ctx); }

private:
    // The box filter over the footprint is separable and the square is odd when exactly
    // one of the two 1D waves is: the mean of a xor b = a + b - 2ab over a product box is
    // A + B - 2AB, with A and B the 1D coverages.
    float odd_fraction(const TextureContext& ctx) const {
        const TexCoord2D tc = m_mapping.map(ctx);
        float half_s = 0.0f, half_t = 0.0f;
        if (m_filtered) {
            half_s = std::max(std::abs(tc.dsdx), std::abs(tc.dsdy));
            half_t = std::max(std::abs(tc.dtdx), std::abs(tc.dtdy));
        }
        const float a = checker_odd_fraction(tc.st.x, half_s);
        const float b = checker_odd_fraction(tc.st.y, half_t);
        return a + b - 2.0f * a * b;
    }

    TextureMapping2D m_mapping;
    Rgb m_even, m_odd;
    bool m_filtered;
};

class Checker3DTexture final : public Texture {
public:
    Checker3DTexture(SolidMapping mapping, Rgb even, Rgb odd)
        : m_mapping(mapping), m_even(even), m_odd(odd) {}

    Rgb eval(const TextureContext& ctx) const override { return is_odd(ctx) ? m_odd : m_even; }
    float pattern(const TextureContext& ctx) const override { return is_odd(ctx) ? 1.0f : 0.0f; }

private:
    bool is_odd(const TextureContext& ctx) const {
        const Vec3 q = m_mapping.map(ctx);
        return is_odd_cell(q.x) != (is_odd_cell(q.y) != is_odd_cell(q.z));
    }

    SolidMapping m_mapping;
    Rgb m_even, m_odd;
};

}  // namespace

float checker_odd_fraction(float x, float half_width) {
    if (!(half_width > 0.0f)) return is_odd_cell(x) ? 1.0f : 0.0f;
    // Shift x by whole periods to near 0 (exactly: the integral gains 1 per period), so
    // the difference below does not cancel away the precision of a small footprint.
    const float local = x - 2.0f * std::floor(0.5f * x);
    return (odd_cells_integral(local + half_width) - odd_cells_integral(local - half_width)) /
           (2.0f * half_width);
}

// glint.texture.checker{...}
//   even       colour of the squares with floor(s) + floor(t) even      default 0.8
//   odd        colour of the others                                     default 0.2
//   dimension  2: squares in (s, t); 3: cubes in object space           default 2
//   2D: mapping, scale (squares per unit of s and t), offset, ... as read_mapping_2d;
//       filter "box" (average over the pixel footprint) or "none"       default "box"
//   3D: transform, scale (cubes per unit) as read_solid_mapping; not filtered.
std::unique_ptr<Texture> make_checker_texture(const Params& params, TextureTable&) {
    const Rgb even = read_colour(params, "even", Rgb(0.8f));
    const Rgb odd = read_colour(params, "odd", Rgb(0.2f));
    const int dimension = params.get_int("dimension", 2);
    if (dimension == 3)
        return std::make_unique<Checker3DTexture>(read_solid_mapping(params), even, odd);
    if (dimension != 2) params.fail("'dimension' must be 2 or 3");

    const std::string filter = params.get_string("filter", "box");
    if (filter != "box" && filter != "none")
        params.fail("'filter' must be \"box\" or \"none\", not \"" + filter + "\"");
    return std::make_unique<Checker2DTexture>(read_mapping_2d(params), even, odd, filter == "box");
}

}  // namespace glint
