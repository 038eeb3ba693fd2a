// The light tracer ("light"): it converges to the path tracer wherever both can see, finds
// the caustic of a point light behind glass that the path tracer cannot, and gives the
// same bits for any thread count.
//
// Comparisons between Monte Carlo images use bounds taken from the images' own noise:
// each integrator renders K images with independent seeds; the spread of the K values of
// a statistic (a block mean, a region mean) gives its standard error, with every
// correlation between pixels included (one light path splats to several pixels, so the
// pixels of a light-traced image are not independent).
#include <glint/core/arena.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/material/bsdf.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace glint;
using glint::test::read_text;
using glint::test::render_lua;

namespace {

// An example scene with its glint.render{...} call (output list included) replaced by
// `settings`: a second glint.render would be an error.
std::string example_with(const char* file, const std::string& settings) {
    const std::string code = read_text(std::string(GLINT_SOURCE_DIR "/examples/") + file);
    const size_t start = code.find("glint.render{");
    const size_t end = code.find('}', code.find('}', code.find("output", start)) + 1);
    return code.substr(0, start) + "glint.render{ " + settings + " }" + code.substr(end + 1);
}

// Pixels the light tracer can see as the path tracer does: those whose camera ray first
// hits a surface without delta lobes (or an area light). A specular vertex cannot connect
// to the lens, so a light-traced image shows mirrors and glass seen directly as black,
// and rays that escape would need lights at infinity (which it cannot see either). A pixel
// gathers light from its whole square, so the rays through the centres of its eight
// neighbours must hit such a surface too: that keeps out pixels that straddle an edge.
// The mask holds kScattering or kEmitter for a pixel kept (kEmitter where its own ray
// hits an area light), 0 for one left out.
constexpr uint8_t kScattering = 1, kEmitter = 2;
std::vector<uint8_t> non_delta_mask(const std::string& code) {
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
std::vector<Image> render_seeds(const std::function<std::string(int)>& scene, int k) {
    std::vector<Image> images;
    for (int seed = 1; seed <= k; ++seed) images.push_back(render_lua(scene(seed)));
    return images;
}

// A statistic of each of K independent images: its mean and the standard error of that mean.
struct Estimate {
    double mean = 0.0, se = 0.0;
};
Estimate estimate(const std::vector<double>& values, double scale) {
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

// Means over the masked pixels of a square block of `block` x `block` pixels (NaN for
// a block with fewer than a quarter of its pixels masked), per channel, and over the
// kScattering pixels of the mask (the last three entries). The region means leave out the
// lights seen directly: the path tracer sees them without noise and they are bright, so
// they would dilute a bias of the rest (the blocks keep them).
std::vector<double> masked_means(const Image& image, const std::vector<uint8_t>& mask, int block) {
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

Comparison compare(const std::vector<Image>& test, const std::vector<Image>& reference,
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

// Light and path tracing of `scene(integrator, spp, seed)` agree over the non-delta mask,
// and the same check rejects the light-traced images scaled by 1.03 (a 3 % bias).
void expect_light_converges_to_path(
    const std::function<std::string(const std::string&, int, int)>& scene, int light_spp,
    int path_spp) {
    constexpr int kImages = 8;
    constexpr int kBlock = 4;
    const std::vector<uint8_t> mask = non_delta_mask(scene("path", 1, 1));
    const auto light =
        render_seeds([&](int seed) { return scene("light", light_spp, seed); }, kImages);
    const auto path =
        render_seeds([&](int seed) { return scene("path", path_spp, seed); }, kImages);
    const Comparison same = compare(light, path, mask, kBlock);
    const Comparison biased = compare(light, path, mask, kBlock, 1.03);
    fmt::print("light vs path: {}\nlight x 1.03 vs path: {}\n", same.describe(), biased.describe());
    ASSERT_GT(same.pixels, static_cast<int>(mask.size() / 4));
    EXPECT_TRUE(same.mse_agrees()) << same.describe();
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same.means_agree(c)) << "channel " << c;
    EXPECT_FALSE(biased.agrees()) << "a 3 % bias passes: " << biased.describe();
}

}  // namespace

// (a) The Cornell box: diffuse everywhere, the light seen directly (its one emitting side).
TEST(LightTracer, ConvergesToPathOnTheCornellBox) {
    expect_light_converges_to_path(
        [](const std::string& integrator, int spp, int seed) {
            return example_with("cornell-box.lua",
                                fmt::format("width = 32, height = 32, spp = {}, seed = {}, "
                                            "integrator = '{}'",
                                            spp, seed, integrator));
        },
        128, 64);
}

// (b) A two-sided area light shines through a smooth glass slab onto a diffuse floor; the
// camera, under the slab, sees the floor directly (not through the glass), the slab's edge
// (masked out) and the light's lower side beside the slab. Light paths reach the floor
// through both faces of the slab (importance-mode refraction) and the two-sided light
// connects to the lens from the side sample_le chose.
TEST(LightTracer, ConvergesToPathUnderAGlassSlab) {
    expect_light_converges_to_path(
        [](const std::string& integrator, int spp, int seed) {
            return fmt::format(R"(
                glint.camera{{ eye = {{0, 0.7, 3.5}}, look_at = {{0, 0.25, 0}}, fov = 60 }}
                glint.render{{ width = 32, height = 32, spp = {}, seed = {}, integrator = '{}' }}
                glint.quad{{ vertices = {{ {{-4, 0, 4}}, {{4, 0, 4}}, {{4, 0, -4}}, {{-4, 0, -4}} }},
                             material = glint.diffuse{{ reflectance = {{0.7, 0.6, 0.5}} }} }}
                glint.box{{ min = {{-1.2, 0.8, -1.2}}, max = {{1.2, 1.0, 1.2}},
                            material = glint.dielectric{{ ior = 1.5 }} }}
                glint.quad{{ vertices = {{ {{-0.8, 1.6, -0.8}}, {{0.8, 1.6, -0.8}}, {{0.8, 1.6, 0.8}},
                                           {{-0.8, 1.6, 0.8}} }},
                             material = glint.emissive{{ radiance = {{3, 2.5, 2}}, two_sided = true }} }}
            )",
                               spp, seed, integrator);
        },
        64, 256);
}

// (c) The Cornell box with a glass and a mirror sphere: the spheres are masked out, but
// the walls and floor keep the caustic and the light reflected off the mirror.
TEST(LightTracer, ConvergesToPathOnTheCornellSpheres) {
    expect_light_converges_to_path(
        [](const std::string& integrator, int spp, int seed) {
            return example_with("cornell-spheres.lua",
                                fmt::format("width = 32, height = 32, spp = {}, seed = {}, "
                                            "integrator = '{}'",
                                            spp, seed, integrator));
        },
        128, 64);
}

namespace {

// A point light above a glass ball held over a diffuse floor. The ball (radius 0.4, centre
// 1.2 above the floor, the light 0.8 above its centre; paraxial focal length 0.6 from its
// centre) sends the light it catches towards a point 2.4 below its centre, so the floor
// holds a bright disc inside the ball's shadow. The camera sees that floor directly, under
// the ball.
std::string point_light_behind_glass(const std::string& settings) {
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

// Pixels whose camera rays (through the centre and the neighbours' centres, as for
// non_delta_mask) all hit the floor at points the ball hides from the point light: there
// the path tracer finds no direct light (its shadow rays stop at the glass, and a
// BSDF-sampled ray never hits a point), only the little that comes off the floor's lit
// part by way of the ball.
std::vector<bool> shadow_mask(const std::string& code, const Vec3& light) {
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
    std::vector<bool> mask(shadowed.size(), false);
    for (int y = 1; y + 1 < h; ++y) {
        for (int x = 1; x + 1 < w; ++x) {
            bool all = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    all = all && shadowed[static_cast<size_t>(y + dy) * w + x + dx];
            mask[static_cast<size_t>(y) * w + x] = all;
        }
    }
    return mask;
}

// Per-channel means over `mask` of each image, as estimates with standard errors.
std::array<Estimate, 3> region_means(const std::vector<Image>& images,
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

}  // namespace

// The caustic of a point light behind glass: invisible to the path tracer, seen by the light
// tracer and by SPPM, which must agree on it. SPPM is biased by its finite radius, which
// blurs the caustic (and the shadow's edge): over this region its mean moves by about 5 %
// between initial radii of 0.04 and 0.01 (0.099 -> 0.104 in red, 32 passes of 30000
// photons), so it may differ from the unbiased light tracer by 8 % of its value plus four
// standard errors of the difference.
TEST(LightTracer, SeesThePointLightCausticBehindGlassLikeSppm) {
    constexpr int kImages = 6;
    const Vec3 light(0.0f, 2.0f, 0.0f);
    const std::vector<bool> mask = shadow_mask(point_light_behind_glass("spp = 1"), light);
    const int pixels = static_cast<int>(std::count(mask.begin(), mask.end(), true));
    ASSERT_GE(pixels, 50);
    auto render = [&](const std::string& settings) {
        return region_means(
            render_seeds(
                [&](int seed) {
                    return point_light_behind_glass(fmt::format("seed = {}, {}", seed, settings));
                },
                kImages),
            mask);
    };
    const auto path = render("spp = 16, integrator = 'path'");
    const auto light_traced = render("spp = 256, integrator = 'light'");
    const auto sppm =
        render("spp = 32, integrator = 'sppm', photons = 30000, photon_radius = 0.01");
    for (int c = 0; c < 3; ++c) {
        const double noise = 4.0 * std::hypot(light_traced[c].se, sppm[c].se);
        fmt::print(
            "channel {} over {} pixels: path {:.4g}, light {:.4g} +- {:.2g}, sppm {:.4g} "
            "+- {:.2g}\n",
            c, pixels, path[c].mean, light_traced[c].mean, light_traced[c].se, sppm[c].mean,
            sppm[c].se);
        EXPECT_NEAR(light_traced[c].mean, sppm[c].mean, noise + 0.08 * sppm[c].mean)
            << "channel " << c;
        // "Black" for the path tracer: what reaches the shadow by way of the ball's
        // reflection is below 1 % of the caustic.
        EXPECT_GT(light_traced[c].mean, 100.0 * path[c].mean) << "channel " << c;
        EXPECT_GT(sppm[c].mean, 100.0 * path[c].mean) << "channel " << c;
    }
}

// Light paths are keyed by (seed, path index) and their splats reach the film in chunk
// order: the image is bit-identical for one and two threads. 48 x 48 x 64 paths are 36
// chunks of 4096, so two threads interleave many chunks.
TEST(LightTracer, ImageIsIdenticalForAnyThreadCount) {
    const std::string scene = example_with(
        "cornell-spheres.lua", "width = 48, height = 48, spp = 64, seed = 7, integrator = 'light'");
    const Image one = render_lua(scene, 1);
    const Image two = render_lua(scene, 2);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_TRUE(one.pixels == two.pixels);
}
