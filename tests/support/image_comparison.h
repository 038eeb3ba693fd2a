#pragma once
// Comparisons of Monte Carlo images for the integrator tests (light tracing and bdpt against
// path tracing and SPPM). Bounds come from the images' own noise: each integrator renders K
// images with independent seeds; the spread of the K values of a statistic (a block mean, a
// region mean) gives its standard error, with every correlation between pixels included (one
// light path splats to several pixels, so the pixels of a light-traced image are not
// independent).
#include <glint/core/arena.h>
#include <glint/film/image.h>
#include <glint/material/bsdf.h>
#include <glint/material/material.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace glint::test {

// Pixels the light tracer can see as the path tracer does: those whose camera ray first
// hits a surface without delta lobes (or an area light). A specular vertex cannot connect
// to the lens, so a light-traced image shows mirrors and glass seen directly as black,
// and rays that escape would need lights at infinity (which it cannot see either). A pixel
// gathers light from its whole square, so the rays through the centres of its eight
// neighbours must hit such a surface too: that keeps out pixels that straddle an edge.
// The mask holds kScattering or kEmitter for a pixel kept (kEmitter where its own ray
// hits an area light), 0 for one left out.
inline constexpr uint8_t kScattering = 1, kEmitter = 2;
inline std::vector<uint8_t> non_delta_mask(const std::string& code) {
    const SceneDesc desc = load_scene_string(code, "mask.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    const int w = settings.width, h = settings.height;
    Arena arena;
    std::vector<bool> seen(static_cast<size_t>(w) * h), emitter(seen.size());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Ray ray = scene->camera().generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            std::optional<SurfaceInteraction> si = scene->intersect(ray);
            if (!si) continue;
            arena.reset();
            const Bsdf* bsdf = si->material->scatter(*si, arena);
            seen[static_cast<size_t>(y) * w + x] =
                bsdf ? !(bsdf->flags() & kBsdfDelta) : si->material->is_emissive();
            emitter[static_cast<size_t>(y) * w + x] = !bsdf && si->material->is_emissive();
        }
    }
    std::vector<uint8_t> mask(seen.size(), 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool all = true;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
                    all = all && seen[static_cast<size_t>(ny) * w + nx];
                }
            }
            if (all)
                mask[static_cast<size_t>(y) * w + x] =
                    emitter[static_cast<size_t>(y) * w + x] ? kEmitter : kScattering;
        }
    }
    return mask;
}

// K renders of one integrator with independent seeds.
inline std::vector<Image> render_seeds(const std::function<std::string(int)>& scene, int k) {
    std::vector<Image> images;
    for (int seed = 1; seed <= k; ++seed) images.push_back(render_lua(scene(seed)));
    return images;
}

// A statistic of each of K independent images: its mean and the standard error of that mean.
struct Estimate {
    double mean = 0.0, se = 0.0;
};
inline Estimate estimate(const std::vector<double>& values, double scale) {
    const double k = static_cast<double>(values.size());
    double sum = 0.0, sum2 = 0.0;
    for (double v : values) {
        sum += scale * v;
        sum2 += scale * v * scale * v;
    }
    const double mean = sum / k;
    const double variance = std::max(0.0, (sum2 - k * mean * mean) / (k - 1.0));
    return {mean, std::sqrt(variance / k)};
}

// The mean over all pixels and channel `c` of K renders of `scene(seed)`, with its standard
// error from the renders' spread.
inline Estimate image_mean(const std::function<std::string(int)>& scene, int k, int c) {
    std::vector<double> means;
    for (const Image& image : render_seeds(scene, k))
        means.push_back(mean_channel(image, c, 0, 0, image.width, image.height));
    return estimate(means, 1.0);
}

// image_mean for all three channels, rendering the K images once.
inline std::array<Estimate, 3> channel_means(const std::function<std::string(int)>& scene, int k) {
    const std::vector<Image> images = render_seeds(scene, k);
    std::array<Estimate, 3> result;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> means;
        for (const Image& image : images)
            means.push_back(mean_channel(image, c, 0, 0, image.width, image.height));
        result[c] = estimate(means, 1.0);
    }
    return result;
}

// The noise of one pixel of `scene` in channel `c`: half the mean squared difference of two
// renders with independent seeds, over all pixels (for a scene whose pixels all have the same
// expected value, such as a furnace). With hundreds of pixels it is known to a few per cent,
// far better than the spread of a few image means, so it can be bounded against a recorded
// level: an integrator that became less efficient (a wrong MIS weight) shows it here.
inline double pixel_variance(const std::function<std::string(int)>& scene, int c) {
    const std::vector<Image> images = render_seeds(scene, 2);
    const Image& a = images[0];
    const Image& b = images[1];
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const double d = static_cast<double>(a.at(x, y, c)) - b.at(x, y, c);
            sum += 0.5 * d * d;
        }
    }
    return sum / (static_cast<double>(a.width) * a.height);
}

// Means over the masked pixels of a square block of `block` x `block` pixels (NaN for
// a block with fewer than a quarter of its pixels masked), per channel, and over the
// kScattering pixels of the mask (the last three entries). The region means leave out the
// lights seen directly: the path tracer sees them without noise and they are bright, so
// they would dilute a bias of the rest (the blocks keep them).
inline std::vector<double> masked_means(const Image& image, const std::vector<uint8_t>& mask,
                                        int block) {
    const int bw = image.width / block, bh = image.height / block;
    std::vector<double> means;
    std::array<double, 3> total{};
    int total_count = 0;
    for (int by = 0; by < bh; ++by) {
        for (int bx = 0; bx < bw; ++bx) {
            std::array<double, 3> sum{};
            int count = 0;
            for (int y = by * block; y < (by + 1) * block; ++y) {
                for (int x = bx * block; x < (bx + 1) * block; ++x) {
                    const uint8_t kind = mask[static_cast<size_t>(y) * image.width + x];
                    if (!kind) continue;
                    ++count;
                    for (int c = 0; c < 3; ++c) sum[c] += image.at(x, y, c);
                    if (kind != kScattering) continue;
                    ++total_count;
                    for (int c = 0; c < 3; ++c) total[c] += image.at(x, y, c);
                }
            }
            for (int c = 0; c < 3; ++c)
                means.push_back(4 * count >= block * block ? sum[c] / count : std::nan(""));
        }
    }
    for (int c = 0; c < 3; ++c) means.push_back(total[c] / total_count);
    return means;
}

// The comparison of a test integrator's images (scaled by `scale`) with a reference's over
// the masked pixels.
//  - Relative MSE of the block means (mean of the K images): (a - b)^2 / b^2 summed over
//    blocks and channels. Without bias its expectation is the same sum of the two means'
//    variances (var_a + var_b) / b^2, estimated from the K images' spread; `expected`.
//  - The region mean per channel, with its standard error.
struct Comparison {
    double rel_mse = 0.0, expected = 0.0;
    std::array<Estimate, 3> test, reference;
    int blocks = 0, pixels = 0;

    // Limits: the relative MSE may exceed its expectation by 60 % (with ~100 block-channel
    // terms and variances estimated from K = 8 images, its ratio to the estimate scatters
    // by about 20 %); the region means may differ by four standard errors of their
    // difference (the standard errors estimated from K = 8 values).
    bool mse_agrees() const { return rel_mse < 1.6 * expected; }
    bool means_agree(int c) const {
        const double se = std::hypot(test[c].se, reference[c].se);
        return std::abs(test[c].mean - reference[c].mean) < 4.0 * se;
    }
    bool agrees() const {
        return mse_agrees() && means_agree(0) && means_agree(1) && means_agree(2);
    }
    std::string describe() const {
        std::string text =
            fmt::format("{} pixels, {} block-channels: relMSE {:.4g} (expected {:.4g})", pixels,
                        blocks, rel_mse, expected);
        for (int c = 0; c < 3; ++c) {
            text += fmt::format("; ch{} {:.5g} +- {:.2g} vs {:.5g} +- {:.2g}", c, test[c].mean,
                                test[c].se, reference[c].mean, reference[c].se);
        }
        return text;
    }
};

inline Comparison compare(const std::vector<Image>& test, const std::vector<Image>& reference,
                          const std::vector<uint8_t>& mask, int block, double scale = 1.0) {
    std::vector<std::vector<double>> a, b;
    for (const Image& image : test) a.push_back(masked_means(image, mask, block));
    for (const Image& image : reference) b.push_back(masked_means(image, mask, block));
    const size_t n = a.front().size();
    auto column = [](const std::vector<std::vector<double>>& rows, size_t i) {
        std::vector<double> values;
        for (const auto& row : rows) values.push_back(row[i]);
        return values;
    };
    Comparison result;
    for (size_t i = 0; i + 3 < n; ++i) {
        if (std::isnan(a.front()[i])) continue;
        const Estimate ea = estimate(column(a, i), scale), eb = estimate(column(b, i), 1.0);
        // A floor on the denominator keeps black blocks (none in these scenes) finite.
        const double denominator = eb.mean * eb.mean + 1e-6;
        result.rel_mse += (ea.mean - eb.mean) * (ea.mean - eb.mean) / denominator;
        result.expected += (ea.se * ea.se + eb.se * eb.se) / denominator;
        ++result.blocks;
    }
    for (int c = 0; c < 3; ++c) {
        result.test[c] = estimate(column(a, n - 3 + c), scale);
        result.reference[c] = estimate(column(b, n - 3 + c), 1.0);
    }
    result.pixels = static_cast<int>(mask.size() - std::count(mask.begin(), mask.end(), 0));
    return result;
}

// A point light above a glass ball held over a diffuse floor. The ball (radius 0.4, centre
// 1.2 above the floor, the light 0.8 above its centre; paraxial focal length 0.6 from its
// centre) sends the light it catches towards a point 2.4 below its centre, so the floor
// holds a bright disc inside the ball's shadow. The camera sees that floor directly, under
// the ball.
inline std::string point_light_behind_glass(const std::string& settings) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 1.0, 3.5}}, look_at = {{0, 0, 0}}, fov = 30 }}
        glint.render{{ width = 32, height = 32, {} }}
        glint.quad{{ vertices = {{ {{-4, 0, 4}}, {{4, 0, 4}}, {{4, 0, -4}}, {{-4, 0, -4}} }},
                     material = glint.diffuse{{ reflectance = {{0.7, 0.6, 0.5}} }} }}
        glint.sphere{{ center = {{0, 1.2, 0}}, radius = 0.4, material = glint.dielectric{{ ior = 1.5 }} }}
        glint.point_light{{ position = {{0, 2, 0}}, intensity = {{2, 1.5, 1}} }}
    )",
                       settings);
}

// The pixels of a w x h `mask` whose 3 x 3 neighbourhood lies wholly inside it: away from
// the region's edge, where a pixel's samples would straddle it.
inline std::vector<bool> interior_of(const std::vector<bool>& mask, int w, int h) {
    std::vector<bool> interior(mask.size(), false);
    for (int y = 1; y + 1 < h; ++y) {
        for (int x = 1; x + 1 < w; ++x) {
            bool all = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    all = all && mask[static_cast<size_t>(y + dy) * w + x + dx];
            interior[static_cast<size_t>(y) * w + x] = all;
        }
    }
    return interior;
}

// Pixels whose camera rays (through the centre and the neighbours' centres, as for
// non_delta_mask) all hit the floor at points the ball hides from the point light: there
// the path tracer finds no direct light (its shadow rays stop at the glass, and a
// BSDF-sampled ray never hits a point), only the little that comes off the floor's lit
// part by way of the ball.
inline std::vector<bool> shadow_mask(const std::string& code, const Vec3& light) {
    const SceneDesc desc = load_scene_string(code, "shadow.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    const int w = settings.width, h = settings.height;
    std::vector<bool> shadowed(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Ray ray = scene->camera().generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            const std::optional<SurfaceInteraction> si = scene->intersect(ray);
            if (!si || std::abs(si->p.y) > 1e-3f) continue;  // not the floor
            const Vec3 p = si->p + Vec3(0.0f, 1e-3f, 0.0f);
            shadowed[static_cast<size_t>(y) * w + x] =
                scene->intersect(Ray{p, light - p, 0.0f, 1.0f}).has_value();
        }
    }
    return interior_of(shadowed, w, h);
}

// Per-channel means over `mask` of each image, as estimates with standard errors.
inline std::array<Estimate, 3> region_means(const std::vector<Image>& images,
                                            const std::vector<bool>& mask) {
    std::array<Estimate, 3> result;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> values;
        for (const Image& image : images) {
            double sum = 0.0;
            int count = 0;
            for (int y = 0; y < image.height; ++y) {
                for (int x = 0; x < image.width; ++x) {
                    if (!mask[static_cast<size_t>(y) * image.width + x]) continue;
                    sum += image.at(x, y, c);
                    ++count;
                }
            }
            values.push_back(sum / count);
        }
        result[c] = estimate(values, 1.0);
    }
    return result;
}

}  // namespace glint::test
