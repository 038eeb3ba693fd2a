#include <glint/core/error.h>
#include <glint/denoise/svgf.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace glint {
namespace {

constexpr float kAlbedoFloor = 1e-3f;
// The à-trous kernels' weights by |offset|: the B3 spline (5x5, as the paper) and its 3x3
// counterpart (as A-SVGF, Schied et al. 2018, for speed).
constexpr float kKernel5[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
constexpr float kKernel3[2] = {1.0f / 2.0f, 1.0f / 4.0f};

template <typename Body>
void for_rows(int height, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) body(y);
    });
}

// exp(-x) for x >= 0 to about 1e-5 relative: 2^-t as an exponent in the float's bits times
// a polynomial for the fraction. The filter's weights need no more, and std::exp is most of
// an à-trous tap's time.
float exp_negative(float x) {
    const float t = std::min(x * 1.44269504f, 126.0f);  // -x in powers of two, clamped
    const float n = std::floor(t);
    const float f = n - t;  // in (-1, 0]
    // 2^f on (-1, 0], a degree-5 fit.
    const float p =
        1.0f +
        f * (0.693147182f +
             f * (0.240226507f + f * (0.0555041087f + f * (0.00961812911f + f * 0.00133335581f))));
    const int exponent = 127 - static_cast<int>(n);
    uint32_t bits = static_cast<uint32_t>(exponent) << 23;
    float scale;
    std::memcpy(&scale, &bits, sizeof scale);
    return p * scale;
}

// max(0, c)^power for the integer powers of two the normal test uses, by squaring.
float normal_weight(float cosine, float power) {
    float w = std::max(0.0f, cosine);
    if (power == 128.0f) {
        for (int i = 0; i < 7; ++i) w *= w;
        return w;
    }
    return std::pow(w, power);
}

// The per-pixel state the passes share.
struct Planes {
    int width, height;
    std::vector<Rgb> illumination;
    std::vector<float> variance, luminance;
    std::vector<float> depth_gradient;  // max |dz| to a 4-neighbour that lies on the surface
    const SvgfInput* input;

    std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
    bool surface(std::size_t i) const { return input->depth[i] > 0.0f; }
};

float depth_weight(const Planes& p, std::size_t i, std::size_t j, float distance,
                   const SvgfSettings& s) {
    const float zi = p.input->depth[i];
    const float scale = s.sigma_depth * p.depth_gradient[i] * distance + 1e-3f * zi;
    return std::exp(-std::abs(zi - p.input->depth[j]) / scale);
}

void estimate_depth_gradient(Planes& p) {
    p.depth_gradient.assign(p.illumination.size(), 0.0f);
    for_rows(p.height, [&](int y) {
        for (int x = 0; x < p.width; ++x) {
            const std::size_t i = p.at(x, y);
            if (!p.surface(i)) continue;
            // The smaller one-sided difference on each axis: a depth edge beside the pixel does
            // not count as its surface's slope.
            auto slope = [&](int dx, int dy) {
                float best = INFINITY;
                for (int sign : {-1, 1}) {
                    const int nx = x + sign * dx, ny = y + sign * dy;
                    if (nx < 0 || ny < 0 || nx >= p.width || ny >= p.height) continue;
                    const std::size_t j = p.at(nx, ny);
                    if (p.surface(j))
                        best = std::min(best, std::abs(p.input->depth[j] - p.input->depth[i]));
                }
                return std::isfinite(best) ? best : 0.0f;
            };
            p.depth_gradient[i] = std::max(slope(1, 0), slope(0, 1));
        }
    });
}

// Temporal variance where the history is long enough, else a spatial estimate from the
// moments of a 7x7 neighbourhood on the same surface, raised for short histories.
void estimate_variance(Planes& p, const SvgfSettings& s) {
    const SvgfInput& in = *p.input;
    p.variance.assign(p.illumination.size(), 0.0f);
    for_rows(p.height, [&](int y) {
        for (int x = 0; x < p.width; ++x) {
            const std::size_t i = p.at(x, y);
            if (!p.surface(i)) continue;
            const float h = in.history_length[i];
            if (h >= s.min_temporal_history) {
                p.variance[i] = std::max(0.0f, in.moments[i].y - in.moments[i].x * in.moments[i].x);
                continue;
            }
            float sum_w = 0.0f;
            Vec2 sum_m(0.0f);
            for (int dy = -3; dy <= 3; ++dy) {
                for (int dx = -3; dx <= 3; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= p.width || ny >= p.height) continue;
                    const std::size_t j = p.at(nx, ny);
                    if (!p.surface(j)) continue;
                    const float distance = std::sqrt(static_cast<float>(dx * dx + dy * dy));
                    const float w =
                        depth_weight(p, i, j, distance, s) *
                        normal_weight(glm::dot(in.normal[i], in.normal[j]), s.normal_power);
                    sum_w += w;
                    sum_m += w * in.moments[j];
                }
            }
            const Vec2 m = sum_m / sum_w;  // sum_w > 0: the pixel itself has weight 1
            p.variance[i] =
                std::max(0.0f, m.y - m.x * m.x) * (s.min_temporal_history / std::max(1.0f, h));
        }
    });
}

// One à-trous pass with holes `step` pixels apart: illumination and variance into `out`.
// The three stopping functions multiply into one exponential per tap (the normal's power by
// squaring), and each tap's distance comes from a table: the pass is most of the filter's
// time.
void atrous_pass(const Planes& p, int step, const SvgfSettings& s, std::vector<Rgb>& out_illum,
                 std::vector<float>& out_var) {
    const SvgfInput& in = *p.input;
    const int r = s.kernel_radius;
    float distance[5][5] = {};
    for (int ky = -r; ky <= r; ++ky)
        for (int kx = -r; kx <= r; ++kx)
            distance[ky + 2][kx + 2] =
                static_cast<float>(step) * std::sqrt(static_cast<float>(kx * kx + ky * ky));
    const float* kernel = r == 1 ? kKernel3 : kKernel5;
    for_rows(p.height, [&](int y) {
        for (int x = 0; x < p.width; ++x) {
            const std::size_t i = p.at(x, y);
            if (!p.surface(i)) {
                out_illum[i] = p.illumination[i];
                out_var[i] = p.variance[i];
                continue;
            }
            // The luminance test's scale: the standard deviation, blurred 3x3 (less noisy).
            float blurred_var = 0.0f, blur_w = 0.0f;
            for (int dy = -1; dy <= 1; ++dy) {
                const int ny = y + dy;
                if (ny < 0 || ny >= p.height) continue;
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx;
                    if (nx < 0 || nx >= p.width) continue;
                    const std::size_t j = p.at(nx, ny);
                    if (!p.surface(j)) continue;
                    const float w = (dx == 0 ? 0.5f : 0.25f) * (dy == 0 ? 0.5f : 0.25f);
                    blurred_var += w * p.variance[j];
                    blur_w += w;
                }
            }
            const float inv_luminance_scale =
                1.0f /
                (s.sigma_luminance * std::sqrt(std::max(0.0f, blurred_var / blur_w)) + 1e-6f);
            const float li = p.luminance[i];
            const float zi = in.depth[i];
            // 1 / the depth test's scale at each tap's distance.
            const float depth_slope = s.sigma_depth * p.depth_gradient[i];
            float inv_depth_scale[5][5];
            for (int ky = -r; ky <= r; ++ky)
                for (int kx = -r; kx <= r; ++kx)
                    inv_depth_scale[ky + 2][kx + 2] =
                        1.0f / (depth_slope * distance[ky + 2][kx + 2] + 1e-3f * zi);
            const Vec3 ni = in.normal[i];
            Rgb sum(0.0f);
            float sum_w = 0.0f, sum_var = 0.0f;
            for (int ky = -r; ky <= r; ++ky) {
                const int ny = y + ky * step;
                if (ny < 0 || ny >= p.height) continue;
                for (int kx = -r; kx <= r; ++kx) {
                    const int nx = x + kx * step;
                    if (nx < 0 || nx >= p.width) continue;
                    const std::size_t j = p.at(nx, ny);
                    if (!p.surface(j)) continue;
                    float w = kernel[std::abs(kx)] * kernel[std::abs(ky)];
                    if (j != i) {
                        const float exponent =
                            std::abs(zi - in.depth[j]) * inv_depth_scale[ky + 2][kx + 2] +
                            std::abs(li - p.luminance[j]) * inv_luminance_scale;
                        w *= normal_weight(glm::dot(ni, in.normal[j]), s.normal_power) *
                             exp_negative(exponent);
                    }
                    sum += p.illumination[j] * w;
                    sum_w += w;
                    sum_var += w * w * p.variance[j];
                }
            }
            out_illum[i] = sum / sum_w;
            out_var[i] = sum_var / (sum_w * sum_w);
        }
    });
}

}  // namespace

Rgb svgf_demodulation(const Rgb& albedo) {
    Rgb d;
    for (int c = 0; c < 3; ++c) d[c] = albedo[c] > kAlbedoFloor ? albedo[c] : 1.0f;
    return d;
}

Vec2 svgf_moments(const Rgb& colour, const Rgb& albedo) {
    const Rgb d = svgf_demodulation(albedo);
    const float y = Rgb(colour.r / d.r, colour.g / d.g, colour.b / d.b).luminance();
    return Vec2(y, y * y);
}

std::vector<Rgb> svgf_filter(const SvgfInput& input, const SvgfSettings& settings) {
    const std::size_t count = static_cast<std::size_t>(input.width) * input.height;
    if (input.width <= 0 || input.height <= 0 || input.colour.size() != count ||
        input.albedo.size() != count || input.normal.size() != count ||
        input.depth.size() != count || input.moments.size() != count ||
        input.history_length.size() != count) {
        throw Error(
            fmt::format("SVGF: every input must hold {}x{} pixels", input.width, input.height));
    }
    Planes p{input.width, input.height, {}, {}, {}, {}, &input};
    p.illumination.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Rgb d = svgf_demodulation(input.albedo[i]);
        p.illumination[i] =
            Rgb(input.colour[i].r / d.r, input.colour[i].g / d.g, input.colour[i].b / d.b);
    }
    estimate_depth_gradient(p);
    estimate_variance(p, settings);
    std::vector<Rgb> next_illum(count);
    std::vector<float> next_var(count);
    p.luminance.resize(count);
    for (int level = 0; level < settings.levels; ++level) {
        for (std::size_t i = 0; i < count; ++i) p.luminance[i] = p.illumination[i].luminance();
        atrous_pass(p, 1 << level, settings, next_illum, next_var);
        std::swap(p.illumination, next_illum);
        std::swap(p.variance, next_var);
    }
    std::vector<Rgb> result(count);
    for (std::size_t i = 0; i < count; ++i)
        result[i] = p.illumination[i] * svgf_demodulation(input.albedo[i]);
    return result;
}

}  // namespace glint
