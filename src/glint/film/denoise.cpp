#include <glint/core/cancel.h>
#include <glint/film/denoise.h>

#include <glint/core/error.h>
#include <glint/film/film.h>
#include <glint/math/vector.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace glint {

namespace {

// Albedo below this is treated as this when demodulating: dividing by a near-zero albedo
// (a black surface, the sky, which has no features) would blow the noise up, while any
// positive divisor that is multiplied back after filtering leaves an unfiltered pixel as
// it was.
constexpr float kMinAlbedo = 0.02f;
// See clamp_fireflies(); 1.5 costs 1-3 % of relative MSE against clamping at 1 on
// examples/textures.lua and the Cornell box at 16 spp, and leaves noise-free images alone.
constexpr float kFireflyRatio = 1.5f;

float luminance(const Vec3& c) {
    return Rgb(c.x, c.y, c.z).luminance();
}

// The channels the denoiser reads from one image.
struct Channels {
    int rgb[3], albedo[3], normal[3], depth;

    explicit Channels(const Image& image, const char* which) {
        const char* names[10] = {"R",        "G",        "B",        "albedo.R", "albedo.G",
                                 "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z"};
        int found[10];
        for (int k = 0; k < 10; ++k) {
            found[k] = image.channel_index(names[k]);
            if (found[k] < 0) {
                throw Error(
                    fmt::format("denoise: the {} image has no channel {} (the denoiser "
                                "needs radiance and the albedo, normal and depth AOVs)",
                                which, names[k]));
            }
        }
        for (int c = 0; c < 3; ++c) {
            rgb[c] = found[c];
            albedo[c] = found[3 + c];
            normal[c] = found[6 + c];
        }
        depth = found[9];
    }
    Vec3 read(const Image& image, int x, int y, const int (&channels)[3]) const {
        return Vec3(image.at(x, y, channels[0]), image.at(x, y, channels[1]),
                    image.at(x, y, channels[2]));
    }
};

Vec3 demodulation_divisor(const Vec3& albedo) {
    return glm::max(albedo, Vec3(kMinAlbedo));
}

// Row-parallel loop over an image's rows; every row is written by one task only.
template <typename Body>
void for_each_row(int height, Body&& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        throw_if_cancelled();  // the denoiser's every pass goes through here
        for (int y = rows.begin(); y < rows.end(); ++y) body(y);
    });
}

// Mean of `values` over the (2 radius + 1)^2 box around each pixel, within the image.
template <typename T>
std::vector<T> box_mean(const std::vector<T>& values, int width, int height, int radius) {
    std::vector<T> rows(values.size()), result(values.size());
    for_each_row(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            T sum{};
            const int x0 = std::max(0, x - radius), x1 = std::min(width - 1, x + radius);
            for (int sx = x0; sx <= x1; ++sx) sum += values[static_cast<size_t>(y) * width + sx];
            rows[static_cast<size_t>(y) * width + x] = sum / static_cast<float>(x1 - x0 + 1);
        }
    });
    for_each_row(height, [&](int y) {
        const int y0 = std::max(0, y - radius), y1 = std::min(height - 1, y + radius);
        for (int x = 0; x < width; ++x) {
            T sum{};
            for (int sy = y0; sy <= y1; ++sy) sum += rows[static_cast<size_t>(sy) * width + x];
            result[static_cast<size_t>(y) * width + x] = sum / static_cast<float>(y1 - y0 + 1);
        }
    });
    return result;
}

// Two robust limits on a half's pixel, in luminance: more than kFireflyRatio times as
// bright as all 16 neighbours of it in both halves, it is scaled down to the brightest of
// them (a firefly in both halves, or an isolated one); more than kFireflyRatio times as
// bright as the other half's 3 x 3 window, it is scaled down to that ratio (a cluster of
// fireflies in one half). Not any pixel brighter than its neighbours: the top of a smooth
// highlight is one, and stays. A legitimate bright pixel has bright neighbours
// or a bright twin in the other half's neighbourhood; an isolated one is a rare path that
// 8 or 16 samples cannot average out, and would be smeared over the whole search window.
std::vector<Vec3> clamp_fireflies(const std::vector<Vec3>& own, const std::vector<Vec3>& other,
                                  int width, int height) {
    std::vector<Vec3> result(own.size());
    for_each_row(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            float brightest = 0.0f;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height)
                        continue;
                    const size_t j = static_cast<size_t>(ny) * width + nx;
                    brightest = std::max({brightest, luminance(own[j]), luminance(other[j])});
                }
            }
            const float l = luminance(own[i]);
            // The other half's 3 x 3 window, centre included: a rare path lands in one
            // half only, so a cluster of fireflies in this half still stands out there.
            float other_max = 0.0f;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    other_max =
                        std::max(other_max, luminance(other[static_cast<size_t>(ny) * width + nx]));
                }
            }
            float limit = l;
            if (l > kFireflyRatio * brightest) limit = brightest;
            if (l > kFireflyRatio * other_max) limit = std::min(limit, kFireflyRatio * other_max);
            result[i] = limit < l ? own[i] * (limit / l) : own[i];
        }
    });
    return result;
}

}  // namespace

Image denoise(const Image& full, const Image& half_a, const Image& half_b,
              const DenoiseSettings& settings) {
    if (full.width != half_a.width || full.height != half_a.height || full.width != half_b.width ||
        full.height != half_b.height) {
        throw Error(fmt::format("denoise: the halves ({}x{}, {}x{}) differ from the image ({}x{})",
                                half_a.width, half_a.height, half_b.width, half_b.height,
                                full.width, full.height));
    }
    if (settings.radius < 0 || settings.radius > 32 || settings.patch_radius < 0 ||
        settings.patch_radius > 8) {
        throw Error("denoise: radius must be in [0, 32] and patch_radius in [0, 8]");
    }
    if (!(settings.color_strength > 0.0f) || !(settings.albedo_sigma > 0.0f) ||
        !(settings.normal_sigma > 0.0f) || !(settings.depth_sigma > 0.0f)) {
        throw Error("denoise: strengths and sigmas must be positive");
    }
    const Channels cf(full, "full"), ca(half_a, "first half"), cb(half_b, "second half");
    const int w = full.width, h = full.height;
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);

    // Demodulated halves, and the features of the whole pixel with their variance from the
    // halves' disagreement: the variance of the mean of two halves is (a - b)^2 / 4. Both
    // halves are divided by the whole pixel's albedo, the one that multiplies the result
    // back (each half's own albedo measured 5-15 % worse: its noise stays in the ratio).
    std::vector<Vec3> a(n), b(n), albedo(n), normal(n), divisor(n);
    std::vector<float> depth(n), albedo_var(n), normal_var(n), depth_var(n);
    for_each_row(h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = static_cast<size_t>(y) * w + x;
            const Vec3 albedo_a = ca.read(half_a, x, y, ca.albedo),
                       albedo_b = cb.read(half_b, x, y, cb.albedo);
            albedo[i] = cf.read(full, x, y, cf.albedo);
            divisor[i] = demodulation_divisor(albedo[i]);
            a[i] = ca.read(half_a, x, y, ca.rgb) / divisor[i];
            b[i] = cb.read(half_b, x, y, cb.rgb) / divisor[i];
            normal[i] = cf.read(full, x, y, cf.normal);
            depth[i] = full.at(x, y, cf.depth);
            const Vec3 da = albedo_a - albedo_b;
            const Vec3 dn = ca.read(half_a, x, y, ca.normal) - cb.read(half_b, x, y, cb.normal);
            const float dz = half_a.at(x, y, ca.depth) - half_b.at(x, y, cb.depth);
            const float scale = std::max(std::abs(depth[i]), 1e-6f);
            albedo_var[i] = 0.25f * glm::dot(da, da);
            normal_var[i] = 0.25f * glm::dot(dn, dn);
            depth_var[i] = 0.25f * (dz / scale) * (dz / scale);
        }
    });
    if (settings.clamp_fireflies) {
        std::vector<Vec3> clamped_a = clamp_fireflies(a, b, w, h);
        b = clamp_fireflies(b, a, w, h);
        a = std::move(clamped_a);
    }
    // The variance of one half, per channel: var(a - b) = 2 var(half). One pixel's estimate
    // has a single degree of freedom, so it is averaged over a 5 x 5 box.
    std::vector<Vec3> variance(n);
    for (size_t i = 0; i < n; ++i) variance[i] = 0.5f * (a[i] - b[i]) * (a[i] - b[i]);
    variance = box_mean(variance, w, h, 2);
    albedo_var = box_mean(albedo_var, w, h, 1);
    normal_var = box_mean(normal_var, w, h, 1);
    depth_var = box_mean(depth_var, w, h, 1);

    const float k2 = settings.color_strength * settings.color_strength;
    const float albedo_s2 = settings.albedo_sigma * settings.albedo_sigma;
    const float normal_s2 = settings.normal_sigma * settings.normal_sigma;
    const float depth_s2 = settings.depth_sigma * settings.depth_sigma;

    // Non-local means, one neighbour offset at a time: for offset d, term(s) is the colour
    // distance between pixels s and s + d, and the patch distance between p and p + d is
    // the mean of term over p's patch (the box-filter formulation of NL-means). Bands of
    // rows run in parallel, each with the patch's rows above and below it; every pixel
    // accumulates its neighbours in the same order of offsets, whatever the threads do.
    std::vector<Vec3> sum_a(n, Vec3(0.0f)), sum_b(n, Vec3(0.0f));
    std::vector<float> weight_a(n, 0.0f), weight_b(n, 0.0f);
    const int r = settings.radius, pr = settings.patch_radius;
    constexpr int kBand = 8;
    auto filter_band = [&](int y0, int y1) {
        // Term rows [t0, t1): the band and the patch's reach beyond it, within the image.
        const int t0 = std::max(0, y0 - pr), t1 = std::min(h, y1 + pr);
        const size_t rows = static_cast<size_t>(t1 - t0) * w;
        std::vector<float> term_a(rows), term_b(rows), valid(rows);
        std::vector<float> row_a(rows), row_b(rows), row_valid(rows);
        for (int dy = -r; dy <= r; ++dy) {
            for (int dx = -r; dx <= r; ++dx) {
                // Distances for filtering a come from b and the other way round.
                for (int y = t0; y < t1; ++y) {
                    for (int x = 0; x < w; ++x) {
                        const size_t i = static_cast<size_t>(y) * w + x;
                        const size_t k = static_cast<size_t>(y - t0) * w + x;
                        const int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= w || qy >= h) {
                            term_a[k] = term_b[k] = valid[k] = 0.0f;
                            continue;
                        }
                        const size_t j = static_cast<size_t>(qy) * w + qx;
                        float ta = 0.0f, tb = 0.0f;
                        for (int c = 0; c < 3; ++c) {
                            const float vp = variance[i][c], vq = variance[j][c];
                            // Noise alone makes E[(u_p - u_q)^2] exceed the true squared
                            // difference by vp + vq; subtracting vp + min(vp, vq) removes
                            // that without cancelling real differences at a noisy pixel's
                            // edge.
                            const float cancel = vp + std::min(vp, vq);
                            const float norm = 1e-10f + k2 * (vp + vq);
                            const float db = b[i][c] - b[j][c], da = a[i][c] - a[j][c];
                            ta += (db * db - cancel) / norm;
                            tb += (da * da - cancel) / norm;
                        }
                        term_a[k] = ta / 3.0f;
                        term_b[k] = tb / 3.0f;
                        valid[k] = 1.0f;
                    }
                }
                // The patch means, as box_mean(): along rows, then along columns.
                for (int y = t0; y < t1; ++y) {
                    const size_t row = static_cast<size_t>(y - t0) * w;
                    for (int x = 0; x < w; ++x) {
                        const int x0 = std::max(0, x - pr), x1 = std::min(w - 1, x + pr);
                        float sa = 0.0f, sb = 0.0f, sv = 0.0f;
                        for (int sx = x0; sx <= x1; ++sx) {
                            sa += term_a[row + sx];
                            sb += term_b[row + sx];
                            sv += valid[row + sx];
                        }
                        const float count = static_cast<float>(x1 - x0 + 1);
                        row_a[row + x] = sa / count;
                        row_b[row + x] = sb / count;
                        row_valid[row + x] = sv / count;
                    }
                }
                for (int y = y0; y < y1; ++y) {
                    const int s0 = std::max(0, y - pr), s1 = std::min(h - 1, y + pr);
                    const float count = static_cast<float>(s1 - s0 + 1);
                    for (int x = 0; x < w; ++x) {
                        const size_t i = static_cast<size_t>(y) * w + x;
                        if (valid[static_cast<size_t>(y - t0) * w + x] == 0.0f) continue;
                        float pa = 0.0f, pb = 0.0f, pv = 0.0f;
                        for (int sy = s0; sy <= s1; ++sy) {
                            const size_t k = static_cast<size_t>(sy - t0) * w + x;
                            pa += row_a[k];
                            pb += row_b[k];
                            pv += row_valid[k];
                        }
                        const size_t j = static_cast<size_t>(y + dy) * w + (x + dx);
                        // Patch means over the pairs that lie inside the image.
                        const float inv = 1.0f / (pv / count);
                        const float ca_w = std::exp(-std::max(0.0f, pa / count * inv));
                        const float cb_w = std::exp(-std::max(0.0f, pb / count * inv));
                        // Features: a squared difference beyond what their own noise
                        // explains, in units of sigma^2 widened by that noise.
                        const Vec3 dalb = albedo[i] - albedo[j];
                        const Vec3 dnor = normal[i] - normal[j];
                        const float zscale = std::max(std::abs(depth[i]), 1e-6f);
                        const float dz = (depth[i] - depth[j]) / zscale;
                        auto feature = [](float d2, float vp, float vq, float s2) {
                            return std::max(0.0f, d2 - vp - std::min(vp, vq)) / (s2 + vp + vq);
                        };
                        const float phi =
                            feature(glm::dot(dalb, dalb), albedo_var[i], albedo_var[j], albedo_s2) +
                            feature(glm::dot(dnor, dnor), normal_var[i], normal_var[j], normal_s2) +
                            feature(dz * dz, depth_var[i], depth_var[j], depth_s2);
                        const float fw = std::exp(-phi);
                        const float wa = ca_w * fw, wb = cb_w * fw;
                        sum_a[i] += wa * a[j];
                        weight_a[i] += wa;
                        sum_b[i] += wb * b[j];
                        weight_b[i] += wb;
                    }
                }
            }
        }
    };
    const int bands = (h + kBand - 1) / kBand;
    tbb::parallel_for(tbb::blocked_range<int>(0, bands), [&](const tbb::blocked_range<int>& range) {
        for (int band = range.begin(); band < range.end(); ++band)
            filter_band(band * kBand, std::min(h, (band + 1) * kBand));
    });

    Image result = make_image(w, h, {"R", "G", "B"});
    for_each_row(h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = static_cast<size_t>(y) * w + x;
            // The centre pixel always has weight 1, so the sums are never empty.
            const Vec3 filtered =
                0.5f * (sum_a[i] / weight_a[i] + sum_b[i] / weight_b[i]) * divisor[i];
            for (int c = 0; c < 3; ++c) result.at(x, y, c) = filtered[c];
        }
    });
    return result;
}

Image denoise(const Film& film, const DenoiseSettings& settings) {
    if (!film.has_halves() || !film.has_aovs())
        throw Error("denoise: the film must keep halves and AOVs");
    return denoise(film.resolve(), film.resolve_half(0), film.resolve_half(1), settings);
}

}  // namespace glint
