// Procedural textures: Perlin noise and its fractal sums against their documented bounds,
// the checkerboard's closed-form filter, object-space evaluation, wood and marble, and
// their scene-language parameters.
#include <glint/core/error.h>
#include <glint/material/texture/checker_texture.h>
#include <glint/material/texture/noise.h>
#include <glint/material/texture/registry.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/test_util.h>

#include <functional>
#include <random>
#include <thread>

using namespace glint;
using glint::test::error_of;

namespace {

Vec3 random_point(std::mt19937& rng, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    return Vec3(u(rng), u(rng), u(rng));
}

Vec3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    Vec3 d;
    do d = Vec3(n(rng), n(rng), n(rng));
    while (glm::length(d) < 1e-3f);
    return glm::normalize(d);
}

// Builds a texture through the registry, as a scene does.
struct TextureMaker {
    TextureTable table{".", true};

    std::unique_ptr<Texture> make(
        const std::string& type, std::initializer_list<std::pair<const char*, ParamValue>> values) {
        Params params(type, "test.lua:1");
        for (const auto& [name, value] : values) params.set(name, value);
        return make_texture(params, table);
    }
};

TextureContext at_object_point(const Vec3& p) {
    TextureContext ctx;
    ctx.p = ctx.p_object = p;
    return ctx;
}

TextureContext at_uv(float u, float v) {
    TextureContext ctx;
    ctx.uv = Vec2(u, v);
    return ctx;
}

void expect_spectrum_eq(const Rgb& a, const Rgb& b, float tolerance = 0.0f) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

ParamValue rgb(double r, double g, double b) {
    return std::vector<double>{r, g, b};
}

}  // namespace

// ----------------------------------------------------------------------------------------
// Noise

TEST(PerlinNoise, IsZeroAtLatticePoints) {
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> coordinate(-1000, 1000);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        ASSERT_EQ(perlin_noise(p), 0.0f) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(PerlinNoise, HandlesHugeAndNonFiniteCoordinates) {
    EXPECT_EQ(perlin_noise(Vec3(1e12f, -3e15f, 7e9f)), 0.0f);  // floats this large are integers
    EXPECT_EQ(perlin_noise(Vec3(kInfinity, 0.5f, 0.5f)), 0.0f);
    EXPECT_EQ(perlin_noise(Vec3(0.5f, std::nanf(""), 0.5f)), 0.0f);
    // Past int range the lattice still repeats every 256 cells.
    const float big = 68719476736.0f;  // 2^36, a multiple of 256
    EXPECT_EQ(fbm(Vec3(big, 0.3f, 0.7f), 3), fbm(Vec3(0.0f, 0.3f, 0.7f), 3));
    EXPECT_NE(fbm(Vec3(0.0f, 0.3f, 0.7f), 3), 0.0f);
}

// The value Perlin's Java reference implementation gives (ImprovedNoise.noise(3.14, 42, 7)).
TEST(PerlinNoise, MatchesPerlinsReferenceImplementation) {
    EXPECT_NEAR(perlin_noise(Vec3(3.14f, 42.0f, 7.0f)), 0.136919959f, 2e-6f);
}

TEST(PerlinNoise, StaysWithinItsBoundAndComesCloseToIt) {
    std::mt19937 rng(2);
    float largest = 0.0f;
    for (int i = 0; i < 1000000; ++i) {
        const float n = perlin_noise(random_point(rng, 300.0f));
        largest = std::max(largest, std::abs(n));
    }
    EXPECT_LE(largest, kNoiseBound);
    EXPECT_GT(largest, 0.95f);  // the bound is not a loose promise
}

TEST(PerlinNoise, IsPeriodicWith256) {
    std::mt19937 rng(3);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p = random_point(rng, 100.0f);
        EXPECT_NEAR(perlin_noise(p), perlin_noise(p + Vec3(256.0f, -256.0f, 512.0f)), 1e-4f);
    }
}

TEST(PerlinNoise, FractalSumsStayWithinTheirBounds) {
    std::mt19937 rng(4);
    std::uniform_int_distribution<int> octaves(1, 8);
    std::uniform_real_distribution<float> lacunarity(1.5f, 3.0f), gain(0.0f, 1.0f);
    for (int i = 0; i < 100000; ++i) {
        const Vec3 p = random_point(rng, 100.0f);
        const int o = octaves(rng);
        const float l = lacunarity(rng), g = gain(rng);
        const float f = fbm(p, o, l, g);
        const float t = turbulence(p, o, l, g);
        ASSERT_LE(std::abs(f), kNoiseBound);
        ASSERT_GE(t, 0.0f);
        ASSERT_LE(t, kNoiseBound);
    }
}

// |n(p) - n(q)| <= L |p - q| with the L derived in noise.cpp, and some pair of points
// comes within a few percent of it, so a wrong fade or gradient set would be caught.
TEST(PerlinNoise, IsLipschitzWithTheDerivedConstant) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> step(1e-3f, 1e-2f);
    float steepest = 0.0f;
    for (int i = 0; i < 1000000; ++i) {
        const Vec3 p = random_point(rng, 128.0f);
        const Vec3 q = p + step(rng) * random_direction(rng);
        const float distance = glm::length(q - p);  // as represented, after rounding
        const float slope = std::abs(perlin_noise(q) - perlin_noise(p)) / distance;
        ASSERT_LE(slope, kNoiseLipschitz * 1.001f) << p.x << " " << p.y << " " << p.z;
        steepest = std::max(steepest, slope);
    }
    // Random directions rarely line up with the steepest one: 1e6 pairs reach about 75%.
    // A cubic fade (slope 1.5 instead of 15/8) would stay near 60%.
    EXPECT_GT(steepest, 0.7f * kNoiseLipschitz);

    // The steepest point found for Perlin's table (noise.h): 95% of the bound.
    const Vec3 p(241.4665f, 233.4995f, 151.4789f);
    const float h = 1e-3f;
    const Vec3 gradient(perlin_noise(p + Vec3(h, 0, 0)) - perlin_noise(p - Vec3(h, 0, 0)),
                        perlin_noise(p + Vec3(0, h, 0)) - perlin_noise(p - Vec3(0, h, 0)),
                        perlin_noise(p + Vec3(0, 0, h)) - perlin_noise(p - Vec3(0, 0, h)));
    const float slope = glm::length(gradient) / (2.0f * h);
    EXPECT_GT(slope, 0.95f * kNoiseLipschitz);
    EXPECT_LE(slope, kNoiseLipschitz);
}

TEST(PerlinNoise, VariesWithMeanNearZero) {
    std::mt19937 rng(6);
    double sum = 0.0, sum_sq = 0.0, fbm_sum_sq = 0.0;
    const int count = 100000;
    for (int i = 0; i < count; ++i) {
        const Vec3 p = random_point(rng, 200.0f);
        const double n = perlin_noise(p);
        sum += n;
        sum_sq += n * n;
        const double f = fbm(p, 4);
        fbm_sum_sq += f * f;
    }
    const double mean = sum / count;
    const double variance = sum_sq / count - mean * mean;
    EXPECT_NEAR(mean, 0.0, 0.01);
    EXPECT_GT(variance, 0.02);  // standard deviation about 0.2
    EXPECT_GT(fbm_sum_sq / count, 0.01);
}

TEST(PerlinNoise, IsDeterministicAcrossCallsAndThreads) {
    std::mt19937 rng(7);
    std::vector<Vec3> points(20000);
    for (Vec3& p : points) p = random_point(rng, 50.0f);
    auto evaluate = [&](std::vector<float>& out) {
        out.resize(points.size());
        for (size_t i = 0; i < points.size(); ++i)
            out[i] = fbm(points[i], 6) + perlin_noise(points[i]);
    };
    std::vector<float> first, second, third;
    evaluate(first);
    std::thread a([&] { evaluate(second); });
    std::thread b([&] { evaluate(third); });
    a.join();
    b.join();
    EXPECT_EQ(first, second);
    EXPECT_EQ(first, third);
}

// ----------------------------------------------------------------------------------------
// Checker

TEST(CheckerTexture, ExactValuesIn2D) {
    TextureMaker maker;
    const Rgb even(0.9f, 0.5f, 0.1f), odd(0.1f, 0.2f, 0.3f);
    auto checker =
        maker.make("checker", {{"even", rgb(0.9, 0.5, 0.1)}, {"odd", rgb(0.1, 0.2, 0.3)}});
    expect_spectrum_eq(checker->eval(at_uv(0.5f, 0.5f)), even);
    expect_spectrum_eq(checker->eval(at_uv(1.5f, 0.5f)), odd);
    expect_spectrum_eq(checker->eval(at_uv(1.5f, 1.5f)), even);
    expect_spectrum_eq(checker->eval(at_uv(-0.5f, 0.5f)), odd);
    expect_spectrum_eq(checker->eval(at_uv(-0.5f, -0.5f)), even);

    // scale = squares per unit: (0.3, 0.1) * 4 = (1.2, 0.4) lies in square (1, 0).
    auto fine = maker.make("checker", {{"scale", 4.0}});
    expect_spectrum_eq(fine->eval(at_uv(0.3f, 0.1f)), Rgb(0.2f));
    expect_spectrum_eq(fine->eval(at_uv(0.3f, 0.3f)), Rgb(0.8f));
    EXPECT_EQ(fine->pattern(at_uv(0.3f, 0.1f)), 1.0f);
}

TEST(CheckerTexture, ExactValuesIn3DInObjectSpace) {
    TextureMaker maker;
    auto checker = maker.make("checker", {{"dimension", 3.0}});
    const Rgb even(0.8f), odd(0.2f);
    expect_spectrum_eq(checker->eval(at_object_point(Vec3(0.5f, 0.5f, 0.5f))), even);
    expect_spectrum_eq(checker->eval(at_object_point(Vec3(1.5f, 0.5f, 0.5f))), odd);
    expect_spectrum_eq(checker->eval(at_object_point(Vec3(1.5f, 1.5f, 0.5f))), even);
    expect_spectrum_eq(checker->eval(at_object_point(Vec3(1.5f, 1.5f, 1.5f))), odd);
    expect_spectrum_eq(checker->eval(at_object_point(Vec3(-0.5f, -0.5f, -0.5f))), odd);
    auto scaled = maker.make("checker", {{"dimension", 3.0}, {"scale", 2.0}});
    expect_spectrum_eq(scaled->eval(at_object_point(Vec3(0.75f, 0.25f, 0.25f))), odd);
}

TEST(CheckerTexture, OddFractionIsTheBoxAverageOfTheSquareWave) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> position(-20.0f, 20.0f), width(0.01f, 3.0f);
    for (int i = 0; i < 200; ++i) {
        const float x = position(rng), w = width(rng);
        // Midpoint rule over many samples: the average the closed form must give.
        const int samples = 20000;
        double covered = 0.0;
        for (int k = 0; k < samples; ++k) {
            const double t = x - w + 2.0 * w * (k + 0.5) / samples;
            covered += std::fmod(std::floor(t), 2.0) != 0.0 ? 1.0 : 0.0;
        }
        EXPECT_NEAR(checker_odd_fraction(x, w), covered / samples, 2e-3) << x << " " << w;
    }
    // A box of exactly one period covers half odd cells wherever it lies.
    EXPECT_NEAR(checker_odd_fraction(1234.37f, 1.0f), 0.5f, 1e-5f);
    // A tiny box far from any edge sees one cell only, even at large coordinates.
    EXPECT_NEAR(checker_odd_fraction(1001.5f, 1e-4f), 1.0f, 1e-3f);
    EXPECT_NEAR(checker_odd_fraction(1000.5f, 1e-4f), 0.0f, 1e-3f);
}

TEST(CheckerTexture, LargeFootprintAveragesTheColours) {
    TextureMaker maker;
    auto checker = maker.make("checker", {{"even", 1.0}, {"odd", rgb(0.0, 0.5, 0.25)}});
    const Rgb mean(0.5f, 0.75f, 0.625f);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> uv(-10.0f, 10.0f);
    for (int i = 0; i < 100; ++i) {
        TextureContext ctx = at_uv(uv(rng), uv(rng));
        ctx.dudx = 50.0f;
        ctx.dvdy = -37.0f;
        expect_spectrum_eq(checker->eval(ctx), mean, 1e-3f);
        // A footprint of exactly one period along s averages to the mean whatever t does.
        ctx.dudx = 1.0f;
        ctx.dvdy = 0.0f;
        expect_spectrum_eq(checker->eval(ctx), mean, 1e-5f);
    }
}

TEST(CheckerTexture, ZeroFootprintEqualsTheUnfilteredChecker) {
    TextureMaker maker;
    auto filtered = maker.make("checker", {});
    auto unfiltered = maker.make("checker", {{"filter", std::string("none")}});
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> uv(-10.0f, 10.0f);
    for (int i = 0; i < 1000; ++i) {
        TextureContext ctx = at_uv(uv(rng), uv(rng));
        const Rgb point = filtered->eval(ctx);
        EXPECT_TRUE(point == Rgb(0.8f) || point == Rgb(0.2f));
        ctx.dudx = ctx.dvdy = 3.0f;  // ignored without filtering
        EXPECT_EQ(point, unfiltered->eval(ctx));
    }
}

// ----------------------------------------------------------------------------------------
// Object space and placement

TEST(SolidTextures, FollowTheObjectNotTheWorld) {
    TextureMaker maker;
    std::vector<std::unique_ptr<Texture>> solids;
    solids.push_back(maker.make("noise", {}));
    solids.push_back(maker.make("fbm", {}));
    solids.push_back(maker.make("turbulence", {}));
    solids.push_back(maker.make("wood", {}));
    solids.push_back(maker.make("marble", {}));
    solids.push_back(maker.make("checker", {{"dimension", 3.0}}));
    std::mt19937 rng(11);
    for (const auto& texture : solids) {
        for (int i = 0; i < 100; ++i) {
            TextureContext ctx = at_object_point(random_point(rng, 3.0f));
            const Rgb value = texture->eval(ctx);
            const float scalar = texture->pattern(ctx);
            ctx.p += random_point(rng, 100.0f);  // the object moved; its own point did not
            EXPECT_EQ(texture->eval(ctx), value);
            EXPECT_EQ(texture->pattern(ctx), scalar);
        }
    }
}

// A translated sphere hit at the same place on itself shows the same wood.
TEST(SolidTextures, MovingAnInstanceMovesThePattern) {
    const std::string code = R"(
        local g = glint.group()
        g:sphere{ radius = 1, material = glint.diffuse{ reflectance = glint.texture.wood{} } }
        glint.place(g, glint.translate(OFFSET, 0, 0))
    )";
    TextureMaker maker;
    auto wood = maker.make("wood", {});
    std::vector<float> seen;
    for (const char* offset : {"0", "7.5"}) {
        std::string scene_code = code;
        scene_code.replace(scene_code.find("OFFSET"), 6, offset);
        const SceneDesc desc = load_scene_string(scene_code, "scene.lua", ".");
        const auto scene = build_scene(desc, parse_render_settings(nullptr));
        const float x = std::stof(offset);
        const auto hit = scene->intersect(Ray{Vec3(x + 0.3f, 0.2f, 5.0f), Vec3(0, 0, -1)});
        ASSERT_TRUE(hit.has_value());
        seen.push_back(wood->pattern(TextureContext(*hit)));
    }
    EXPECT_NEAR(seen[0], seen[1], 1e-4f);
}

TEST(SolidTextures, TransformAndScalePlaceThePattern) {
    TextureMaker maker;
    const Vec3 offset(0.7f, -1.3f, 2.1f);
    auto plain = maker.make("fbm", {});
    auto moved = maker.make("fbm", {{"transform", Transform::translate(offset)}});
    auto enlarged = maker.make("fbm", {{"transform", Transform::scale(Vec3(2.0f))}});
    auto finer = maker.make("fbm", {{"scale", 2.0}});
    auto stretched = maker.make("fbm", {{"scale", std::vector<double>{1, 4, 1}}});
    auto turned = maker.make("fbm", {{"transform", Transform::rotate(90.0f, Vec3(0, 0, 1))}});
    std::mt19937 rng(12);
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = random_point(rng, 2.0f);
        const float value = plain->pattern(at_object_point(p));
        // translate(offset) moves the pattern by +offset.
        EXPECT_NEAR(moved->pattern(at_object_point(p + offset)), value, 1e-4f);
        // scale(2) makes features twice as large; the `scale` frequency 2 half as large.
        EXPECT_NEAR(enlarged->pattern(at_object_point(2.0f * p)), value, 1e-4f);
        EXPECT_NEAR(finer->pattern(at_object_point(0.5f * p)), value, 1e-4f);
        EXPECT_NEAR(stretched->pattern(at_object_point(Vec3(p.x, 0.25f * p.y, p.z))), value, 1e-4f);
        // A quarter turn about z carries the pattern's x axis onto y.
        EXPECT_NEAR(turned->pattern(at_object_point(Vec3(-p.y, p.x, p.z))), value, 1e-4f);
    }
}

// ----------------------------------------------------------------------------------------
// Noise textures, wood and marble

TEST(NoiseTextures, ColourBetweenLowAndHighAndScalarIsThePattern) {
    TextureMaker maker;
    auto noise = maker.make("noise", {{"low", rgb(0.1, 0.2, 0.3)}, {"high", rgb(0.9, 0.4, 0.3)}});
    auto turbulent = maker.make("turbulence", {{"octaves", 3.0}, {"high", 2.0}});
    std::mt19937 rng(13);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 p = random_point(rng, 10.0f);
        const TextureContext ctx = at_object_point(p);
        EXPECT_EQ(noise->pattern(ctx), perlin_noise(p));
        const Rgb c = noise->eval(ctx);
        EXPECT_GE(c.r, 0.1f - 1e-6f);
        EXPECT_LE(c.r, 0.9f + 1e-6f);
        EXPECT_NEAR(c.r, 0.5f + 0.4f * perlin_noise(p), 1e-5f);  // 0 maps half-way
        EXPECT_NEAR(c.b, 0.3f, 1e-6f);
        EXPECT_EQ(turbulent->pattern(ctx), turbulence(p, 3));
        EXPECT_NEAR(turbulent->eval(ctx).g, 2.0f * turbulence(p, 3), 1e-5f);
    }
}

TEST(WoodTexture, StaysBetweenItsColours) {
    TextureMaker maker;
    const Rgb light(1.5f, 0.6f, 0.2f), dark(0.1f, 0.6f, 0.4f);
    auto wood = maker.make(
        "wood",
        {{"light", rgb(1.5, 0.6, 0.2)}, {"dark", rgb(0.1, 0.6, 0.4)}, {"noise_amount", 2.0}});
    std::mt19937 rng(14);
    float darkest = 0.0f, lightest = 1.0f;
    for (int i = 0; i < 100000; ++i) {
        const TextureContext ctx = at_object_point(random_point(rng, 5.0f));
        const float t = wood->pattern(ctx);
        ASSERT_GE(t, 0.0f);
        ASSERT_LE(t, 1.0f);
        darkest = std::max(darkest, t);
        lightest = std::min(lightest, t);
        const Rgb c = wood->eval(ctx);
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(c[k], std::min(light[k], dark[k]) - 1e-6f);
            ASSERT_LE(c[k], std::max(light[k], dark[k]) + 1e-6f);
        }
    }
    EXPECT_GT(darkest, 0.99f);  // both colours are reached
    EXPECT_LT(lightest, 0.01f);
}

TEST(WoodTexture, WithoutNoiseIsPeriodicInTheDistanceFromTheAxis) {
    TextureMaker maker;
    auto wood = maker.make("wood", {{"rings", 5.0}, {"noise_amount", 0.0}});
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> radius(0.0f, 3.0f), angle(0.0f, 2.0f * kPi),
        height(-5.0f, 5.0f);
    for (int i = 0; i < 1000; ++i) {
        const float r = radius(rng), phi = angle(rng), y = height(rng);
        auto at = [&](float rr, float h) {
            return wood->pattern(at_object_point(Vec3(rr * std::cos(phi), h, rr * std::sin(phi))));
        };
        EXPECT_NEAR(at(r, y), at(r + 0.2f, y), 2e-4f);  // one ring is 1/5
        EXPECT_NEAR(at(r, y), at(r, 0.0f), 1e-6f);      // the same all along the axis
    }
    // Light at each ring boundary, darkest half-way between.
    EXPECT_NEAR(wood->pattern(at_object_point(Vec3(0.4f, 0, 0))), 0.0f, 1e-5f);
    EXPECT_NEAR(wood->pattern(at_object_point(Vec3(0, 1, 0.5f))), 1.0f, 1e-5f);
}

TEST(MarbleTexture, StaysBetweenItsColoursAndVeinsFollowX) {
    TextureMaker maker;
    auto marble =
        maker.make("marble", {{"base", rgb(0.9, 0.9, 0.8)}, {"vein", rgb(0.1, 0.3, 0.8)}});
    std::mt19937 rng(16);
    float most_vein = 0.0f, least_vein = 1.0f;
    for (int i = 0; i < 100000; ++i) {
        const TextureContext ctx = at_object_point(random_point(rng, 5.0f));
        const float t = marble->pattern(ctx);
        ASSERT_GE(t, 0.0f);
        ASSERT_LE(t, 1.0f);
        most_vein = std::max(most_vein, t);
        least_vein = std::min(least_vein, t);
        const Rgb c = marble->eval(ctx);
        ASSERT_GE(c.r, 0.1f - 1e-6f);
        ASSERT_LE(c.r, 0.9f + 1e-6f);
        ASSERT_GE(c.g, 0.3f - 1e-6f);
        ASSERT_LE(c.g, 0.9f + 1e-6f);
        ASSERT_NEAR(c.b, 0.8f, 1e-6f);
    }
    EXPECT_GT(most_vein, 0.99f);
    EXPECT_LT(least_vein, 0.01f);

    // Without turbulence the veins are planes x = const, 2 pi / frequency apart.
    auto calm = maker.make("marble", {{"turbulence_amount", 0.0}, {"frequency", 4.0}});
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p = random_point(rng, 3.0f);
        const float value = calm->pattern(at_object_point(p));
        EXPECT_NEAR(calm->pattern(at_object_point(Vec3(p.x, 0, 0))), value, 1e-6f);
        EXPECT_NEAR(calm->pattern(at_object_point(p + Vec3(0.5f * kPi, 0, 0))), value, 1e-4f);
    }
}

// ----------------------------------------------------------------------------------------
// Scene language

TEST(ProceduralTexturesInLua, LoadAndBuild) {
    const SceneDesc desc = load_scene_string(R"(
        local wood = glint.texture.wood{ rings = 4, noise_amount = 0.3, light = {0.8, 0.6, 0.4},
                                         dark = 0.2, transform = glint.rotate(90, {1, 0, 0}) }
        local marble = glint.texture.marble{ frequency = 3, turbulence_amount = 4, octaves = 5,
                                             base = 0.9, vein = {0.1, 0.1, 0.2}, scale = 2 }
        local checker = glint.texture.checker{ even = 1, odd = 0, scale = 8 }
        local cubes = glint.texture.checker{ dimension = 3, scale = {2, 2, 2} }
        local bumps = glint.texture.fbm{ scale = 10, octaves = 4, lacunarity = 2.2, gain = 0.4 }
        local clouds = glint.texture.turbulence{ low = {0.2, 0.3, 0.8}, high = 1 }
        local grain = glint.texture.noise{ scale = 20, transform = glint.translate(1, 2, 3) }
        glint.sphere{ radius = 1, material = glint.diffuse{ reflectance = wood, bump = bumps } }
        glint.sphere{ center = {3, 0, 0}, material = glint.diffuse{ reflectance = marble } }
        glint.quad{ vertices = {{-5, -1, -5}, {-5, -1, 5}, {5, -1, 5}, {5, -1, -5}},
                    material = glint.diffuse{ reflectance = checker } }
        glint.box{ material = glint.diffuse{ reflectance = cubes } }
        glint.sphere{ center = {-3, 0, 0}, material = glint.diffuse{ reflectance = clouds } }
        glint.sphere{ center = {0, 3, 0}, material = glint.diffuse{ reflectance = grain } }
    )",
                                             "scene.lua", ".");
    ASSERT_EQ(desc.textures.size(), 7u);
    EXPECT_NO_THROW(build_scene(desc, parse_render_settings(nullptr)));

    // The Lua parameters reach the texture: the wood's rings, turned to run along z.
    TextureTable table(".", true);
    auto wood = make_texture(desc.textures[0], table);
    const Rgb light(0.8f, 0.6f, 0.4f);
    TextureMaker maker;
    auto reference = maker.make("wood", {{"rings", 4.0},
                                         {"noise_amount", 0.3},
                                         {"light", rgb(0.8, 0.6, 0.4)},
                                         {"dark", 0.2},
                                         {"transform", Transform::rotate(90, Vec3(1, 0, 0))}});
    std::mt19937 rng(17);
    for (int i = 0; i < 100; ++i) {
        const TextureContext ctx = at_object_point(random_point(rng, 2.0f));
        EXPECT_EQ(wood->eval(ctx), reference->eval(ctx));
    }
}

TEST(ProceduralTexturesInLua, ErrorsNameTheLineAndTheParameter) {
    struct Case {
        const char* code;
        const char* line;
        const char* words;
    };
    const Case cases[] = {
        {"local m = 1\nglint.texture.wood{ ringz = 4 }", "scene.lua:2:", "ringz"},
        {"\n\nglint.texture.marble{ vein = {-1, 0, 0} }", "scene.lua:3:", "'vein'"},
        {"glint.texture.checker{ odd = -0.5 }", "scene.lua:1:", "'odd'"},
        {"\nglint.texture.fbm{ high = {1, -2, 1} }", "scene.lua:2:", "'high'"},
        {"glint.texture.wood{ dark = {0, 0, -0.1} }", "scene.lua:1:", "'dark'"},
        {"glint.texture.checker{ dimension = 4 }", "scene.lua:1:", "'dimension'"},
        {"glint.texture.checker{ dimension = 3, filter = 'none' }", "scene.lua:1:", "filter"},
        {"glint.texture.noise{ octaves = 3 }", "scene.lua:1:", "octaves"},
        {"glint.texture.turbulence{ octaves = 0 }", "scene.lua:1:", "'octaves'"},
        {"glint.texture.fbm{ scale = 0 }", "scene.lua:1:", "'scale'"},
        {"glint.texture.wood{ rings = -1 }", "scene.lua:1:", "'rings'"},
        {"glint.texture.marble{ transform = 3 }", "scene.lua:1:", "'transform'"},
    };
    for (const Case& c : cases) {
        const std::string message = error_of([&] {
            const SceneDesc desc = load_scene_string(c.code, "scene.lua", ".");
            build_scene(desc, parse_render_settings(nullptr));
        });
        EXPECT_NE(message.find(c.line), std::string::npos) << c.code << "\n  gave: " << message;
        EXPECT_NE(message.find(c.words), std::string::npos) << c.code << "\n  gave: " << message;
    }
}
