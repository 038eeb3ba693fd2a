// glTF as exporters write it: KHR_lights_punctual's photometric units (candela and lux over
// 683 lm/W, or light_scale), the material extensions (specular, ior, transmission, volume,
// clearcoat, sheen, emissive strength, texture transform) mapped onto the principled
// material, and the specification's rule for required and optional extensions. Each file is
// a small glTF JSON written by the test, with its one quad embedded as a data URI.
#include <glint/film/image_io.h>
#include <glint/scene/build.h>
#include <glint/scene/import/import.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <cmath>
#include <fstream>
#include <string>

using namespace glint;
using glint::test::error_of;

namespace {

// A 2 x 2 quad in the y = 0 plane: four float positions and six uint16 indices, 60 bytes.
const char* kQuadBuffer =
    "data:application/octet-stream;base64,"
    "AACAvwAAAAAAAIC/AACAvwAAAAAAAIA/AACAPwAAAAAAAIA/AACAPwAAAAAAAIC/AAABAAIAAAACAAMA";

// A glTF file: the quad with material 0 (`material` is its JSON), `extra` more top-level
// members (lights, extension lists), `nodes` more nodes after the quad's.
std::string gltf(const std::string& material, const std::string& extra = "",
                 const std::string& nodes = "") {
    return fmt::format(R"({{
  "asset": {{"version": "2.0"}}{extra},
  "buffers": [{{"byteLength": 60, "uri": "{buffer}"}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                  {{"buffer": 0, "byteOffset": 48, "byteLength": 12}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
      "min": [-1, 0, -1], "max": [1, 0, 1]}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1, "material": 0}}]}}],
  "materials": [{material}],
  "textures": [{{"source": 0}}],
  "images": [{{"uri": "image.png"}}],
  "nodes": [{{"mesh": 0}}{nodes}],
  "scenes": [{{"nodes": [0{node_list}]}}]
}})",
                       fmt::arg("extra", extra), fmt::arg("buffer", kQuadBuffer),
                       fmt::arg("material", material), fmt::arg("nodes", nodes),
                       fmt::arg("node_list", nodes.empty() ? "" : ", 1"));
}

SceneDesc import(const test::TempDir& dir, const std::string& json,
                 const std::string& options = "") {
    std::ofstream(dir.file("model.gltf")) << json;
    Image image = make_image(2, 2, {"R", "G", "B"});
    write_image(dir.file("image.png"), image);
    return load_scene_string(fmt::format("glint.import{{ file = 'model.gltf'{} }}", options),
                             "scene.lua", dir.file(""));
}

void expect_numbers(const Params& p, const std::string& name, std::vector<double> expected) {
    const std::vector<double> got = p.get_numbers(name);
    ASSERT_EQ(got.size(), expected.size()) << name;
    for (size_t i = 0; i < got.size(); ++i)
        EXPECT_NEAR(got[i], expected[i], 1e-5 * std::max(1.0, std::abs(expected[i])))
            << name << "[" << i << "]";
}

bool has_warning(const SceneDesc& desc, const std::string& part) {
    for (const std::string& w : desc.warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

const char* kLights = R"(,
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
      {"type": "point", "intensity": 1366, "color": [1, 0.5, 0.25]},
      {"type": "spot", "intensity": 683, "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.5}},
      {"type": "directional", "intensity": 2049}]}})";
const char* kLightNodes = R"(,
    {"children": [2, 3, 4]},
    {"translation": [0, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"extensions": {"KHR_lights_punctual": {"light": 2}}})";

}  // namespace

// Candela and lux become W/sr and W/m^2 at 683 lm/W; light_scale = 1 takes the numbers as
// they are (the unitless reading).
TEST(GltfExtensions, LightUnitsAreCandelaAndLuxOver683) {
    test::TempDir dir;
    const std::string json = gltf(R"({})", kLights, kLightNodes);
    const SceneDesc desc = import(dir, json);
    ASSERT_EQ(desc.lights.size(), 3u);
    expect_numbers(desc.lights[0], "intensity", {2, 1, 0.5});
    expect_numbers(desc.lights[1], "intensity", {1, 1, 1});
    expect_numbers(desc.lights[2], "irradiance", {3, 3, 3});
    const SceneDesc unitless = import(dir, json, ", light_scale = 1");
    expect_numbers(unitless.lights[0], "intensity", {1366, 683, 341.5});
    expect_numbers(unitless.lights[2], "irradiance", {2049, 2049, 2049});
}

// The units end to end, as Blender exports a light over a dielectric with specular 0
// (KHR_materials_specular's colour 0): a point light of 683 pi cd at height 2 over a grey
// 0.5 Lambertian floor gives the radiance 0.5 / pi * pi / 2^2 = 0.125 straight below it,
// with no specular layer on top.
TEST(GltfExtensions, BlenderStylePointLightOverSpecularZeroRendersInAbsoluteUnits) {
    test::TempDir dir;
    const std::string material = R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1],
        "metallicFactor": 0, "roughnessFactor": 0.5},
        "extensions": {"KHR_materials_specular": {"specularColorFactor": [0, 0, 0]},
                       "KHR_materials_ior": {"ior": 1.45}}})";
    const std::string extra = fmt::format(R"(,
  "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_specular", "KHR_materials_ior"],
  "extensions": {{"KHR_lights_punctual": {{"lights": [{{"type": "point", "intensity": {}}}]}}}})",
                                          683.0 * M_PI);
    const std::string nodes = R"(,
    {"translation": [0, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})";
    std::ofstream(dir.file("model.gltf")) << gltf(material, extra, nodes);
    write_image(dir.file("image.png"), make_image(2, 2, {"R", "G", "B"}));
    const Image image = test::render_lua(fmt::format(R"(
        glint.import{{ file = "{}" }}
        glint.camera{{ eye = {{0, 1, 0}}, look_at = {{0, 0, 0}}, up = {{0, 0, -1}}, fov = 2 }}
        glint.render{{ width = 4, height = 4, spp = 16, max_depth = 1 }}
    )",
                                                     dir.file("model.gltf")));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(test::mean_channel(image, c, 0, 0, 4, 4), 0.125, 0.125 * 0.01) << c;
}

// Each material extension onto the principled material's parameters.
TEST(GltfExtensions, MaterialExtensionsMapOntoThePrincipledMaterial) {
    test::TempDir dir;
    const std::string material = R"({
      "pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
          "extensions": {"KHR_texture_transform": {"offset": [0.1, 0.2], "scale": [2, 3]}}}},
      "emissiveFactor": [1, 0.5, 0],
      "extensions": {
        "KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [1, 1, 1]},
        "KHR_materials_ior": {"ior": 1.5},
        "KHR_materials_transmission": {"transmissionFactor": 0.75},
        "KHR_materials_volume": {"thicknessFactor": 0.1, "attenuationDistance": 2,
                                 "attenuationColor": [0.5, 0.25, 1]},
        "KHR_materials_clearcoat": {"clearcoatFactor": 0.7, "clearcoatRoughnessFactor": 0.2},
        "KHR_materials_sheen": {"sheenColorFactor": [0.5, 0.4, 0.3]},
        "KHR_materials_emissive_strength": {"emissiveStrength": 4}}})";
    const SceneDesc desc = import(dir, gltf(material), ", emission_scale = 0.5");
    ASSERT_EQ(desc.materials.size(), 1u);
    const Params& m = desc.materials[0];
    // F0 = ((1.5 - 1) / (1.5 + 1))^2 x 1 x 0.5 = 0.02 = 0.08 x 0.25.
    EXPECT_NEAR(m.get_float("specular"), 0.25, 1e-6);
    EXPECT_NEAR(m.get_float("ior"), 1.5, 1e-6);
    EXPECT_NEAR(m.get_float("transmission"), 0.75, 1e-6);
    expect_numbers(m, "absorption", {std::log(2.0) / 2, std::log(4.0) / 2, 0.0});
    EXPECT_NEAR(m.get_float("clearcoat"), 0.7, 1e-6);
    EXPECT_NEAR(m.get_float("clearcoat_roughness"), 0.2, 1e-6);
    EXPECT_NEAR(m.get_float("sheen"), 0.5, 1e-6);
    expect_numbers(m, "emission", {1, 0.5, 0});
    EXPECT_NEAR(m.get_float("emission_strength"), 2.0, 1e-6);
    // glTF's uv' = (2 u + 0.1, 3 v + 0.2) with v down is glint's st = (2 u + 0.1, 3 t - 2.2).
    const Params& texture = desc.textures.at(m.get_ref("base_color", "texture").index);
    expect_numbers(texture, "scale", {2, 3});
    expect_numbers(texture, "offset", {0.1, -2.2});
    EXPECT_TRUE(has_warning(desc, "sheen"));
}

// A transformed texture is its own texture, beside the same image untransformed; the
// rotation glint cannot follow is named in a warning.
TEST(GltfExtensions, TransformedTextureIsItsOwnTexture) {
    test::TempDir dir;
    const std::string material = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
          "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.25], "scale": [0.5, 2],
                                                   "rotation": 0.3}}},
        "metallicRoughnessTexture": {"index": 0}}})";
    const SceneDesc desc = import(dir, gltf(material));
    ASSERT_EQ(desc.textures.size(), 2u);
    expect_numbers(desc.textures[0], "offset", {0.5, 1.0 - 2.0 - 0.25});
    EXPECT_FALSE(desc.textures[1].has("offset"));
    EXPECT_TRUE(has_warning(desc, "rotation is ignored"));
}

// Blender writes specular 0 as KHR_materials_specular's colour 0: no specular layer.
TEST(GltfExtensions, SpecularColourZeroIsNoSpecularLayer) {
    test::TempDir dir;
    const SceneDesc desc = import(
        dir,
        gltf(R"({"extensions": {"KHR_materials_specular": {"specularColorFactor": [0, 0, 0]}}})"));
    EXPECT_EQ(desc.materials[0].get_float("specular"), 0.0f);
    const SceneDesc plain = import(dir, gltf(R"({})"));
    EXPECT_FALSE(plain.materials[0].has("specular"));  // the index 1.5 decides, F0 = 0.04
}

// The specification: a file that requires an extension the loader does not support is
// refused; one that is only used is read without it (a warning names it).
TEST(GltfExtensions, UnknownRequiredExtensionIsAnErrorUnknownUsedOneAWarning) {
    test::TempDir dir;
    const std::string required = test::error_of([&] {
        import(dir, gltf("{}", R"(,
  "extensionsUsed": ["EXT_made_up"], "extensionsRequired": ["EXT_made_up"])"));
    });
    EXPECT_NE(required.find("scene.lua:1"), std::string::npos) << required;
    EXPECT_NE(required.find("model.gltf"), std::string::npos) << required;
    EXPECT_NE(required.find("requires extension EXT_made_up"), std::string::npos) << required;
    const SceneDesc used = import(dir, gltf("{}", R"(,
  "extensionsUsed": ["EXT_made_up", "KHR_materials_specular"],
  "extensionsRequired": ["KHR_materials_specular"])"));
    EXPECT_TRUE(has_warning(used, "extension EXT_made_up is not supported"));
    EXPECT_FALSE(has_warning(used, "KHR_materials_specular"));
}

// Values out of the extensions' ranges are errors naming the material and the key.
TEST(GltfExtensions, BadExtensionValuesAreErrors) {
    test::TempDir dir;
    const std::string bad_colour = test::error_of([&] {
        import(dir, gltf(R"({"extensions": {"KHR_materials_volume": {"attenuationDistance": 1,
                                              "attenuationColor": [0, 1, 1]}}})"));
    });
    EXPECT_NE(bad_colour.find("material 0"), std::string::npos) << bad_colour;
    EXPECT_NE(bad_colour.find("attenuationColor"), std::string::npos) << bad_colour;
    const std::string bad_factor = test::error_of([&] {
        import(dir, gltf(R"({"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 2}}})"));
    });
    EXPECT_NE(bad_factor.find("'clearcoatFactor' must be a number in [0, 1]"), std::string::npos)
        << bad_factor;
}

// A spot's fade starts at innerConeAngle, as the specification says; in a file from
// Blender's exporter, which writes inner = outer (1 - blend), it starts where Blender's
// does: cos = cos(outer) + (1 - cos(outer)) blend.
TEST(GltfExtensions, SpotFadeStartsAtInnerAngleOrWhereBlenderFades) {
    test::TempDir dir;
    const std::string json = gltf("{}", kLights, kLightNodes);
    const SceneDesc plain = import(dir, json);
    EXPECT_NEAR(plain.lights[1].get_float("falloff_start"), 0.3 * 180 / M_PI, 1e-4);
    EXPECT_NEAR(plain.lights[1].get_float("cone_angle"), 0.5 * 180 / M_PI, 1e-4);
    std::string blender = json;
    blender.replace(blender.find("\"version\": \"2.0\""), 16,
                    "\"version\": \"2.0\", \"generator\": \"Khronos glTF Blender I/O v3.4.50\"");
    const SceneDesc from_blender = import(dir, blender);
    const double blend = 1.0 - 0.3 / 0.5;
    const double start = std::acos(std::cos(0.5) + (1.0 - std::cos(0.5)) * blend);
    EXPECT_NEAR(from_blender.lights[1].get_float("falloff_start"), start * 180 / M_PI, 1e-4);
    EXPECT_NEAR(from_blender.lights[1].get_float("cone_angle"), 0.5 * 180 / M_PI, 1e-4);
}

// Blender 3's clear coat is a quarter-weight lobe; its exporter writes the weight as it is.
TEST(GltfExtensions, BlenderClearcoatIsAQuarterWeight) {
    test::TempDir dir;
    std::string json = gltf(
        R"({"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.1}}})");
    EXPECT_NEAR(import(dir, json).materials[0].get_float("clearcoat"), 0.8, 1e-6);
    json.replace(json.find("\"version\": \"2.0\""), 16,
                 "\"version\": \"2.0\", \"generator\": \"Khronos glTF Blender I/O v3.4.50\"");
    const SceneDesc desc = import(dir, json);
    EXPECT_NEAR(desc.materials[0].get_float("clearcoat"), 0.2, 1e-6);
    EXPECT_NEAR(desc.materials[0].get_float("clearcoat_roughness"), 0.1, 1e-6);
}

// `glint render model.gltf` sizes its image by the camera's aspectRatio: the default height,
// the width the ratio gives; a file without one keeps the default square image.
TEST(GltfExtensions, CameraAspectRatioSizesAModelRender) {
    test::TempDir dir;
    std::string json = gltf("{}", R"(,
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "aspectRatio": 1.7777778, "znear": 0.1}}])",
                            R"(, {"camera": 0, "translation": [0, 1, 5]})");
    std::ofstream(dir.file("model.gltf")) << json;
    write_image(dir.file("image.png"), make_image(2, 2, {"R", "G", "B"}));
    const SceneDesc desc = load_model_scene(dir.file("model.gltf"));
    ASSERT_TRUE(desc.render.has_value());
    EXPECT_EQ(desc.render->get_int("width", 0), 910);
    EXPECT_EQ(desc.render->get_int("height", 0), 512);
    json.replace(json.find(", \"aspectRatio\": 1.7777778"), 26, "");
    std::ofstream(dir.file("square.gltf")) << json;
    EXPECT_FALSE(load_model_scene(dir.file("square.gltf")).render.has_value());
}

// KHR_materials_dispersion's `dispersion` is 20 / V_d: the principled material's Abbe number.
TEST(GltfExtensions, DispersionBecomesTheAbbeNumber) {
    test::TempDir dir;
    const std::string material = R"({"extensions": {
        "KHR_materials_ior": {"ior": 1.6},
        "KHR_materials_transmission": {"transmissionFactor": 1},
        "KHR_materials_dispersion": {"dispersion": 0.5}}})";
    const SceneDesc desc = import(dir, gltf(material));
    ASSERT_EQ(desc.materials.size(), 1u);
    EXPECT_NEAR(desc.materials[0].get_float("abbe"), 40.0, 1e-6);
    EXPECT_NEAR(desc.materials[0].get_float("ior"), 1.6, 1e-6);
    const SceneDesc plain = import(dir, gltf(R"({"extensions": {
        "KHR_materials_dispersion": {"dispersion": 0}}})"));
    EXPECT_FALSE(plain.materials[0].has("abbe"));
}
