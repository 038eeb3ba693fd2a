#include <glint/core/error.h>
#include <glint/core/parallel.h>
#include <glint/denoise/svgf.h>

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace glint {
namespace {

constexpr float kAlbedoFloor = 1e-3f;
// The à-trous kernels' weights by |offset|: the B3 spline (5x5, as the paper) and its 3x3
// counterpart (as A-SVGF, Schied et al. 2018, for speed).
constexpr float kKernel5[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
constexpr float kKernel3[2] = {1.0f / 2.0f, 1.0f / 4.0f};

// Four or eight floats (ints) in one SSE or AVX register (GCC's vector extensions): an
// à-trous pass computes four or eight pixels' taps at once. Every operation is the IEEE one
// its scalar form does (no fused multiply-add: the AVX2 kernel is compiled without FMA), so
// every width gives the bits the scalar loop gives.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));
using Int8 = int32_t __attribute__((vector_size(32)));

// The integer vector of a float vector's width.
template <typename V>
struct IntLanes;
template <>
struct IntLanes<Float4> {
    using type = Int4;
};
template <>
struct IntLanes<Float8> {
    using type = Int8;
};

// The helpers (and atrous_row with its lambdas) are always inlined: the AVX2 kernel then
// compiles them with AVX2. They take lanes by reference, and GCC still warns, at the end of
// the file where it emits their eight-lane copies, that returning the lanes from code
// without AVX would pass them differently; no such call is made. (So the warning is off to
// the end of this file, which CMake compiles on its own, outside the unity batches.)
#pragma GCC diagnostic ignored "-Wpsabi"
template <typename V>
[[gnu::always_inline]] inline V load(const float* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
template <typename V>
[[gnu::always_inline]] inline void store(float* p, const V& v) {
    std::memcpy(p, &v, sizeof v);
}
template <typename V>
[[gnu::always_inline]] inline V abs_lanes(const V& v) {
    using I = typename IntLanes<V>::type;
    return reinterpret_cast<V>(reinterpret_cast<I>(v) & 0x7fffffff);
}

// 2^f on (-1, 0], a degree-5 fit, for floats and vectors alike.
template <typename T>
[[gnu::always_inline]] inline T exp2_fraction(const T& f) {
    return 1.0f + f * (0.693147182f +
                       f * (0.240226507f +
                            f * (0.0555041087f + f * (0.00961812911f + f * 0.00133335581f))));
}

// exp(-x) for x >= 0 to about 1e-5 relative: 2^-t as an exponent in the float's bits times
// a polynomial for the fraction. The filter's weights need no more, and std::exp is most of
// an à-trous tap's time. -x in powers of two is clamped (NaN too, from pixels whose result
// is thrown away).
[[gnu::always_inline]] inline float exp_negative(float x) {
    const float scaled = x * 1.44269504f;
    const float t = scaled < 126.0f ? scaled : 126.0f;
    const int whole = static_cast<int>(t);  // floor: t >= 0
    const float p = exp2_fraction(static_cast<float>(whole) - t);
    return p * std::bit_cast<float>(static_cast<uint32_t>(127 - whole) << 23);
}
template <typename V>
[[gnu::always_inline]] inline V exp_negative(const V& x) {
    using I = typename IntLanes<V>::type;
    const V scaled = x * 1.44269504f;
    const V t = scaled < 126.0f ? scaled : 126.0f;
    const I whole = __builtin_convertvector(t, I);
    const V p = exp2_fraction(__builtin_convertvector(whole, V) - t);
    return p * reinterpret_cast<V>((127 - whole) << 23);
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
    parallel_for_rows(p.height, [&](int y) {
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
    parallel_for_rows(p.height, [&](int y) {
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

// The planes an à-trous pass reads and writes, one float per pixel each, so that a pass can
// run along a row with every tap's arithmetic in SIMD lanes.
struct Signal {
    std::vector<float> r, g, b, variance, luminance;
    std::vector<float> variance_row_sums;  // row_sums() of the variance, for its 3x3 blur
    explicit Signal(std::size_t count)
        : r(count), g(count), b(count), variance(count), luminance(count) {}
};

// What the passes compare, constant over the levels.
struct Guide {
    int width, height;
    const float* depth;
    std::vector<float> nx, ny, nz;  // normals as planes
    const float* depth_gradient;
    // The 3x3 variance blur's weight sums: row_sums() of 1 on surfaces, 0 where rays escaped.
    std::vector<float> surface_row_sums;
};

// The variance blur's kernel along one axis (its 2D weights are products of these).
constexpr float kBlurCentre = 0.5f, kBlurSide = 0.25f;

// Each pixel's horizontal 1-2-1 sum (kBlurSide, kBlurCentre, kBlurSide) of `values` times
// `surface` (1 on a surface, 0 where the ray escaped); neighbours beyond the image add 0.
void row_sums(const Guide& g, const float* values, std::vector<float>& sums) {
    sums.resize(static_cast<std::size_t>(g.width) * g.height);
    parallel_for_rows(g.height, [&](int y) {
        const std::size_t row = static_cast<std::size_t>(y) * g.width;
        const float* v = values + row;
        const float* z = g.depth + row;
        float* out = sums.data() + row;
        auto masked = [&](int x) { return z[x] > 0.0f ? v[x] : 0.0f; };
        for (int x = 0; x < g.width; ++x) {
            float sum = kBlurCentre * masked(x);
            if (x > 0) sum += kBlurSide * masked(x - 1);
            if (x + 1 < g.width) sum += kBlurSide * masked(x + 1);
            out[x] = sum;
        }
    });
}

// A row's per-pixel scales of the stopping functions (atrous_row), and its running sums.
struct RowScales {
    const float* inv_luminance_scale;
    const float* slope;
    const float* floor_scale;
};
struct RowSums {
    float *r, *g, *b, *w, *variance;
};

// The taps of the pixels [x_begin, x_end) of row y, which all lie inside the image's row
// (x_end - x_begin a multiple of V's lanes), for the normal power of 128: `V`'s lanes of
// pixels at a time through every tap, their sums held in registers, where atrous_row's
// tap-by-tap loop loads and stores them once per tap. Each pixel adds its taps in the same
// order with the same operations: the same bits (tested).
template <typename V>
[[gnu::always_inline]] inline void interior_taps(const Guide& g, const Signal& in, int step,
                                                 const SvgfSettings& s, int y, RowScales scales,
                                                 RowSums sums, int x_begin, int x_end) {
    constexpr int kLanes = sizeof(V) / sizeof(float);
    const int width = g.width, r = s.kernel_radius;
    const float* kernel = r == 1 ? kKernel3 : kKernel5;
    struct Tap {
        std::ptrdiff_t shift;  // from the pixel's index to the tap's
        float kernel_w, distance;
    };
    Tap taps[24];
    int tap_count = 0;
    for (int ky = -r; ky <= r; ++ky) {
        const int ty = y + ky * step;
        if (ty < 0 || ty >= g.height) continue;
        for (int kx = -r; kx <= r; ++kx) {
            if (kx == 0 && ky == 0) continue;
            taps[tap_count++] = {
                static_cast<std::ptrdiff_t>(ky) * step * width + kx * step,
                kernel[std::abs(kx)] * kernel[std::abs(ky)],
                static_cast<float>(step) * std::sqrt(static_cast<float>(kx * kx + ky * ky))};
        }
    }
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(y) * width;
    const V zero{};
    for (int x = x_begin; x < x_end; x += kLanes) {
        const std::ptrdiff_t i = row + x;
        const V zi = load<V>(g.depth + i), li = load<V>(in.luminance.data() + i);
        const V nxi = load<V>(g.nx.data() + i), nyi = load<V>(g.ny.data() + i),
                nzi = load<V>(g.nz.data() + i);
        const V slope = load<V>(scales.slope + x), floor_scale = load<V>(scales.floor_scale + x);
        const V inv_luminance_scale = load<V>(scales.inv_luminance_scale + x);
        V sr = load<V>(sums.r + x), sg = load<V>(sums.g + x), sb = load<V>(sums.b + x),
          sw = load<V>(sums.w + x), sv = load<V>(sums.variance + x);
        for (int t = 0; t < tap_count; ++t) {
            const std::ptrdiff_t j = i + taps[t].shift;
            const V cosine = nxi * load<V>(g.nx.data() + j) + nyi * load<V>(g.ny.data() + j) +
                             nzi * load<V>(g.nz.data() + j);
            const V z = load<V>(g.depth + j);
            const V exponent =
                abs_lanes(zi - z) / (slope * taps[t].distance + floor_scale) +
                abs_lanes(li - load<V>(in.luminance.data() + j)) * inv_luminance_scale;
            V c = cosine > 0.0f ? cosine : zero;
            c *= c, c *= c, c *= c, c *= c, c *= c, c *= c;
            const V weight = taps[t].kernel_w * (c * c) * exp_negative(exponent);
            const V w = z > 0.0f ? weight : zero;  // escaped: no part
            sr = sr + w * load<V>(in.r.data() + j);
            sg = sg + w * load<V>(in.g.data() + j);
            sb = sb + w * load<V>(in.b.data() + j);
            sw = sw + w;
            sv = sv + w * w * load<V>(in.variance.data() + j);
        }
        store(sums.r + x, sr);
        store(sums.g + x, sg);
        store(sums.b + x, sb);
        store(sums.w + x, sw);
        store(sums.variance + x, sv);
    }
}

// Row y of one à-trous pass with holes `step` pixels apart, tap by tap: each tap's weights
// for the whole row in one loop without branches, `V`'s lanes at a time, the stopping
// functions' exponents summed into one exponential, the normal's power by squaring.
template <typename V>
[[gnu::always_inline]] inline void atrous_row(const Guide& g, const Signal& in, int step,
                                              const SvgfSettings& s, Signal& out, int y) {
    constexpr int kLanes = sizeof(V) / sizeof(float);
    const int width = g.width, r = s.kernel_radius;
    const float* kernel = r == 1 ? kKernel3 : kKernel5;
    const bool square_normal = s.normal_power == 128.0f;
    const std::size_t row = static_cast<std::size_t>(y) * width;
    std::vector<float> inv_luminance_scale(width), slope(width), floor_scale(width);
    std::vector<float> sum_r(width), sum_g(width), sum_b(width), sum_w(width), sum_var(width);
    for (int x = 0; x < width; ++x) {
        const std::size_t i = row + x;
        // The luminance test's scale: the standard deviation, its variance blurred 3x3 over
        // the pixels on a surface (less noisy), from the rows' horizontal sums.
        float blurred_var = 0.0f, blur_w = 0.0f;
        for (int dy = -1; dy <= 1; ++dy) {
            const int ny = y + dy;
            if (ny < 0 || ny >= g.height) continue;
            const float wy = dy == 0 ? kBlurCentre : kBlurSide;
            const std::size_t j = static_cast<std::size_t>(ny) * width + x;
            blurred_var += wy * in.variance_row_sums[j];
            blur_w += wy * g.surface_row_sums[j];
        }
        inv_luminance_scale[x] =
            blur_w > 0.0f
                ? 1.0f /
                      (s.sigma_luminance * std::sqrt(std::max(0.0f, blurred_var / blur_w)) + 1e-6f)
                : 0.0f;
        slope[x] = s.sigma_depth * g.depth_gradient[i];
        floor_scale[x] = 1e-3f * g.depth[i];
        // The pixel itself, with the kernel's weight alone.
        const float w = kernel[0] * kernel[0];
        sum_r[x] = w * in.r[i];
        sum_g[x] = w * in.g[i];
        sum_b[x] = w * in.b[i];
        sum_w[x] = w;
        sum_var[x] = w * w * in.variance[i];
    }
    // The interior: pixels all of whose taps lie inside the row, whole groups of lanes of
    // them, which interior_taps() filters with every tap at once (the usual power of 128).
    const int margin = r * step;
    const int interior_begin = margin;
    const int interior_end =
        square_normal && s.blocked_taps
            ? interior_begin + std::max(0, width - 2 * margin) / kLanes * kLanes
            : interior_begin;
    const float* zi = g.depth + row;
    const float* li = in.luminance.data() + row;
    const float* nxi = g.nx.data() + row;
    const float* nyi = g.ny.data() + row;
    const float* nzi = g.nz.data() + row;
    for (int ky = -r; ky <= r; ++ky) {
        const int ty = y + ky * step;
        if (ty < 0 || ty >= g.height) continue;
        for (int kx = -r; kx <= r; ++kx) {
            if (kx == 0 && ky == 0) continue;
            const int dx = kx * step;
            const int x0 = std::max(0, -dx), x1 = std::min(width, width - dx);
            if (x0 >= x1) continue;
            const float kernel_w = kernel[std::abs(kx)] * kernel[std::abs(ky)];
            const float distance =
                static_cast<float>(step) * std::sqrt(static_cast<float>(kx * kx + ky * ky));
            // Tap j of pixel x is element x of these.
            const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(ty) * width + dx;
            const float* zj = g.depth + shift;
            const float* lj = in.luminance.data() + shift;
            const float* nxj = g.nx.data() + shift;
            const float* nyj = g.ny.data() + shift;
            const float* nzj = g.nz.data() + shift;
            const float* rj = in.r.data() + shift;
            const float* gj = in.g.data() + shift;
            const float* bj = in.b.data() + shift;
            const float* vj = in.variance.data() + shift;
            // The loop twice, so that the usual power of 128 needs no branch inside. Local
            // restrict pointers tell the compiler the sums alias no input: it can then run
            // the loop in SIMD lanes.
            auto taps_over = [&](auto normal_of, int x_begin, int x_end)
                __attribute__((always_inline)) {
                const float* __restrict czi = zi;
                const float* __restrict cli = li;
                const float* __restrict cnx = nxi;
                const float* __restrict cny = nyi;
                const float* __restrict cnz = nzi;
                const float* __restrict tz = zj;
                const float* __restrict tl = lj;
                const float* __restrict tnx = nxj;
                const float* __restrict tny = nyj;
                const float* __restrict tnz = nzj;
                const float* __restrict tr = rj;
                const float* __restrict tg = gj;
                const float* __restrict tb = bj;
                const float* __restrict tv = vj;
                const float* __restrict sl = slope.data();
                const float* __restrict fl = floor_scale.data();
                const float* __restrict il = inv_luminance_scale.data();
                float* __restrict sr = sum_r.data();
                float* __restrict sg = sum_g.data();
                float* __restrict sb = sum_b.data();
                float* __restrict sw = sum_w.data();
                float* __restrict sv = sum_var.data();
                const float kw = kernel_w, dist = distance;
                int x = x_begin;
                for (; x + kLanes <= x_end; x += kLanes) {
                    const V cosine = load<V>(cnx + x) * load<V>(tnx + x) +
                                     load<V>(cny + x) * load<V>(tny + x) +
                                     load<V>(cnz + x) * load<V>(tnz + x);
                    const V z = load<V>(tz + x);
                    const V exponent =
                        abs_lanes(load<V>(czi + x) - z) /
                            (load<V>(sl + x) * dist + load<V>(fl + x)) +
                        abs_lanes(load<V>(cli + x) - load<V>(tl + x)) * load<V>(il + x);
                    const V zero{};
                    const V weight =
                        kw * normal_of(cosine > 0.0f ? cosine : zero) * exp_negative(exponent);
                    const V w = z > 0.0f ? weight : zero;  // escaped: no part
                    store(sr + x, load<V>(sr + x) + w * load<V>(tr + x));
                    store(sg + x, load<V>(sg + x) + w * load<V>(tg + x));
                    store(sb + x, load<V>(sb + x) + w * load<V>(tb + x));
                    store(sw + x, load<V>(sw + x) + w);
                    store(sv + x, load<V>(sv + x) + w * w * load<V>(tv + x));
                }
                for (; x < x_end; ++x) {
                    const float cosine = cnx[x] * tnx[x] + cny[x] * tny[x] + cnz[x] * tnz[x];
                    const float exponent = std::abs(czi[x] - tz[x]) / (sl[x] * dist + fl[x]) +
                                           std::abs(cli[x] - tl[x]) * il[x];
                    const float weight =
                        kw * normal_of(cosine > 0.0f ? cosine : 0.0f) * exp_negative(exponent);
                    const float w = tz[x] > 0.0f ? weight : 0.0f;  // escaped: no part
                    sr[x] += w * tr[x];
                    sg[x] += w * tg[x];
                    sb[x] += w * tb[x];
                    sw[x] += w;
                    sv[x] += w * w * tv[x];
                }
            };
            // The pixels this tap-by-tap loop serves: all of them, or those beside the
            // interior that interior_taps() serves.
            auto taps = [&](auto normal_of) __attribute__((always_inline)) {
                if (interior_end <= interior_begin) {
                    taps_over(normal_of, x0, x1);
                    return;
                }
                taps_over(normal_of, x0, std::min(x1, interior_begin));
                taps_over(normal_of, std::max(x0, interior_end), x1);
            };
            if (square_normal) {
                // The lanes by reference: see the helpers on passing them.
                taps([](const auto& cosine) __attribute__((always_inline)) {
                    auto c = cosine;
                    c *= c, c *= c, c *= c, c *= c, c *= c, c *= c;
                    return c * c;  // c^128
                });
            } else {
                taps([&](const auto& cosine) __attribute__((always_inline)) {
                    // Any other power lane by lane (slower; the settings' default is 128).
                    auto c = cosine;
                    if constexpr (std::is_same_v<decltype(c), float>) {
                        return std::pow(c, s.normal_power);
                    } else {
                        for (int k = 0; k < kLanes; ++k) c[k] = std::pow(c[k], s.normal_power);
                        return c;
                    }
                });
            }
        }
    }
    if (interior_end > interior_begin)
        interior_taps<V>(g, in, step, s, y,
                         {inv_luminance_scale.data(), slope.data(), floor_scale.data()},
                         {sum_r.data(), sum_g.data(), sum_b.data(), sum_w.data(), sum_var.data()},
                         interior_begin, interior_end);
    for (int x = 0; x < width; ++x) {
        const std::size_t i = row + x;
        if (!(g.depth[i] > 0.0f)) {  // escaped: passes through
            out.r[i] = in.r[i];
            out.g[i] = in.g[i];
            out.b[i] = in.b[i];
            out.variance[i] = in.variance[i];
            continue;
        }
        const float inv = 1.0f / sum_w[x];
        out.r[i] = sum_r[x] * inv;
        out.g[i] = sum_g[x] * inv;
        out.b[i] = sum_b[x] * inv;
        out.variance[i] = sum_var[x] * inv * inv;
    }
}

// The row in SSE2 (every x86-64), and in AVX2 where the processor has it: eight lanes, the
// same bits (SvgfSettings::wide_lanes; tested).
void atrous_row_sse2(const Guide& g, const Signal& in, int step, const SvgfSettings& s, Signal& out,
                     int y) {
    atrous_row<Float4>(g, in, step, s, out, y);
}
__attribute__((target("avx2"))) void atrous_row_avx2(const Guide& g, const Signal& in, int step,
                                                     const SvgfSettings& s, Signal& out, int y) {
    atrous_row<Float8>(g, in, step, s, out, y);
}

bool processor_has_avx2() {
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
}

void atrous_pass(const Guide& g, const Signal& in, int step, const SvgfSettings& s, Signal& out) {
    const auto row = s.wide_lanes && processor_has_avx2() ? atrous_row_avx2 : atrous_row_sse2;
    parallel_for_rows(g.height, [&](int y) { row(g, in, step, s, out, y); });
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
    // Every per-pixel step runs in parallel: at 640x480 the serial loops took a third of
    // the filter's time. Each pixel's value is its own, so the bits do not depend on threads.
    parallel_for_indices(count, [&](std::size_t i) {
        const Rgb d = svgf_demodulation(input.albedo[i]);
        p.illumination[i] =
            Rgb(input.colour[i].r / d.r, input.colour[i].g / d.g, input.colour[i].b / d.b);
    });
    estimate_depth_gradient(p);
    estimate_variance(p, settings);
    Guide guide{input.width, input.height, input.depth.data(),      {},
                {},          {},           p.depth_gradient.data(), {}};
    guide.nx.resize(count);
    guide.ny.resize(count);
    guide.nz.resize(count);
    Signal signal(count), next(count);
    parallel_for_indices(count, [&](std::size_t i) {
        guide.nx[i] = input.normal[i].x;
        guide.ny[i] = input.normal[i].y;
        guide.nz[i] = input.normal[i].z;
        signal.r[i] = p.illumination[i].r;
        signal.g[i] = p.illumination[i].g;
        signal.b[i] = p.illumination[i].b;
        signal.variance[i] = p.variance[i];
    });
    row_sums(guide, std::vector<float>(count, 1.0f).data(), guide.surface_row_sums);
    for (int level = 0; level < settings.levels; ++level) {
        parallel_for_indices(count, [&](std::size_t i) {
            signal.luminance[i] = Rgb(signal.r[i], signal.g[i], signal.b[i]).luminance();
        });
        row_sums(guide, signal.variance.data(), signal.variance_row_sums);
        atrous_pass(guide, signal, 1 << level, settings, next);
        std::swap(signal, next);
    }
    std::vector<Rgb> result(count);
    parallel_for_indices(count, [&](std::size_t i) {
        result[i] = Rgb(signal.r[i], signal.g[i], signal.b[i]) * svgf_demodulation(input.albedo[i]);
    });
    return result;
}

}  // namespace glint
