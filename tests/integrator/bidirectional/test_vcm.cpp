// Vertex connection and merging ("vcm"): analytic scenes, convergence to the path tracer,
// agreement with SPPM where only merging (the mirror caustic) or light subpaths (a point
// light behind glass) find the light, agreement with bdpt when the merging radius is tiny,
// the same bits for any thread count, and MIS weights over connections and merges that sum
// to one.
//
// Monte Carlo bounds come from the images' own noise (K renders with independent seeds), as
// in test_bdpt. Merging is biased by the kernel's blur; where that matters it is said below.
#include <glint/core/error.h>
#include <glint/integrator/bidirectional/bdpt.h>
#include <glint/integrator/bidirectional/bdpt_mis.h>
#include <glint/integrator/bidirectional/vcm.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/image_comparison.h>
#include <support/render_helpers.h>

#include <cmath>
#include <string>
#include <vector>

using namespace glint;
using namespace glint::test;

// test_bdpt's closed furnace: a diffuse sphere (albedo a) inside a sphere emitting Le inwards
// reflects exactly a Le. Merging has no bias here: the photons lie on a sphere, where the
// part within distance r of a point has area exactly pi r^2 (Archimedes), and the irradiance
// is uniform. What is left is the bias of the merges' weights, computed as if the photon lay
// at the camera vertex: it grows as r^2 and was measured as 1.4 % at a fixed r = 0.2 and
// 0.2 % at r = 0.05 (albedo 1, 256 iterations); r_0 = 0.05 shrinking, hence 0.3 % on top
// of the noise. Merges carry a few per cent of this image (eta = n pi r^2 = 2 for n = 16 x 16 light
// paths): the point light's furnace below is where merging is weighed.
namespace {

// The scene of the test below, with `extra` settings for glint.render.
std::string emitting_sphere(int seed, const std::string& extra) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 1.8}}, look_at = {{0, 0, 0}}, fov = 30 }}
        glint.render{{ width = 16, height = 16, spp = 32, seed = {}, integrator = 'vcm',
                      vcm_radius = 0.05 {} }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 3,
                      material = glint.emissive{{ radiance = 2, two_sided = true }} }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 1,
                      material = glint.diffuse{{ reflectance = {{0.8, 0.5, 0.2}} }} }}
    )",
                       seed, extra);
}

// Pixel variances of the two furnaces below (channel 1), measured at this commit.
constexpr double kRecordedEmittingVariance = 0.000320776;
constexpr double kRecordedPointVariance = 0.00526412;

void expect_emitting_sphere(const std::string& extra) {
    const double expected[3] = {1.6, 1.0, 0.4};
    for (int c = 0; c < 3; ++c) {
        const Estimate e = image_mean([&](int seed) { return emitting_sphere(seed, extra); }, 6, c);
        fmt::print("channel {}: {:.5f} +- {:.5f} (exact {})\n", c, e.mean, e.se, expected[c]);
        EXPECT_LT(4.0 * e.se, 0.01 * expected[c]);
        EXPECT_NEAR(e.mean, expected[c], 4.0 * e.se + 0.003 * expected[c]) << "channel " << c;
    }
}

// The scene of ClosedSphereAroundPointLightSumsEveryBounce, with `extra` settings.
std::string point_light_sphere(int seed, const std::string& extra) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 0}}, look_at = {{0, 0, -1}}, fov = 70 }}
        glint.render{{ width = 32, height = 32, spp = 16, seed = {}, integrator = 'vcm',
                      vcm_radius = 0.05 {} }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 1, material = glint.diffuse{{ reflectance = 0.5 }} }}
        glint.point_light{{ position = {{0, 0, 0}}, intensity = math.pi }}
    )",
                       seed, extra);
}

void expect_point_light_sphere(const std::string& extra, int images) {
    for (int c = 0; c < 3; c += 2) {
        const Estimate e =
            image_mean([&](int seed) { return point_light_sphere(seed, extra); }, images, c);
        fmt::print("channel {}: {:.5f} +- {:.5f} (exact 1)\n", c, e.mean, e.se);
        EXPECT_LT(4.0 * e.se, 0.01);
        EXPECT_NEAR(e.mean, 1.0, 4.0 * e.se + 0.003) << "channel " << c;
    }
}

}  // namespace

// test_bdpt's closed furnace: a diffuse sphere (albedo a) inside a sphere emitting Le inwards
// reflects exactly a Le. Merging has no bias here: the photons lie on a sphere, where the
// part within distance r of a point has area exactly pi r^2 (Archimedes), and the irradiance
// is uniform. What is left is the bias of the merges' weights, computed as if the photon lay
// at the camera vertex: it grows as r^2 and was measured as 1.4 % at a fixed r = 0.2 and
// 0.2 % at r = 0.05 (albedo 1, 256 iterations); r_0 = 0.05 shrinking, hence 0.3 % on top
// of the noise. Merges carry a few per cent of this image (eta = n pi r^2 = 2 for n = 16 x 16 light
// paths): the point light's furnace below is where merging is weighed.
TEST(Vcm, DiffuseSphereInsideAnEmittingSphere) {
    expect_emitting_sphere("");
}

// A point light of intensity pi at the centre of a closed diffuse sphere (radius 1, albedo
// 0.5): L = 1 everywhere, every bounce included. The irradiance is uniform on a sphere, so
// the kernel is unbiased here too; s = 0 cannot hit the point light, merging (eta = 8 for
// 32 x 32 light paths: about 40 % of the image) and connections share the rest. The merges'
// weights leave a bias of -0.2 % (measured), within the 0.3 % allowed as above.
TEST(VcmSlow, ClosedSphereAroundPointLightSumsEveryBounce) {
    expect_point_light_sphere("", 6);
}

// Both furnaces with 4 times as many light subpaths as pixels and a quarter as many: the
// merges' kernel and eta, light tracing's count and the splats' scale follow n_L (with 4x,
// merging takes about 70 % of the point light's image, with 1/4 about 15 %).
TEST(Vcm, EmittingSphereFurnaceWithMoreOrFewerLightSubpaths) {
    expect_emitting_sphere(", vcm_light_paths = 1024");
    expect_emitting_sphere(", vcm_light_paths = 64");
}

TEST(VcmSlow, PointLightFurnaceWithMoreLightSubpaths) {
    expect_point_light_sphere(", vcm_light_paths = 4096", 4);
}

TEST(VcmSlow, PointLightFurnaceWithFewerLightSubpaths) {
    expect_point_light_sphere(", vcm_light_paths = 256", 6);
}

// The furnaces' pixel noise (green), recorded when the merge weights were right (issue 28:
// with the merges' weight doubled the image stayed unbiased and only a precondition on the
// image means' spread, at 0.0161 against 0.016, caught it). A quarter more noise than
// recorded fails; the estimate itself is known to a few per cent (256 and 1024 pixels).
TEST(Vcm, FurnaceNoiseStaysAtItsRecordedLevel) {
    const double emitting = pixel_variance([](int seed) { return emitting_sphere(seed, ""); }, 1);
    const double point = pixel_variance([](int seed) { return point_light_sphere(seed, ""); }, 1);
    fmt::print("pixel variance: emitting sphere {:.6g}, point light {:.6g}\n", emitting, point);
    EXPECT_LT(emitting, 1.25 * kRecordedEmittingVariance);
    EXPECT_LT(point, 1.25 * kRecordedPointVariance);
}

namespace {

std::string example(const char* file, const std::string& settings) {
    return example_with_settings(file, "width = 32, height = 32, " + settings);
}

// `test` and `reference` agree over every pixel of 8 renders each, and the same check
// rejects `test` scaled by 1.03 (a 3 % bias).
void expect_converges(const std::function<std::string(int)>& test,
                      const std::function<std::string(int)>& reference, const char* what) {
    constexpr int kImages = 8;
    constexpr int kBlock = 4;
    const auto a = render_seeds(test, kImages);
    const auto b = render_seeds(reference, kImages);
    const std::vector<uint8_t> mask(static_cast<size_t>(a[0].width) * a[0].height, kScattering);
    const Comparison same = compare(a, b, mask, kBlock);
    const Comparison biased = compare(a, b, mask, kBlock, 1.03);
    fmt::print("{}: {}\nx 1.03: {}\n", what, same.describe(), biased.describe());
    EXPECT_TRUE(same.mse_agrees()) << same.describe();
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same.means_agree(c)) << "channel " << c;
    EXPECT_FALSE(biased.agrees()) << "a 3 % bias passes: " << biased.describe();
}

void expect_vcm_converges_to_path(const char* file, const std::string& extra = "", int spp = 32) {
    expect_converges(
        [&](int seed) {
            return example(
                file, fmt::format("spp = {}, seed = {}, integrator = 'vcm'{}", spp, seed, extra));
        },
        [&](int seed) {
            return example(file, fmt::format("spp = 64, seed = {}, integrator = 'path'", seed));
        },
        "vcm vs path");
}

}  // namespace

// The default radius (1/256 of the scene's diagonal) at 32 x 32: merges take a few per cent
// of the diffuse light and blur it over about a tenth of a pixel, far below the noise.
TEST(VcmSlow, ConvergesToPathOnTheCornellBox) {
    expect_vcm_converges_to_path("cornell-box.lua");
}

// Glass and mirror spheres: delta lobes seen directly, caustics on the floor (where merging
// and connections share the paths).
TEST(VcmSlow, ConvergesToPathOnTheCornellSpheres) {
    expect_vcm_converges_to_path("cornell-spheres.lua");
}

// 4 times as many light subpaths as pixels (32 x 32) and a quarter as many: with 4x, every
// pixel connects to one of the first 1024 subpaths and the rest only merge and join the
// lens; with 1/4, each subpath serves 4 pixels 8 rows apart. 4x costs about 3 times as much
// per iteration: 12 iterations, and the bound follows the noise.
TEST(VcmSlow, ConvergesToPathOnTheCornellSpheresWithMoreLightSubpaths) {
    expect_vcm_converges_to_path("cornell-spheres.lua", ", vcm_light_paths = 4096", 12);
}

TEST(VcmSlow, ConvergesToPathOnTheCornellSpheresWithFewerLightSubpaths) {
    expect_vcm_converges_to_path("cornell-spheres.lua", ", vcm_light_paths = 256");
}

// With a merging radius far below a pixel's footprint merges get almost no weight: vcm is
// bdpt with its light subpaths traced apart, and the two agree.
TEST(VcmSlow, WithATinyRadiusAgreesWithBdpt) {
    expect_converges(
        [](int seed) {
            return example(
                "cornell-spheres.lua",
                fmt::format("spp = 16, seed = {}, integrator = 'vcm', vcm_radius = 1e-5", seed));
        },
        [](int seed) {
            return example("cornell-spheres.lua",
                           fmt::format("spp = 16, seed = {}, integrator = 'bdpt'", seed));
        },
        "vcm (tiny radius) vs bdpt");
}

namespace {

// examples/mirror-caustic.lua at 32 x 32.
std::string mirror_caustic(const std::string& settings) {
    return example_with_settings("mirror-caustic.lua", "width = 32, height = 32, " + settings);
}

// Pixels whose camera rays (through the centre and the neighbours' centres) hit the mirror,
// and, reflected, the floor at a point the ball hides from the light at `light`: all the
// light there comes by the glass, a diffuse bounce and the mirror.
std::vector<bool> mirrored_shadow_mask(const std::string& code, const Vec3& light) {
    const SceneDesc desc = load_scene_string(code, "mirror.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    const int w = settings.width, h = settings.height;
    std::vector<bool> shadowed(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Ray ray = scene->camera().generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            const std::optional<SurfaceInteraction> mirror = scene->intersect(ray);
            if (!mirror || std::abs(mirror->p.z + 1.2f) > 1e-3f) continue;  // not the mirror
            Vec3 d = glm::normalize(ray.direction);
            d.z = -d.z;
            const Vec3 origin = mirror->p + Vec3(0.0f, 0.0f, 1e-3f);
            const std::optional<SurfaceInteraction> floor = scene->intersect(Ray{origin, d});
            if (!floor || std::abs(floor->p.y) > 1e-3f) continue;
            const Vec3 p = floor->p + Vec3(0.0f, 1e-3f, 0.0f);
            shadowed[static_cast<size_t>(y) * w + x] =
                scene->intersect(Ray{p, light - p, 0.0f, 1.0f}).has_value();
        }
    }
    return interior_of(shadowed, w, h);
}

std::array<Estimate, 3> mirror_region(const std::vector<bool>& mask, const std::string& settings,
                                      int images) {
    return region_means(
        render_seeds(
            [&](int seed) { return mirror_caustic(fmt::format("seed = {}, {}", seed, settings)); },
            images),
        mask);
}

}  // namespace

// The caustic of a point light through a glass ball, seen in a mirror (point light, glass,
// floor, mirror, lens): only merging finds it. vcm agrees with SPPM there (within the noise
// and 8 % for SPPM's blur, as in test_bdpt), and bdpt, which has no strategy for such a path,
// leaves the region black: we assert it holds less than 1 % of vcm's light.
TEST(VcmSlow, SeesTheCausticInAMirrorLikeSppm) {
    const Vec3 light(0.0f, 2.0f, 0.0f);
    const std::vector<bool> mask = mirrored_shadow_mask(mirror_caustic("spp = 1"), light);
    ASSERT_GE(std::count(mask.begin(), mask.end(), true), 8);
    const auto vcm = mirror_region(mask, "spp = 16, integrator = 'vcm'", 6);
    const auto bdpt = mirror_region(mask, "spp = 16, integrator = 'bdpt'", 2);
    const auto sppm = mirror_region(
        mask, "spp = 16, integrator = 'sppm', photons = 30000, photon_radius = 0.02", 6);
    for (int c = 0; c < 3; ++c) {
        fmt::print("channel {}: bdpt {:.4g}, vcm {:.4g} +- {:.2g}, sppm {:.4g} +- {:.2g}\n", c,
                   bdpt[c].mean, vcm[c].mean, vcm[c].se, sppm[c].mean, sppm[c].se);
        const double noise = 4.0 * std::hypot(vcm[c].se, sppm[c].se);
        EXPECT_NEAR(vcm[c].mean, sppm[c].mean, noise + 0.08 * sppm[c].mean) << "channel " << c;
        EXPECT_LT(bdpt[c].mean, 0.01 * vcm[c].mean) << "channel " << c;
    }
}

// test_bdpt's point light behind a glass ball, seen directly: black for the path tracer,
// found by vcm's light subpaths and merges, as by SPPM.
TEST(VcmSlow, SeesThePointLightCausticBehindGlassLikeSppm) {
    constexpr int kImages = 6;
    const Vec3 light(0.0f, 2.0f, 0.0f);
    const std::vector<bool> mask = shadow_mask(point_light_behind_glass("spp = 1"), light);
    ASSERT_GE(std::count(mask.begin(), mask.end(), true), 50);
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
    const auto vcm = render("spp = 32, integrator = 'vcm'");
    const auto sppm =
        render("spp = 32, integrator = 'sppm', photons = 30000, photon_radius = 0.01");
    for (int c = 0; c < 3; ++c) {
        fmt::print("channel {}: path {:.4g}, vcm {:.4g} +- {:.2g}, sppm {:.4g} +- {:.2g}\n", c,
                   path[c].mean, vcm[c].mean, vcm[c].se, sppm[c].mean, sppm[c].se);
        const double noise = 4.0 * std::hypot(vcm[c].se, sppm[c].se);
        EXPECT_NEAR(vcm[c].mean, sppm[c].mean, noise + 0.08 * sppm[c].mean) << "channel " << c;
        EXPECT_GT(vcm[c].mean, 100.0 * path[c].mean) << "channel " << c;
    }
}

// The same with more light subpaths than pixels (9316 for 48 x 48 x 4: a last chunk partly
// filled) and fewer (1000, shared by pixels).
TEST(Vcm, ImageIsIdenticalForAnyThreadCountWithMoreOrFewerLightSubpaths) {
    for (int n : {9316, 1000}) {
        const std::string scene = example_with_settings(
            "cornell-spheres.lua",
            fmt::format("width = 48, height = 48, spp = 2, seed = 7, integrator = 'vcm', "
                        "vcm_light_paths = {}",
                        n));
        const Image one = render_lua(scene, 1);
        const Image two = render_lua(scene, 2);
        ASSERT_EQ(one.pixels.size(), two.pixels.size());
        EXPECT_TRUE(one.pixels == two.pixels) << n << " light subpaths";
    }
}

// One light subpath per pixel, given explicitly, is the default bit for bit (the splats'
// scale, eta and the kernel are computed from n_L as they were from the pixel count).
TEST(Vcm, OneLightSubpathPerPixelIsTheDefault) {
    const std::string settings = "width = 24, height = 20, spp = 3, seed = 5, integrator = 'vcm'";
    const Image plain = render_lua(example_with_settings("cornell-spheres.lua", settings), 2);
    const Image given = render_lua(
        example_with_settings("cornell-spheres.lua", settings + ", vcm_light_paths = 480"), 2);
    ASSERT_EQ(plain.pixels.size(), given.pixels.size());
    EXPECT_TRUE(plain.pixels == given.pixels);
}

TEST(Vcm, RadiusShrinksWithAlpha) {
    EXPECT_FLOAT_EQ(VcmIntegrator::radius_at(0.1f, 0.75f, 0), 0.1f);
    EXPECT_NEAR(VcmIntegrator::radius_at(0.1f, 0.75f, 15), 0.1 * std::pow(16.0, -0.125), 1e-7);
    EXPECT_FLOAT_EQ(VcmIntegrator::radius_at(0.1f, 1.0f, 99), 0.1f);
}

TEST(Vcm, RejectsBadSettings) {
    for (const char* bad :
         {"vcm_radius = -1", "vcm_alpha = 0", "vcm_alpha = 1.5", "vcm_light_paths = -1",
          "vcm_light_paths = 16777217", "vcm_light_paths = 2.5"}) {
        const std::string code = fmt::format(
            "glint.camera{{ eye = {{0, 0, 1}}, look_at = {{0, 0, 0}} }}\n"
            "glint.render{{ width = 4, height = 4, integrator = 'vcm', {} }}",
            bad);
        EXPECT_THROW(render_lua(code), Error) << bad;
    }
}

// The weights of every connection and every merge that can make a path sum to 1, for both
// heuristics, on paths of 3 to 5 vertices, with a delta vertex (no connection next to it, no
// merge at it) and with a delta light; with eta = 0 they are bdpt's.
TEST(VcmMis, WeightsOfConnectionsAndMergesSumToOne) {
    const std::vector<MisVertex> five = {{0.3f, 2.0f, false},
                                         {1.7f, 0.4f, false},
                                         {0.05f, 3.0f, false},
                                         {2.5f, 0.9f, false},
                                         {1.0f, 1.0f, false}};
    auto total = [](const std::vector<MisVertex>& path, bool delta_light, float eta, MisHeuristic h,
                    float count = 1.0f) {
        const int k = static_cast<int>(path.size());
        double sum = 0.0;
        for (int s = 0; s < k; ++s) {
            const bool possible = s == 0 ? !delta_light : !path[s].delta && !path[s - 1].delta;
            if (possible) sum += vcm_strategy_weight(path, s, false, delta_light, eta, h, count);
            if (s >= 1 && s <= k - 2 && !path[s].delta)
                sum += vcm_strategy_weight(path, s, true, delta_light, eta, h, count);
        }
        return sum;
    };
    for (MisHeuristic h : {MisHeuristic::kBalance, MisHeuristic::kPower}) {
        for (float eta : {0.01f, 0.7f, 30.0f}) {
            for (size_t k = 3; k <= five.size(); ++k) {
                const std::vector<MisVertex> path(five.end() - k, five.end());
                EXPECT_NEAR(total(path, false, eta, h), 1.0, 1e-6) << k << " vertices";
            }
            std::vector<MisVertex> mirrored = five;
            mirrored[2] = {0.0f, 0.0f, true};
            mirrored[3].pdf_light = 0.0f;  // reached through the delta lobe
            mirrored[1].pdf_camera = 0.0f;
            EXPECT_NEAR(total(mirrored, false, eta, h), 1.0, 1e-6) << "with a delta vertex";
            EXPECT_NEAR(total(five, true, eta, h), 1.0, 1e-6) << "with a delta light";
        }
        for (int s = 0; s < 5; ++s)
            EXPECT_EQ(vcm_strategy_weight(five, s, false, false, 0.0f, h),
                      strategy_weight(five, s, false, h));
    }
    // n_L / n_C light subpaths per camera subpath: light tracing (s = k - 1) counts n_L / n_C,
    // the rest as before, and the weights still sum to 1.
    for (MisHeuristic h : {MisHeuristic::kBalance, MisHeuristic::kPower}) {
        for (float count : {0.25f, 1.0f, 4.0f, 8.0f}) {
            for (float eta : {0.0f, 0.7f, 30.0f}) {
                for (size_t k = 2; k <= five.size(); ++k) {
                    const std::vector<MisVertex> path(five.end() - k, five.end());
                    EXPECT_NEAR(total(path, false, eta, h, count), 1.0, 1e-6)
                        << k << " vertices, count " << count;
                }
                std::vector<MisVertex> mirrored = five;
                mirrored[2] = {0.0f, 0.0f, true};
                mirrored[3].pdf_light = 0.0f;
                mirrored[1].pdf_camera = 0.0f;
                EXPECT_NEAR(total(mirrored, false, eta, h, count), 1.0, 1e-6) << count;
                EXPECT_NEAR(total(five, true, eta, h, count), 1.0, 1e-6) << count;
            }
        }
    }
    // Equal densities and eta = 1: the connection at x_1 and the merge there share equally
    // with the connection at x_2 (three strategies for a three-vertex path, one merge).
    const std::vector<MisVertex> even = {
        {1.0f, 1.0f, false}, {1.0f, 1.0f, false}, {1.0f, 1.0f, false}};
    EXPECT_NEAR(vcm_strategy_weight(even, 1, true, false, 1.0f, MisHeuristic::kBalance), 1.0 / 4.0,
                1e-6);
    // With 4 light subpaths per camera subpath light tracing (s = 2) counts 4 against the
    // other connections' 1 and the merge's eta = 1: 4 / 7, and the merge 1 / 7.
    EXPECT_NEAR(vcm_strategy_weight(even, 2, false, false, 1.0f, MisHeuristic::kBalance, 4.0f),
                4.0 / 7.0, 1e-6);
    EXPECT_NEAR(vcm_strategy_weight(even, 1, true, false, 1.0f, MisHeuristic::kBalance, 4.0f),
                1.0 / 7.0, 1e-6);
}

// The weights vcm computes from real subpaths in the Cornell box: for the path light[0, 2)
// joined to camera[0, 3) by the merge at camera vertex 2, merge_mis_weight's array holds
// finite densities and the weights of every connection and merge over it sum to 1.
TEST(VcmMis, StrategiesOfARealMergedPathSumToOne) {
    const SceneDesc desc = load_scene_string(
        example_with_settings("cornell-box.lua", "width = 32, height = 32, spp = 1"), "cb.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    auto sampler = make_sampler("independent", 256, 11);
    Arena arena;
    RayCounter counter;
    std::vector<PathVertex> camera, light;
    std::vector<MisVertex> scratch;
    int checked = 0;
    for (int attempt = 0; attempt < 200 && checked < 20; ++attempt) {
        sampler->start_pixel_sample(Vec2i(attempt % 32, 16), attempt);
        const Ray ray = scene->camera().generate_ray(Vec2(attempt % 32 + 0.5f, 16.5f), Vec2(0.5f));
        generate_camera_subpath(*scene, ray, *sampler, arena, counter, WalkLimits{4, false},
                                camera);
        generate_light_subpath(*scene, ray.time, *sampler, arena, counter, WalkLimits{3, false},
                               light);
        if (camera.size() < 3 || light.size() < 2 || !camera[2].connectible()) continue;
        // eta such that the merge at x_2 weighs as much as the connection there (the box's
        // densities per area are small in its units).
        merge_mis_weight(*scene, std::span(light).first(2), camera, 2, 3, 1.0f,
                         MisHeuristic::kBalance, scratch);
        if (!(scratch[2].pdf_light > 0.0f)) continue;
        const float eta = 1.0f / scratch[2].pdf_light;
        const float w = merge_mis_weight(*scene, std::span(light).first(2), camera, 2, 3, eta,
                                         MisHeuristic::kBalance, scratch);
        EXPECT_GT(w, 0.0f);
        ASSERT_EQ(scratch.size(), 5u);
        for (const MisVertex& v : scratch)
            EXPECT_TRUE(std::isfinite(v.pdf_light) && std::isfinite(v.pdf_camera));
        double sum = 0.0;
        for (int s = 0; s < 5; ++s) {
            sum += vcm_strategy_weight(scratch, s, false, false, eta, MisHeuristic::kBalance);
            if (s >= 1 && s <= 3)
                sum += vcm_strategy_weight(scratch, s, true, false, eta, MisHeuristic::kBalance);
        }
        EXPECT_NEAR(sum, 1.0, 1e-5);
        ++checked;
    }
    EXPECT_GE(checked, 5);
}
