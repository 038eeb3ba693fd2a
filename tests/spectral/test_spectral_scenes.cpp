// Spectral inputs as scenes state them (blackbody, spectrum, metal, dispersive ior): what RGB
// mode renders from them, and the errors for bad values, with the script's file and line.
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/spectral/dispersion.h>
#include <glint/spectral/emission_params.h>
#include <glint/spectral/illuminants.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <fmt/format.h>

namespace glint {
namespace {

// A camera that sees only the front of an emitting quad: each pixel is its radiance.
Rgb seen_radiance(const std::string& emissive) {
    const Image image = test::render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 3}}, look_at = {{0, 0, 0}}, fov = 10 }}
        glint.quad{{ vertices = {{{{-2, -2, 0}}, {{2, -2, 0}}, {{2, 2, 0}}, {{-2, 2, 0}}}},
                    material = {} }}
        glint.render{{ integrator = "path", width = 2, height = 2, spp = 1 }}
    )",
                                                     emissive));
    return {float(test::mean_channel(image, 0, 0, 0, 2, 2)),
            float(test::mean_channel(image, 1, 0, 0, 2, 2)),
            float(test::mean_channel(image, 2, 0, 0, 2, 2))};
}

TEST(SpectralScenes, BlackbodyAndSpectraSetColourNotBrightness) {
    const Rgb warm = seen_radiance("glint.emissive{ radiance = 2, blackbody = 2700 }");
    EXPECT_NEAR(warm.luminance(), 2.0f, 2e-3f);
    EXPECT_GT(warm.r, warm.g);
    EXPECT_GT(warm.g, warm.b);
    const Rgb expected = 2.0f * spectral::EmissionShape::blackbody(2700).rgb();
    EXPECT_NEAR(warm.r, expected.r, 1e-5f);
    EXPECT_NEAR(warm.b, expected.b, 1e-5f);

    const Rgb cold = seen_radiance("glint.emissive{ radiance = 2, blackbody = 12000 }");
    EXPECT_GT(cold.b, cold.r);
    EXPECT_NEAR(cold.luminance(), 2.0f, 2e-3f);

    // D65 is sRGB's white: grey, as bright as the radiance says.
    const Rgb d65 = seen_radiance("glint.emissive{ radiance = 2, spectrum = 'D65' }");
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(d65[c], 2.0f, 0.01f) << c;

    // A table rising towards red is red; its colour is its own, whatever its scale.
    const Rgb red =
        seen_radiance("glint.emissive{ radiance = 1, spectrum = {{400, 0}, {700, 50}} }");
    EXPECT_GT(red.r, 2.0f * red.g);
    EXPECT_NEAR(red.luminance(), 1.0f, 2e-3f);
}

TEST(SpectralScenes, NamedMetalsRenderTheirColour) {
    const auto centre = [](const char* metal) {
        const Image image = test::render_lua(fmt::format(R"(
            glint.camera{{ eye = {{0, 0, 3}}, look_at = {{0, 0, 0}}, fov = 2 }}
            glint.background{{ radiance = 1 }}
            glint.sphere{{ radius = 1, material = glint.conductor{{ metal = "{}", roughness = 0 }} }}
            glint.render{{ integrator = "path", width = 2, height = 2, spp = 1 }}
        )",
                                                         metal));
        return Rgb(float(test::mean_channel(image, 0, 0, 0, 2, 2)),
                   float(test::mean_channel(image, 1, 0, 0, 2, 2)),
                   float(test::mean_channel(image, 2, 0, 0, 2, 2)));
    };
    const Rgb gold = centre("Au"), silver = centre("silver"), copper = centre("Cu");
    EXPECT_GT(gold.r, gold.g);
    EXPECT_GT(gold.g, 1.3f * gold.b);
    EXPECT_GT(silver.min_value(), 0.85f);
    EXPECT_GT(copper.r, 1.2f * copper.g);
}

// RGB mode renders a dispersive glass at its index n_d: the same image as that number.
TEST(SpectralScenes, DispersiveGlassRendersAtItsReferenceIndex) {
    const auto render = [](const std::string& dielectric) {
        return test::render_lua(R"(
            glint.camera{ eye = {0, 0.5, 3}, look_at = {0, 0, 0}, fov = 30 }
            glint.background{ radiance = 1 }
            glint.quad{ vertices = {{-5, -1, 5}, {5, -1, 5}, {5, -1, -5}, {-5, -1, -5}},
                        material = glint.diffuse{ reflectance = 0.5 } }
            glint.sphere{ radius = 0.8, material = glint.dielectric{ )" +
                                dielectric + R"( } }
            glint.render{ integrator = "path", width = 8, height = 8, spp = 2, seed = 3 }
        )");
    };
    const double n_d = spectral::named_dielectric("BK7")->reference();
    const Image named = render("ior = 'BK7'");
    const Image number = render(fmt::format("ior = {:.9g}", float(n_d)));
    EXPECT_EQ(test::mean_channel(named, 0, 0, 0, 8, 8), test::mean_channel(number, 0, 0, 0, 8, 8));
    const Image abbe = render("ior = 1.6, abbe = 40");
    const Image plain = render("ior = 1.6");
    EXPECT_EQ(test::mean_channel(abbe, 1, 0, 0, 8, 8), test::mean_channel(plain, 1, 0, 0, 8, 8));
    // and the coefficients load (their n_d differs from these numbers).
    render(
        "sellmeier_b = {1.03961212, 0.231792344, 1.01046945}, "
        "sellmeier_c = {0.00600069867, 0.0200179144, 103.560653}");
    render("cauchy = {1.5, 0.004}");
}

// Each bad value is refused with the script's line (line 3) and what was wrong.
TEST(SpectralScenes, BadValuesFailWithFileAndLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"glint.point_light{ position = {0, 1, 0}, intensity = 1, blackbody = -5 }",
         "'blackbody' is a temperature in kelvin"},
        {"glint.point_light{ position = {0, 1, 0}, blackbody = 1e9 }",
         "'blackbody' is a temperature in kelvin"},
        {"glint.spot_light{ position = {0, 1, 0}, look_at = {0, 0, 0}, blackbody = 3000, "
         "spectrum = 'A' }",
         "give 'blackbody' or 'spectrum', not both"},
        {"glint.point_light{ position = {0, 1, 0}, intensity = 1, spectrum = 'D99' }",
         "unknown 'spectrum' 'D99'; known illuminants: 'D65', 'A', 'F1'"},
        {"glint.point_light{ position = {0, 1, 0}, spectrum = {{500, 1}, {400, 1}} }",
         "'spectrum': pair 2: wavelengths must increase"},
        {"glint.point_light{ position = {0, 1, 0}, spectrum = {{400, 1}, {500, -1}} }",
         "'spectrum': pair 2: the value -1 is not a finite non-negative number"},
        {"glint.point_light{ position = {0, 1, 0}, spectrum = {{500, 1}} }",
         "at least two {nm, value} pairs"},
        {"glint.point_light{ position = {0, 1, 0}, spectrum = {{900, 1}, {1000, 2}} }",
         "'spectrum' emits nothing visible"},
        {"glint.point_light{ position = {0, 1, 0}, intensity = -1, blackbody = 3000 }",
         "'intensity' must not be negative"},
        {"glint.sphere{ material = glint.emissive{ radiance = 1, spectrum = 'nope' } }",
         "unknown 'spectrum' 'nope'"},
        {"glint.sphere{ material = glint.conductor{ metal = 'Pt' } }",
         "unknown 'metal' 'Pt'; measured metals: 'Au', 'gold', 'Ag'"},
        {"glint.sphere{ material = glint.conductor{ metal = 'Au', preset = 'gold' } }",
         "give 'metal' alone, without 'preset', 'eta' or 'k'"},
        {"glint.sphere{ material = glint.dielectric{ ior = 'flint' } }",
         "unknown 'ior' preset 'flint'; known: 'BK7', 'fused silica', 'diamond', 'water'"},
        {"glint.sphere{ material = glint.dielectric{ sellmeier_b = {1}, "
         "sellmeier_c = {0.1, 0.2} } }",
         "Sellmeier B and C need as many terms (1 and 2)"},
        {"glint.sphere{ material = glint.dielectric{ sellmeier_b = {1}, sellmeier_c = {0.1}, "
         "ior = 1.5 } }",
         "'ior' follows from the Sellmeier or Cauchy coefficients"},
        {"glint.sphere{ material = glint.dielectric{ ior = 1.5, abbe = 1 } }",
         "'abbe' (the Abbe number V_d) must be in [5, 1000]"},
        {"glint.sphere{ material = glint.dielectric{ cauchy = {1, 2, 3, 4} } }",
         "'cauchy' is {A, B} or {A, B, C}"},
        {"glint.sphere{ material = glint.dielectric{ ior = 'BK7', abbe = 50 } }",
         "give one of a preset 'ior' name, 'abbe'"},
        {"glint.sphere{ material = glint.principled{ ior = 1.5, abbe = 0 } }", "'abbe'"},
    };
    for (const auto& [code, expected] : cases) {
        const std::string message = test::error_of([&] {
            const SceneDesc desc = load_scene_string(
                std::string("glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0} }\n"
                            "glint.render{ width = 2, height = 2, spp = 1 }\n") +
                    code,
                "scene.lua");
            build_scene(desc, parse_render_settings(desc.render ? &*desc.render : nullptr));
        });
        EXPECT_NE(message.find("scene.lua:3:"), std::string::npos) << code << ": " << message;
        EXPECT_NE(message.find(expected), std::string::npos) << code << ": " << message;
    }
}

}  // namespace
}  // namespace glint
