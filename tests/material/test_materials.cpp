// Materials as the integrators use them: what bsdf() hands out at a hit.
#include <glint/core/arena.h>
#include <glint/core/params.h>
#include <glint/core/rng.h>
#include <glint/material/lambertian.h>
#include <glint/material/materials.h>
#include <glint/material/specular_reflection.h>
#include <glint/material/texture/texture_table.h>
#include <glint/math/warp.h>

#include <gtest/gtest.h>

using namespace glint;

namespace {

SurfaceInteraction hit_at(const Vec2& uv) {
    SurfaceInteraction si;
    si.uv = uv;
    si.p = Vec3(uv, 0.0f);
    si.ng = Vec3(0, 0, 1);
    return si;
}

void expect_same_bsdf(const Bsdf& actual, const Bsdf& expected) {
    Rng rng(3);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 wo = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 wi = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec2 u(rng.next_float(), rng.next_float());
        ASSERT_EQ(actual.eval(wo, wi), expected.eval(wo, wi));
        ASSERT_EQ(actual.pdf(wo, wi), expected.pdf(wo, wi));
        const auto a = actual.sample(wo, u, 0.5f), e = expected.sample(wo, u, 0.5f);
        ASSERT_EQ(a.has_value(), e.has_value());
        if (a) {
            ASSERT_EQ(a->f, e->f);
            ASSERT_EQ(a->pdf, e->pdf);
        }
    }
    EXPECT_EQ(actual.flags(), expected.flags());
}

// The material `make` builds from `params` hands out the same BSDF at two different hits,
// and it behaves as `expected`.
template <typename Factory>
void expect_one_shared_bsdf(Factory make, const Params& params, const Bsdf& expected) {
    TextureTable textures(".", true);
    const auto material = make(params, textures);
    Arena arena;
    const Bsdf* first = material->bsdf(hit_at(Vec2(0.1f, 0.2f)), arena);
    const Bsdf* second = material->bsdf(hit_at(Vec2(0.7f, 0.9f)), arena);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first, second);
    expect_same_bsdf(*first, expected);
}

}  // namespace

// Without a texture the BSDF does not vary over the surface: it is built once and the same
// one is handed out at every hit, with the material's parameters.
TEST(DiffuseMaterial, UntexturedHandsOutOneBsdfWithItsReflectance) {
    Params params("diffuse", "scene.lua:1");
    params.set("reflectance", std::vector<double>{0.2, 0.4, 0.6});
    expect_one_shared_bsdf(make_diffuse_material, params,
                           LambertianBsdf(uplift(Rgb(0.2f, 0.4f, 0.6f), RgbRole::unbounded)));
}

TEST(MirrorMaterial, UntexturedHandsOutOneBsdfWithItsTint) {
    Params params("mirror", "scene.lua:1");
    params.set("tint", std::vector<double>{0.9, 0.8, 0.7});
    expect_one_shared_bsdf(
        make_mirror_material, params,
        SpecularReflectionBsdf(uplift(Rgb(0.9f, 0.8f, 0.7f), RgbRole::unbounded)));
}

// Material::may_scatter_specularly() lets photon methods skip aiming at specular surfaces
// when a scene has none: it may say false only for materials whose BSDF is never a delta
// (a wrong false would lose caustics), and must say true for those that hand out one.
TEST(Materials, MayScatterSpecularlyAgreesWithTheirBsdfs) {
    using Factory = std::unique_ptr<Material> (*)(const Params&, TextureTable&);
    const struct {
        const char* name;
        Factory make;
        bool specular;
    } cases[] = {{"diffuse", make_diffuse_material, false},
                 {"emissive", make_emissive_material, false},
                 {"mirror", make_mirror_material, true},
                 {"dielectric", make_dielectric_material, true}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        TextureTable textures(".", true);
        Params params(c.name, "scene.lua:1");
        if (c.make == make_emissive_material) params.set("radiance", 1.0);
        const auto material = c.make(params, textures);
        EXPECT_EQ(material->may_scatter_specularly(), c.specular);
        Arena arena;
        bool delta = false;
        for (int i = 0; i < 16; ++i) {
            const Bsdf* bsdf = material->bsdf(hit_at(Vec2(i / 16.0f, 1.0f - i / 16.0f)), arena);
            delta |= bsdf != nullptr && bsdf->is_delta();
        }
        EXPECT_EQ(delta, c.specular);
    }
    // Materials that may or may not be smooth (by their roughness or a texture) keep the
    // conservative default.
    for (const Factory make : {make_conductor_material, make_plastic_material,
                               make_principled_material, make_phong_material}) {
        TextureTable textures(".", true);
        EXPECT_TRUE(make(Params("material", "scene.lua:1"), textures)->may_scatter_specularly());
    }
}
