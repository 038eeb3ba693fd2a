// Bump and normal mapping: the perturbed normal tilts the right way, and a bump lit from
// above is brighter on its upper slope.
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/material/normal_perturbation.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <functional>

using namespace glint;

namespace {

// A texture given by a function of uv (heights for bumps, colours for normal maps).
class FunctionTexture final : public Texture {
public:
    explicit FunctionTexture(std::function<Rgb(Vec2)> f) : m_f(std::move(f)) {}
    Rgb eval(const TextureContext& ctx) const override { return m_f(ctx.uv); }

private:
    std::function<Rgb(Vec2)> m_f;
};

// A point on the plane z = 0 facing +z, u along x and v along y (a wall).
SurfaceInteraction wall_point(const Vec2& uv) {
    SurfaceInteraction si;
    si.p = si.p_object = Vec3(uv.x, uv.y, 0.0f);
    si.uv = uv;
    si.ng = Vec3(0, 0, 1);
    si.dpdu = Vec3(1, 0, 0);
    si.dpdv = Vec3(0, 1, 0);
    si.shading = Frame::from_normal_tangent(si.ng, si.dpdu);
    return si;
}

float gaussian_bump(Vec2 uv) {
    const Vec2 d = uv - Vec2(0.5f);
    return std::exp(-glm::dot(d, d) / 0.02f);
}

}  // namespace

// Above the bump's top (larger v, i.e. +y) the surface descends as y grows, so its normal
// leans towards +y; below the top it leans towards -y; on the top it is unchanged.
TEST(BumpMapping, NormalLeansAwayFromTheSlope) {
    const FunctionTexture height([](Vec2 uv) { return Rgb(gaussian_bump(uv)); });
    const NormalPerturbation bump = NormalPerturbation::bump(&height, 0.1f);
    SurfaceInteraction upper = wall_point(Vec2(0.5f, 0.6f));
    SurfaceInteraction lower = wall_point(Vec2(0.5f, 0.4f));
    SurfaceInteraction right = wall_point(Vec2(0.6f, 0.5f));
    SurfaceInteraction top = wall_point(Vec2(0.5f, 0.5f));
    for (SurfaceInteraction* si : {&upper, &lower, &right, &top}) bump.apply(*si);
    EXPECT_GT(upper.shading.n().y, 0.1f);
    EXPECT_LT(lower.shading.n().y, -0.1f);
    EXPECT_GT(right.shading.n().x, 0.1f);
    EXPECT_NEAR(top.shading.n().z, 1.0f, 1e-3f);
    // The slope: h' = -2 d / 0.02 * h * scale at d = 0.1, so n = (0, -h', 1) normalised.
    const float slope = 0.1f * (-0.1f / 0.01f) * gaussian_bump(Vec2(0.5f, 0.6f));
    EXPECT_NEAR(upper.shading.n().y, -slope / std::sqrt(1.0f + slope * slope), 2e-2f);
    // The bumped frame stays orthonormal and on the geometric normal's side.
    EXPECT_NEAR(glm::length(upper.shading.n()), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(upper.shading.n(), upper.shading.s()), 0.0f, 1e-5f);
    EXPECT_GT(glm::dot(upper.shading.n(), upper.ng), 0.0f);
}

// uv running the other way round the normal (dp/du x dp/dv = -n) must not flip bumps.
TEST(BumpMapping, MirroredParameterisationKeepsTheSign) {
    const FunctionTexture height([](Vec2 uv) { return Rgb(gaussian_bump(uv)); });
    const NormalPerturbation bump = NormalPerturbation::bump(&height, 0.1f);
    SurfaceInteraction si = wall_point(Vec2(0.5f, 0.6f));
    si.dpdu = Vec3(-1, 0, 0);  // u now runs along -x
    si.shading = Frame::from_normal_tangent(si.ng, si.dpdu);
    bump.apply(si);
    EXPECT_GT(si.shading.n().y, 0.1f);
    EXPECT_GT(si.shading.n().z, 0.0f);
}

// Normal maps (OpenGL convention): red tilts towards +dp/du, green towards +dp/dv; the
// flat colour (0.5, 0.5, 1) leaves the normal alone; flip_y reads DirectX maps.
TEST(NormalMapping, TangentSpaceConventions) {
    const FunctionTexture flat([](Vec2) { return Rgb(0.5f, 0.5f, 1.0f); });
    const FunctionTexture tilted([](Vec2) { return Rgb(0.8f, 0.7f, 0.9f); });
    SurfaceInteraction si = wall_point(Vec2(0.3f, 0.3f));
    NormalPerturbation::normal_map(&flat, false).apply(si);
    EXPECT_NEAR(si.shading.n().z, 1.0f, 1e-5f);

    const Vec3 expected = glm::normalize(Vec3(0.6f, 0.4f, 0.8f));
    SurfaceInteraction opengl = wall_point(Vec2(0.3f, 0.3f));
    NormalPerturbation::normal_map(&tilted, false).apply(opengl);
    EXPECT_NEAR(glm::distance(opengl.shading.n(), expected), 0.0f, 1e-5f);

    SurfaceInteraction directx = wall_point(Vec2(0.3f, 0.3f));
    NormalPerturbation::normal_map(&tilted, true).apply(directx);
    EXPECT_NEAR(directx.shading.n().y, -expected.y, 1e-5f);
}

// The issue's test: a wall with one raised bump, lit by a point light high above it, is
// brighter on the bump's upper slope than on the flat wall, and darker on its lower slope.
TEST(BumpMapping, BumpLitFromAboveIsBrighterOnItsUpperSlope) {
    const glint::test::TempDir dir("glint-bump");
    const int n = 64;
    Image heights = make_image(n, n, {"R", "G", "B"});
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            // Row 0 is the top of the image, v = 1.
            const Vec2 uv((x + 0.5f) / n, 1.0f - (y + 0.5f) / n);
            for (int c = 0; c < 3; ++c) heights.at(x, y, c) = gaussian_bump(uv);
        }
    }
    const std::string file = dir.file("bump.exr");
    write_image(file, heights);
    const std::string code = fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 3}}, look_at = {{0, 0, 0}}, fov = 40 }}
        glint.render{{ width = 40, height = 40, spp = 4, seed = 1, max_depth = 1 }}
        glint.point_light{{ position = {{0, 20, 1}}, intensity = 400 }}
        local bumps = glint.texture.image{{ file = "{}" }}
        glint.quad{{ vertices = {{{{-1, -1, 0}}, {{1, -1, 0}}, {{1, 1, 0}}, {{-1, 1, 0}}}},
                    material = glint.diffuse{{ reflectance = 0.8, bump = bumps,
                                                bump_scale = 0.2 }} }}
    )",
                                         file);
    const Image image = glint::test::render_lua(code);
    // The wall spans the image rows 20 +- 14.6 (fov 40 at distance 3); v = 0.6 and 0.4 are
    // 0.2 units above and below the centre: rows 20 -+ 2.7.
    auto luminance = [&](int x, int y) {
        return glint::test::mean_channel(image, 1, x - 1, y - 1, x + 2, y + 2);
    };
    const double upper = luminance(20, 17), lower = luminance(20, 23);
    const double flat_upper = luminance(8, 17), flat_lower = luminance(8, 23);
    std::cout << fmt::format("upper slope {:.4f} (flat {:.4f}), lower slope {:.4f} (flat {:.4f})\n",
                             upper, flat_upper, lower, flat_lower);
    EXPECT_GT(upper, 1.2 * flat_upper);
    EXPECT_LT(lower, 0.8 * flat_lower);
}
