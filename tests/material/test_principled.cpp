// The principled BSDF and material (material/principled_bsdf.h, principled.cpp): chi-square
// of each lobe's sampling alone and of the full mixture, white furnace (never above 1, and 1
// where the model promises it), reciprocity, equality with the conductor and the rough
// dielectric where the models coincide, and the scene-language parameters.
//
// The furnace test prints its table (run build/tests/material/test_material_principled to
// see it); docs/materials.md quotes it.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/material/principled_bsdf.h>
#include <glint/material/rough_conductor.h>
#include <glint/material/rough_dielectric.h>
#include <glint/material/texture/texture_input.h>
#include <glint/math/warp.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/bsdf_checks.h>
#include <support/test_util.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace glint;
using namespace glint::test;

namespace {

// A BSDF with the albedo tables it borrows. `specular_eta` 1 switches the dielectric's
// specular reflection off, to test the other lobes alone.
struct Principled {
    explicit Principled(const PrincipledParams& p, float specular_eta = 1.5f)
        : specular(specular_eta, std::max(p.alpha, PrincipledBsdf::kMinAlpha),
                   std::max(p.alpha, PrincipledBsdf::kMinAlpha)),
          coat(1.5f, std::max(p.clearcoat_alpha, PrincipledBsdf::kMinAlpha),
               std::max(p.clearcoat_alpha, PrincipledBsdf::kMinAlpha)),
          bsdf(p, specular, coat) {}
    CoatAlbedoTable specular;
    CoatAlbedoTable coat;
    PrincipledBsdf bsdf;
};

PrincipledParams params(const Spectrum& base, float metallic, float roughness) {
    PrincipledParams p;
    p.base_color = base;
    p.metallic = metallic;
    p.alpha = roughness_to_alpha(roughness);
    return p;
}

struct LobeCase {
    std::string name;
    PrincipledParams p;
    float specular_eta;
    float zoom_alpha;  // magnify around the mirror direction to this lobe width; 0: no zoom
};

// Each lobe alone: the others are switched off by their weights (black base, no specular).
std::vector<LobeCase> lobe_cases() {
    std::vector<LobeCase> cases;
    cases.push_back({"diffuse",
                     params(uplift(Rgb(0.8f, 0.5f, 0.3f), RgbRole::unbounded), 0.0f, 0.5f), 1.0f,
                     0.0f});
    for (float roughness : {0.05f, 0.3f, 0.8f}) {
        const float alpha = roughness_to_alpha(roughness);
        cases.push_back({fmt::format("specular {}", roughness),
                         params(Spectrum(0.0f), 0, roughness), 1.5f, alpha});
        cases.push_back({fmt::format("metal {}", roughness),
                         params(uplift(Rgb(0.9f, 0.6f, 0.3f), RgbRole::unbounded), 1.0f, roughness),
                         1.5f, alpha});
    }
    // A black metal reflects only through Schlick's grazing term (its weight's floor).
    cases.push_back(
        {"black metal 0.3", params(Spectrum(0.0f), 1.0f, 0.3f), 1.5f, roughness_to_alpha(0.3f)});
    PrincipledParams coat = params(Spectrum(0.0f), 0.0f, 0.5f);
    coat.clearcoat = 1.0f;
    coat.clearcoat_alpha = roughness_to_alpha(0.1f);
    cases.push_back({"clearcoat", coat, 1.0f, coat.clearcoat_alpha});
    PrincipledParams sheen = params(Spectrum(0.0f), 0.0f, 0.5f);
    sheen.sheen = 1.0f;
    cases.push_back({"sheen", sheen, 1.0f, 0.0f});
    return cases;
}

const std::vector<Vec3>& outgoing() {
    static const std::vector<Vec3> directions = {direction(0.0f), direction(45.0f),
                                                 direction(85.0f), direction(30.0f, 2.0f, true)};
    return directions;
}

}  // namespace

namespace {

// Chi-square of the lobe cases whose name does (or does not) contain "metal".
void expect_lobes_sample_their_pdf(bool metal) {
    std::vector<LobeCase> cases;
    for (const LobeCase& c : lobe_cases()) {
        if ((c.name.find("metal") != std::string::npos) == metal) cases.push_back(c);
    }
    const double significance = 0.01 / (cases.size() * outgoing().size());
    for (const LobeCase& c : cases) {
        const Principled principled(c.p, c.specular_eta);
        for (const Vec3& wo : outgoing()) {
            const Zoom zoom(mirror_direction(wo), c.zoom_alpha > 0 ? zoom_scale(c.zoom_alpha) : 1);
            const auto check =
                check_sampling(principled.bsdf, wo, zoom, Lobe::kAll, 1.0f, significance);
            expect_sampling_ok(check, c.name + ", " + describe(wo));
        }
    }
}

}  // namespace

TEST(PrincipledBsdfSlow, DielectricReflectionLobesSampleTheirPdf) {
    expect_lobes_sample_their_pdf(false);
}

TEST(PrincipledBsdfSlow, MetalLobeSamplesItsPdf) {
    expect_lobes_sample_their_pdf(true);
}

// The glass alone (transmission 1), from outside and inside, reflection and refraction each
// magnified around its centre.
TEST(PrincipledBsdfSlow, GlassLobeSamplingMatchesPdf) {
    const float eta = 1.5f;
    const Vec3 directions[] = {direction(0.0f), direction(60.0f), direction(25.0f, 1.1f, true)};
    const float roughnesses[] = {0.1f, 0.4f, 1.0f};
    const double significance = 0.01 / (std::size(directions) * std::size(roughnesses) * 2);
    for (float roughness : roughnesses) {
        PrincipledParams p =
            params(uplift(Rgb(0.9f, 0.7f, 0.5f), RgbRole::unbounded), 0.0f, roughness);
        p.transmission = 1.0f;
        p.ior = eta;
        const Principled principled(p);
        for (const Vec3& wo : directions) {
            for (Lobe lobe : {Lobe::kReflection, Lobe::kTransmission}) {
                const Vec3 centre =
                    lobe == Lobe::kReflection ? mirror_direction(wo) : refracted_direction(wo, eta);
                const Zoom zoom(centre, zoom_scale(p.alpha));
                const auto check =
                    check_sampling(principled.bsdf, wo, zoom, lobe, eta, significance);
                const std::string label =
                    fmt::format("roughness {}, {}, {}", roughness, describe(wo),
                                lobe == Lobe::kReflection ? "reflection" : "transmission");
                EXPECT_TRUE(check.chi_square.passed) << label << ": " << check.chi_square.details;
                EXPECT_NEAR(check.chi_square.integrated_pdf, check.chi_square.sample_fraction, 5e-3)
                    << label;
                EXPECT_EQ(check.inconsistent, 0) << label << ": " << check.first_inconsistency;
            }
        }
    }
}

namespace {

struct MixtureCase {
    float metallic, roughness, transmission, clearcoat, sheen;
};

// Every lobe at once, unmagnified (reflection and transmission over the whole sphere).
void expect_mixtures_sample_their_pdf(const std::vector<MixtureCase>& cases) {
    const double significance = 0.01 / (cases.size() * outgoing().size());
    for (const MixtureCase& c : cases) {
        PrincipledParams p =
            params(uplift(Rgb(0.8f, 0.6f, 0.4f), RgbRole::unbounded), c.metallic, c.roughness);
        p.transmission = c.transmission;
        p.clearcoat = c.clearcoat;
        p.clearcoat_alpha = roughness_to_alpha(0.3f);
        p.sheen = c.sheen;
        const Principled principled(p);
        for (const Vec3& wo : outgoing()) {
            const Zoom zoom(mirror_direction(wo), 1.0f);
            const auto check =
                check_sampling(principled.bsdf, wo, zoom, Lobe::kAll, p.ior, significance);
            expect_sampling_ok(check, fmt::format("metallic {} roughness {} transmission {} "
                                                  "clearcoat {} sheen {}, {}",
                                                  c.metallic, c.roughness, c.transmission,
                                                  c.clearcoat, c.sheen, describe(wo)));
        }
    }
}

}  // namespace

TEST(PrincipledBsdfSlow, OpaqueMixtureSamplesItsPdf) {
    expect_mixtures_sample_their_pdf({{0.0f, 0.5f, 0.0f, 0.0f, 0.0f},
                                      {0.5f, 0.3f, 0.0f, 0.5f, 0.0f},
                                      {1.0f, 0.9f, 0.0f, 1.0f, 1.0f}});
}

TEST(PrincipledBsdfSlow, TransmittingMixtureSamplesItsPdf) {
    expect_mixtures_sample_their_pdf(
        {{0.2f, 0.6f, 0.5f, 0.3f, 1.0f}, {0.0f, 0.8f, 0.7f, 1.0f, 0.5f}});
}

// White furnace. Every parameter set of a sweep reflects (and transmits, counted as energy)
// at most 1 within four standard errors plus the albedo tables' accuracy (1e-3). Where the
// model promises 1 it is 1 within the same bound: a white opaque dielectric without coat or
// sheen at every roughness (the diffuse term takes exactly what the specular layer passes),
// and a white metal at roughness 0 (F = 1 and GGX at alpha 1e-3 masks nothing).
TEST(PrincipledBsdfSlow, WhiteFurnace) {
    const float angles[] = {0.0f, 30.0f, 60.0f, 75.0f, 85.0f};
    struct Case {
        const char* name;
        float metallic, transmission, clearcoat, sheen;
        bool promises_one;
    };
    const Case cases[] = {{"dielectric", 0, 0, 0, 0, true}, {"metal", 1, 0, 0, 0, false},
                          {"glass", 0, 1, 0, 0, false},     {"clearcoat", 0, 0, 1, 0, false},
                          {"sheen", 0, 0, 0, 1, false},     {"all", 0.3f, 0.3f, 0.5f, 0.5f, false}};
    std::cout << "Principled, white base: directional albedo (4e4 samples each)\n"
              << "case        roughness |";
    for (float a : angles) std::cout << fmt::format(" {:>6.0f}deg", a);
    std::cout << "\n";
    constexpr int kSamples = 40000;
    for (const Case& c : cases) {
        for (float roughness : {0.0f, 0.3f, 0.6f, 1.0f}) {
            PrincipledParams p = params(Spectrum(1.0f), c.metallic, roughness);
            p.transmission = c.transmission;
            p.clearcoat = c.clearcoat;
            p.clearcoat_alpha = roughness_to_alpha(0.2f);
            p.sheen = c.sheen;
            const Principled principled(p);
            std::cout << fmt::format("{:<11} {:>9.2f} |", c.name, roughness);
            for (float degrees : angles) {
                const Albedo e = sampled_albedo(principled.bsdf, direction(degrees), kSamples, 43);
                std::cout << fmt::format(" {:>9.4f}", e.mean);
                const std::string where = fmt::format("{}, roughness {}, {} degrees: {} +- {}",
                                                      c.name, roughness, degrees, e.mean, e.error);
                EXPECT_LE(e.mean, 1.0 + 4.0 * e.error + 1e-3) << where;
                const bool promised = c.promises_one || (c.metallic == 1.0f && roughness == 0.0f);
                if (promised) {
                    EXPECT_GE(e.mean, 1.0 - 4.0 * e.error - 2e-3) << where;
                }
            }
            std::cout << "\n";
        }
    }
}

// The sampling reaches every direction the BSDF scatters into: pdf > 0 wherever f > 0 (a
// lobe given zero weight at some wo would be missing from the estimate without the
// chi-square test noticing: both the samples and the pdf would leave it out). A black metal
// seen at normal incidence is the case to watch: its Schlick reflectance there is 0, but
// tilted facets still reflect.
TEST(PrincipledBsdf, PdfCoversEveryDirectionWithF) {
    std::vector<PrincipledParams> sets;
    for (float metallic : {0.0f, 0.5f, 1.0f}) {
        for (float base : {0.0f, 0.7f}) {
            PrincipledParams p = params(Spectrum(base), metallic, 0.4f);
            sets.push_back(p);
            p.transmission = 0.6f;
            p.clearcoat = 0.5f;
            p.sheen = 0.5f;
            sets.push_back(p);
        }
    }
    Rng rng(59);
    for (const PrincipledParams& p : sets) {
        const Principled principled(p);
        for (int n = 0; n < 2000; ++n) {
            const Vec3 wo =
                n < 100 ? direction(0.0f)
                        : warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
            const Vec3 wi =
                warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
            if (principled.bsdf.eval(wo, wi).max_value() > 0.0f) {
                ASSERT_GT(principled.bsdf.pdf(wo, wi), 0.0f)
                    << "metallic " << p.metallic << " base " << to_rgb(p.base_color).r << " "
                    << describe(wo);
            }
        }
    }
}

// Reflection is reciprocal, f(a, b) = f(b, a); refraction obeys generalised reciprocity,
// f(a, b) / n_a^2 = f(b, a) / n_b^2 (n the index on each direction's side).
TEST(PrincipledBsdf, Reciprocal) {
    PrincipledParams p = params(uplift(Rgb(0.8f, 0.5f, 0.2f), RgbRole::unbounded), 0.4f, 0.5f);
    p.transmission = 0.5f;
    p.clearcoat = 0.6f;
    p.clearcoat_alpha = 0.1f;
    p.sheen = 0.8f;
    const Principled principled(p);
    const PrincipledBsdf& bsdf = principled.bsdf;
    Rng rng(47);
    int transmissions = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 a = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 b = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const float n_a = a.z > 0.0f ? 1.0f : p.ior, n_b = b.z > 0.0f ? 1.0f : p.ior;
        const Spectrum ab = bsdf.eval(a, b) / (n_a * n_a), ba = bsdf.eval(b, a) / (n_b * n_b);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_TRUE(close(to_rgb(ab)[ch], to_rgb(ba)[ch], 2e-4f))
                << to_rgb(ab)[ch] << " against " << to_rgb(ba)[ch];
        if (!same_hemisphere(a, b) && to_rgb(ab).r > 0.0f) ++transmissions;
    }
    EXPECT_GT(transmissions, 100);  // the refraction branch was exercised
}

// Where the principled model is another BSDF of glint's, it is that BSDF: a white metal is a
// GGX perfect reflector (Schlick with F0 = 1 is 1), and full transmission with a white base
// is the rough dielectric of the same index. eval() and pdf() agree to rounding.
TEST(PrincipledBsdf, EqualsConductorAndRoughGlassWhereTheyCoincide) {
    Rng rng(53);
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
        const float alpha = roughness_to_alpha(roughness);
        const Principled metal(params(Spectrum(1.0f), 1.0f, roughness));
        const RoughConductorBsdf conductor(GgxDistribution(alpha),
                                           ConductorFresnel::perfect_reflector());
        PrincipledParams g = params(Spectrum(1.0f), 0.0f, roughness);
        g.transmission = 1.0f;
        g.ior = 1.33f;
        const Principled glass(g);
        const RoughDielectricBsdf dielectric(1.33f, GgxDistribution(alpha));
        for (int i = 0; i < 2000; ++i) {
            const Vec3 a = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
            const Vec3 b = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
            EXPECT_TRUE(
                close(to_rgb(metal.bsdf.eval(a, b)).r, to_rgb(conductor.eval(a, b)).r, 1e-5f));
            EXPECT_TRUE(close(metal.bsdf.pdf(a, b), conductor.pdf(a, b), 1e-5f));
            EXPECT_TRUE(
                close(to_rgb(glass.bsdf.eval(a, b)).r, to_rgb(dielectric.eval(a, b)).r, 1e-5f))
                << to_rgb(glass.bsdf.eval(a, b)).r << " " << to_rgb(dielectric.eval(a, b)).r;
            EXPECT_TRUE(close(glass.bsdf.pdf(a, b), dielectric.pdf(a, b), 1e-5f));
        }
    }
}

namespace {

// A texture of one colour everywhere.
class ConstantTexture final : public Texture {
public:
    explicit ConstantTexture(const Rgb& value) : m_value(value) {}
    Rgb eval(const TextureContext&) const override { return m_value; }

private:
    Rgb m_value;
};

std::string scene_error(const std::string& code) {
    try {
        const SceneDesc desc =
            load_scene_string(code, "scene.lua", GLINT_SOURCE_DIR "/tests/scenes");
        build_scene(desc, parse_render_settings(desc.render ? &*desc.render : nullptr));
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// glTF packs roughness in green and metallic in blue; a channel input reads one of them.
TEST(PrincipledMaterial, ChannelInputReadsOneChannel) {
    const ConstantTexture texture(Rgb(0.1f, 0.5f, 0.9f));
    const SurfaceInteraction si;
    EXPECT_EQ(FloatInput::channel(&texture, 0, 0.0f, 1.0f).eval(si), 0.1f);
    EXPECT_EQ(FloatInput::channel(&texture, 1, 0.0f, 1.0f).eval(si), 0.5f);
    EXPECT_EQ(FloatInput::channel(&texture, 2, 0.0f, 0.6f).eval(si), 0.6f);
    EXPECT_FLOAT_EQ(FloatInput(&texture, 0.0f, 1.0f).eval(si), 0.5f);
}

TEST(PrincipledMaterial, LuaParametersAreChecked) {
    EXPECT_EQ(scene_error(R"(
        glint.sphere{ radius = 1, material = glint.principled{} }
        local t = glint.texture.checker{ even = {0, 0.5, 1}, odd = {0, 0.2, 0.3} }
        glint.sphere{ radius = 1, material = glint.principled{ base_color = t, metallic = 0.5,
                      roughness = 0.2, metallic_roughness = t, ior = 1.45, specular = 0.6,
                      transmission = t, clearcoat = 1, clearcoat_roughness = 0.1, sheen = 0.5,
                      sheen_tint = 1, emission = {1, 2, 3}, emission_strength = 4,
                      normal_map_flip_y = false } }
    )"),
              "");
    struct Case {
        const char* code;
        std::vector<const char*> expected;
    };
    const Case cases[] = {
        {"glint.principled{ roughness = 1.5 }", {"scene.lua:1:", "'roughness' must lie in [0, 1]"}},
        {"\nglint.principled{ metallic = -1 }", {"scene.lua:2:", "'metallic' must lie in [0, 1]"}},
        {"glint.principled{ base_color = {1, 2, 0} }", {"'base_color' must lie in [0, 1]"}},
        {"glint.principled{ ior = 0.5 }", {"'ior' must lie in [1, 10]"}},
        {"glint.principled{ specular = 2 }", {"'specular' must lie in [0, 1]"}},
        {"glint.principled{ transmission = 'glass' }", {"'transmission' must be a number or a"}},
        {"glint.principled{ clearcoat = 1.1 }", {"'clearcoat' must lie in [0, 1]"}},
        {"glint.principled{ clearcoat_roughness = -0.1 }",
         {"'clearcoat_roughness' must lie in [0, 1]"}},
        {"glint.principled{ sheen = glint.texture.checker{} }",
         {"'sheen' must be a number (textures are not supported for it)"}},
        {"glint.principled{ sheen_tint = 3 }", {"'sheen_tint' must lie in [0, 1]"}},
        {"glint.principled{ emission = {-1, 0, 0} }",
         {"'emission' must be finite and not negative"}},
        {"glint.principled{ emission = glint.texture.checker{} }",
         {"'emission' must be a colour: textured emission is not supported yet"}},
        {"glint.principled{ emission_strength = -2 }", {"'emission_strength' must be a finite"}},
        {"glint.principled{ metallic_roughness = 3 }", {"'metallic_roughness' must be a texture"}},
        {"glint.principled{ roughnes = 0.3 }", {"scene.lua:1:", "roughnes"}},
    };
    for (const Case& c : cases) {
        const std::string message =
            scene_error(std::string("glint.sphere{ radius = 1, material = ") + c.code + " }");
        for (const char* expected : c.expected) {
            EXPECT_NE(message.find(expected), std::string::npos)
                << c.code << "\n  gave: " << message;
        }
    }
}

// An emitting principled surface is a light: next-event estimation finds it.
TEST(PrincipledMaterial, EmissionMakesAnAreaLight) {
    const SceneDesc desc = load_scene_string(R"(
        glint.sphere{ radius = 1, material = glint.principled{ emission = {1, 0.5, 0.25},
                                                               emission_strength = 2 } }
        glint.sphere{ center = {3, 0, 0}, radius = 1, material = glint.principled{} }
    )",
                                             "scene.lua", GLINT_SOURCE_DIR "/tests/scenes");
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    ASSERT_EQ(scene->lights().size(), 1u);
    EXPECT_NEAR(to_rgb(scene->lights()[0]->power()).r, 2.0 * 4.0 * M_PI * M_PI, 1e-3);
}
