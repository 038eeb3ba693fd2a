// Image textures (mipmap.h), texture mappings, pixel footprints from ray differentials,
// and what mipmapping buys at grazing angles.
#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/transport/shading.h>
#include <glint/material/texture/image_texture.h>
#include <glint/material/texture/mapping.h>
#include <glint/material/texture/texture_table.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

using namespace glint;
using glint::test::TempDir;

namespace {

// A checkerboard of `squares` x `squares` squares of `size` pixels, values lo and hi.
Image checker_image(int squares, int size, float lo, float hi) {
    const int n = squares * size;
    Image image = make_image(n, n, {"R", "G", "B"});
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const float v = ((x / size + y / size) % 2 == 0) ? lo : hi;
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = v;
        }
    }
    return image;
}

TextureContext context_at(float u, float v) {
    TextureContext ctx;
    ctx.uv = Vec2(u, v);
    return ctx;
}

std::unique_ptr<Texture> load(const std::string& path, TextureTable& table,
                              const std::string& wrap = "repeat",
                              TextureEncoding encoding = TextureEncoding::kAuto) {
    ImageTextureOptions options;
    options.wrap = wrap;
    options.filter = "none";
    options.encoding = encoding;
    return load_image_texture(path, options, TextureMapping2D(), table);
}

}  // namespace

// Row 0 of an image is the top: v = 1. Pixel centres come back exactly with a point
// footprint; 8-bit files are sRGB-decoded, EXR files are linear.
TEST(ImageTexture, PixelsLandWhereUvSaysAndEncodingsDecode) {
    TempDir dir;
    Image image = make_image(2, 2, {"R", "G", "B"});
    const float values[2][2] = {{0.1f, 0.2f}, {0.6f, 0.9f}};  // [row][column]
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = values[y][x];
    write_image(dir.file("t.exr"), image);
    write_image(dir.file("t.png"), image);  // sRGB-encoded by write_image
    TextureTable table(".", true);
    const auto exr = load(dir.file("t.exr"), table);
    const auto png = load(dir.file("t.png"), table);
    const float u[2] = {0.25f, 0.75f}, v[2] = {0.75f, 0.25f};  // v of row 0 and row 1
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x) {
            EXPECT_NEAR(exr->eval(context_at(u[x], v[y])).g, values[y][x], 1e-6) << x << y;
            EXPECT_NEAR(png->eval(context_at(u[x], v[y])).g, values[y][x], 0.01) << x << y;
        }
    }
    // Read as linear, the PNG gives its encoded values back (brighter than linear).
    const auto raw = load(dir.file("t.png"), table, "repeat", TextureEncoding::kLinear);
    EXPECT_GT(raw->eval(context_at(0.25f, 0.75f)).g, 0.3f);
}

TEST(ImageTexture, WrapModes) {
    TempDir dir;
    Image image = make_image(4, 1, {"R", "G", "B"});
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) image.at(x, 0, c) = 0.1f + 0.2f * x;  // 0.1 .. 0.7
    write_image(dir.file("ramp.exr"), image);
    TextureTable table(".", true);
    const auto repeat = load(dir.file("ramp.exr"), table, "repeat");
    const auto clamp = load(dir.file("ramp.exr"), table, "clamp");
    const auto mirror = load(dir.file("ramp.exr"), table, "mirror");
    // u = 1.125 is texel 0 when repeating, the last texel when clamping, and texel 3
    // reflected back (the last one) when mirroring; u = 1.375 mirrors to texel 2.
    EXPECT_NEAR(repeat->eval(context_at(1.125f, 0.5f)).r, 0.1f, 1e-5);
    EXPECT_NEAR(clamp->eval(context_at(1.125f, 0.5f)).r, 0.7f, 1e-5);
    EXPECT_NEAR(mirror->eval(context_at(1.125f, 0.5f)).r, 0.7f, 1e-5);
    EXPECT_NEAR(mirror->eval(context_at(1.375f, 0.5f)).r, 0.5f, 1e-5);
    EXPECT_NEAR(repeat->eval(context_at(-0.875f, 0.5f)).r, 0.1f, 1e-5);
}

// With a footprint covering the whole texture, a mipmapped lookup returns its mean;
// without mipmapping it returns a single texel.
TEST(ImageTexture, LargeFootprintAveragesOnlyWithMipmaps) {
    TempDir dir;
    write_image(dir.file("checker.exr"), checker_image(8, 4, 0.0f, 1.0f));
    for (const bool mipmapping : {true, false}) {
        TextureTable table(".", mipmapping);
        ImageTextureOptions options;
        const auto texture =
            load_image_texture(dir.file("checker.exr"), options, TextureMapping2D(), table);
        TextureContext ctx = context_at(0.3f, 0.3f);
        ctx.dudx = ctx.dvdy = 1.0f;
        const float value = texture->eval(ctx).r;
        if (mipmapping)
            EXPECT_NEAR(value, 0.5f, 0.02f);
        else
            EXPECT_TRUE(value < 0.01f || value > 0.99f) << value;
    }
}

TEST(TextureMapping, ProjectionsAndTiling) {
    auto params = [](const std::string& mapping) {
        Params p("image", "test.lua:1");
        p.set("mapping", mapping);
        return p;
    };
    TextureContext ctx;
    ctx.p_object = Vec3(0.25f, 2.0f, -0.5f);
    const TexCoord2D planar = read_mapping_2d(params("planar")).map(ctx);
    EXPECT_FLOAT_EQ(planar.st.x, 0.25f);
    EXPECT_FLOAT_EQ(planar.st.y, -0.5f);

    ctx.p_object = Vec3(0.0f, 1.0f, 0.0f);  // north pole: t = 1
    EXPECT_NEAR(read_mapping_2d(params("spherical")).map(ctx).st.y, 1.0f, 1e-6);
    ctx.p_object = Vec3(0.0f, 0.0f, 1.0f);  // on the equator, a quarter turn round
    const TexCoord2D spherical = read_mapping_2d(params("spherical")).map(ctx);
    EXPECT_NEAR(spherical.st.x, 0.25f, 1e-6);
    EXPECT_NEAR(spherical.st.y, 0.5f, 1e-6);
    ctx.p_object = Vec3(-1.0f, 3.0f, 0.0f);
    const TexCoord2D cylindrical = read_mapping_2d(params("cylindrical")).map(ctx);
    EXPECT_NEAR(cylindrical.st.x, 0.5f, 1e-6);
    EXPECT_NEAR(cylindrical.st.y, 3.0f, 1e-6);

    Params tiled("image", "test.lua:1");
    tiled.set("scale", 4.0);
    tiled.set("offset", std::vector<double>{0.5, 0.0});
    TextureContext uv_ctx = context_at(0.1f, 0.2f);
    uv_ctx.dudx = 0.01f;
    const TexCoord2D t = read_mapping_2d(tiled).map(uv_ctx);
    EXPECT_NEAR(t.st.x, 0.9f, 1e-6);
    EXPECT_NEAR(t.st.y, 0.8f, 1e-6);
    EXPECT_NEAR(t.dsdx, 0.04f, 1e-7);

    Params bad("image", "test.lua:7");
    bad.set("mapping", std::string("cubic"));
    EXPECT_THROW(read_mapping_2d(bad), Error);
}

// A camera ray's differentials span one pixel on a plane facing the camera: at distance d
// a pixel is 2 d tan(fov / 2) / height wide. The approximation used after a bounce agrees.
TEST(Footprint, CameraDifferentialsSpanOnePixel) {
    const float fov = 40.0f, distance = 5.0f;
    const int height = 100;
    PerspectiveCamera camera(Vec3(0, 0, distance), Vec3(0, 0, 0), Vec3(0, 1, 0), fov,
                             Vec2i(200, height), 0.0f, distance);
    const Ray ray = camera.generate_ray(Vec2(100.0f, 50.0f), Vec2(0.5f));
    ASSERT_TRUE(ray.has_differentials);
    SurfaceInteraction si;
    si.p = Vec3(0.0f);
    si.ng = Vec3(0, 0, 1);
    si.dpdu = Vec3(2, 0, 0);  // a quad 2 units wide with u across it
    si.dpdv = Vec3(0, 2, 0);
    ASSERT_TRUE(footprint_from_differentials(ray, si));
    const float pixel = 2.0f * distance * std::tan(glm::radians(fov) * 0.5f) / height;
    EXPECT_NEAR(glm::length(si.dpdx), pixel, 1e-3f * pixel);
    EXPECT_NEAR(glm::length(si.dpdy), pixel, 1e-3f * pixel);
    EXPECT_NEAR(si.dudx, pixel / 2.0f, 1e-3f * pixel);
    EXPECT_NEAR(si.dvdy, -pixel / 2.0f, 1e-3f * pixel);  // image y runs down, v up
    EXPECT_NEAR(si.dvdx, 0.0f, 1e-6f);

    Vec3 dpdx, dpdy;
    camera.approximate_footprint(si.p, si.ng, dpdx, dpdy);
    EXPECT_NEAR(glm::length(dpdx), pixel, 0.01f * pixel);
    EXPECT_NEAR(glm::length(dpdy), pixel, 0.01f * pixel);

    // More samples per pixel: each sample filters a smaller footprint.
    camera.set_samples_per_pixel(16);
    const Ray fine = camera.generate_ray(Vec2(100.0f, 50.0f), Vec2(0.5f));
    ASSERT_TRUE(footprint_from_differentials(fine, si));
    EXPECT_NEAR(glm::length(si.dpdx), pixel / 4.0f, 1e-3f * pixel);
}

// A missing texture is an error that names the file and the script line.
TEST(ImageTexture, MissingFileNamesFileAndLine) {
    const std::string code =
        "glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0} }\n"
        "local t = glint.texture.image{ file = 'no-such-texture.png' }\n"
        "glint.sphere{ material = glint.diffuse{ reflectance = t } }\n";
    const SceneDesc desc = load_scene_string(code, "scene.lua");
    try {
        build_scene(desc, RenderSettings());
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("no-such-texture.png"), std::string::npos) << message;
        EXPECT_NE(message.find("scene.lua:2"), std::string::npos) << message;
    }
}

// Mipmapping (issue 4): a finely tiled checkerboard plane seen at a grazing angle at
// 4 spp has a lower relative MSE against a 1024-spp reference with mipmapping than
// without. The plane sees only a white sky and the path ends there (max_depth 1), so
// every sample is exactly the texture value: all error comes from texture sampling.
// The reference is supersampled without mipmaps, so it converges to the box-filtered
// texture without the bias of any prefilter.
TEST(ImageTexture, MipmappingLowersErrorAtGrazingAngles) {
    TempDir dir;
    write_image(dir.file("checker.exr"), checker_image(8, 8, 0.05f, 0.95f));
    auto render = [&](int spp, bool mipmapping, int seed, const char* filter = "anisotropic") {
        const std::string code =
            fmt::format(R"(
            glint.camera{{ eye = {{0, 1, 0}}, look_at = {{0, 0, -12}}, fov = 10 }}
            glint.render{{ width = 64, height = 32, spp = {}, seed = {}, max_depth = 1,
                           mipmapping = {} }}
            glint.background{{ radiance = 1 }}
            local checker = glint.texture.image{{ file = "{}", scale = 400, filter = "{}" }}
            glint.quad{{ vertices = {{{{-500, 0, 500}}, {{500, 0, 500}}, {{500, 0, -500}},
                                     {{-500, 0, -500}}}},
                        material = glint.diffuse{{ reflectance = checker }} }}
        )",
                        spp, seed, mipmapping ? "true" : "false", dir.file("checker.exr"), filter);
        return glint::test::render_lua(code);
    };
    const Image reference = render(1024, false, 11);
    const double with_mipmaps = compare_images(render(4, true, 1), reference).rel_mse;
    const double without = compare_images(render(4, false, 1), reference).rel_mse;
    std::cout << fmt::format("relative MSE at 4 spp: mipmapped {:.4g}, not mipmapped {:.4g}\n",
                             with_mipmaps, without);
    EXPECT_LT(with_mipmaps, 0.5 * without);
}

// Anisotropic filtering (the default, docs/scene-language.md) at a grazing angle: stripes
// that run away from the camera are narrow across the view and long along it, so a pixel's
// footprint is long and thin. Filtering over that footprint keeps the stripes; an isotropic
// (trilinear) filter, or a footprint too large, greys them out. Against a reference
// supersampled without mipmaps (1024 spp), the filtered 16-spp image's relative MSE is its
// own variance (half that between two seeds) plus the reference's plus the filter's bias;
// the bias may be at most twice the variance. The test checks that trilinear filtering
// fails the same bound.
TEST(ImageTextureSlow, AnisotropicFilteringKeepsStripesAlongTheView) {
    TempDir dir;
    Image stripes = make_image(8, 8, {"R", "G", "B"});
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            for (int c = 0; c < 3; ++c) stripes.at(x, y, c) = x < 4 ? 0.05f : 0.95f;
        }
    }
    write_image(dir.file("stripes.exr"), stripes);
    // The plane sees a white sky and the path ends there, so a sample is the texture value.
    // The stripes repeat every 0.2 units across (about 3 pixels at the image's middle).
    auto render = [&](int spp, bool mipmapping, int seed, const char* filter) {
        return glint::test::render_lua(fmt::format(R"(
            glint.camera{{ eye = {{0, 1, 0}}, look_at = {{0, 0, -12}}, fov = 10 }}
            glint.render{{ width = 64, height = 32, spp = {}, seed = {}, max_depth = 1,
                           mipmapping = {} }}
            glint.background{{ radiance = 1 }}
            local stripes = glint.texture.image{{ file = "{}", scale = 5000, filter = "{}" }}
            glint.quad{{ vertices = {{{{-500, 0, 500}}, {{500, 0, 500}}, {{500, 0, -500}},
                                     {{-500, 0, -500}}}},
                        material = glint.diffuse{{ reflectance = stripes }} }}
        )",
                                                   spp, seed, mipmapping ? "true" : "false",
                                                   dir.file("stripes.exr"), filter));
    };
    const Image reference = render(1024, false, 11, "none");
    const double reference_variance =
        0.5 * compare_images(render(1024, false, 12, "none"), reference).rel_mse;
    auto bias_bound_holds = [&](const char* filter) {
        const Image a = render(16, true, 1, filter), b = render(16, true, 2, filter);
        const double error = compare_images(a, reference).rel_mse;
        const double variance = 0.5 * compare_images(a, b).rel_mse;
        const double bias = error - variance - reference_variance;
        std::cout << fmt::format("{}: relative MSE {:.4g}, variance {:.4g}, bias {:.4g}\n", filter,
                                 error, variance, bias);
        return bias < 2.0 * variance;
    };
    EXPECT_TRUE(bias_bound_holds("anisotropic"));
    EXPECT_FALSE(bias_bound_holds("trilinear")) << "the bound lets over-blurring pass";
}

namespace {

// A hit on the plane through the origin with normal n, reached by `ray`.
SurfaceInteraction flat_hit(const Ray& ray, const Vec3& p, const Vec3& n) {
    SurfaceInteraction si;
    si.p = p;
    si.ng = n;
    si.shading = Frame::from_normal(n);
    si.dpdu = si.shading.s();
    si.dpdv = si.shading.t();
    si.wo = -glm::normalize(ray.direction);
    return si;
}

// Exact refraction of unit `d` through a surface with normal n (on d's incoming side,
// dot(d, n) < 0) into a medium eta times denser.
Vec3 refract(const Vec3& d, const Vec3& n, float eta) {
    const float cos_i = -glm::dot(d, n);
    const float cos_t = std::sqrt(1.0f - (1.0f - cos_i * cos_i) / (eta * eta));
    return d / eta + (cos_i / eta - cos_t) * n;
}

}  // namespace

// A texture seen in a flat mirror has the footprint it would have seen directly from the
// mirrored camera: differentials are reflected with the ray, not approximated.
TEST(Footprint, MirrorReflectsTheDifferentials) {
    const Vec2i resolution(100, 100);
    PerspectiveCamera camera(Vec3(0, 1, 5), Vec3(0, 0, 0), Vec3(0, 1, 0), 40.0f, resolution, 0.0f,
                             1.0f);
    const Ray ray = camera.generate_ray(Vec2(50.0f, 50.0f), Vec2(0.5f));
    SurfaceInteraction mirror = flat_hit(ray, Vec3(0.0f), Vec3(0, 1, 0));
    const Vec3 wi = glm::reflect(glm::normalize(ray.direction), Vec3(0, 1, 0));
    const Ray reflected = spawn_specular_ray(mirror, ray, wi, false, 1.0f);
    ASSERT_TRUE(reflected.has_differentials);

    // The wall z = -5, reached along the reflected ray and along the mirrored camera's ray.
    auto wall_footprint = [](const Ray& r) {
        const float t = (-5.0f - r.origin.z) / r.direction.z;
        SurfaceInteraction wall = flat_hit(r, r.origin + t * r.direction, Vec3(0, 0, 1));
        EXPECT_TRUE(footprint_from_differentials(r, wall));
        return std::make_pair(wall.dpdx, wall.dpdy);
    };
    PerspectiveCamera mirrored(Vec3(0, -1, 5), Vec3(0, 0, 0), Vec3(0, -1, 0), 40.0f, resolution,
                               0.0f, 1.0f);
    const auto [dpdx, dpdy] = wall_footprint(reflected);
    const auto [ref_dpdx, ref_dpdy] =
        wall_footprint(mirrored.generate_ray(Vec2(50.0f, 50.0f), Vec2(0.5f)));
    EXPECT_NEAR(glm::length(dpdx), glm::length(ref_dpdx), 1e-3f * glm::length(ref_dpdx));
    EXPECT_NEAR(glm::length(dpdy), glm::length(ref_dpdy), 1e-3f * glm::length(ref_dpdy));
    // Across the ray (x), the footprint is one pixel's angle times the whole path length,
    // eye to mirror to wall: 2 * sqrt(26).
    const float pixel_angle = 2.0f * std::tan(glm::radians(20.0f)) / 100.0f;
    EXPECT_NEAR(glm::length(dpdx), pixel_angle * 2.0f * std::sqrt(26.0f),
                1e-2f * glm::length(dpdx));
}

// Refracted differentials are the first-order change of the refracted direction: they
// match refracting the neighbouring rays exactly, to second order in their offset.
TEST(Footprint, RefractionTurnsTheDifferentialsBySnellsLaw) {
    const float eta = 1.5f;
    const Vec3 n(0, 1, 0);
    for (const float degrees : {0.0f, 30.0f, 60.0f}) {
        Ray ray;
        ray.origin = Vec3(0.0f);
        ray.direction =
            -Vec3(std::sin(glm::radians(degrees)), std::cos(glm::radians(degrees)), 0.0f);
        ray.origin = -ray.direction;  // one unit before the surface
        ray.has_differentials = true;
        const float step = 1e-3f;
        ray.differentials = {ray.origin, ray.direction + Vec3(step, 0, 0), ray.origin,
                             ray.direction + Vec3(0, 0, step)};
        SurfaceInteraction glass = flat_hit(ray, Vec3(0.0f), n);
        const Vec3 wi = refract(ray.direction, n, eta);
        const Ray refracted = spawn_specular_ray(glass, ray, wi, true, eta);
        ASSERT_TRUE(refracted.has_differentials);
        const Vec3 exact_x = refract(glm::normalize(ray.differentials.rx_direction), n, eta);
        const Vec3 exact_z = refract(glm::normalize(ray.differentials.ry_direction), n, eta);
        const Vec3 turned_x = refracted.differentials.rx_direction;
        const Vec3 turned_z = refracted.differentials.ry_direction;
        EXPECT_LT(glm::length(turned_x - exact_x), 0.02f * glm::length(exact_x - wi)) << degrees;
        EXPECT_LT(glm::length(turned_z - exact_z), 0.02f * glm::length(exact_z - wi)) << degrees;
        // At normal incidence angles shrink by 1/eta.
        if (degrees == 0.0f) {
            EXPECT_NEAR(glm::length(turned_x - wi), step / eta, 0.01f * step);
        }
    }
}
