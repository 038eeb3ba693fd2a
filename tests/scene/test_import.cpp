// glint.import: OBJ with its .mtl, glTF/GLB (meshes, hierarchy, instancing, materials,
// textures, camera, lights) and PLY come into the scene description with the expected
// counts, transforms, materials and texture bindings; bad files are errors naming the
// script line and the file.
#include <glint/core/error.h>
#include <glint/scene/build.h>
#include <glint/scene/import/import.h>
#include <glint/scene/import/mtl.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/test_util.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace glint;
using glint::test::contains;
using glint::test::error_of;

namespace {

void write(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

SceneDesc load(const std::string& code, const test::TempDir& dir) {
    return load_scene_string(code, "scene.lua", dir.file(""));
}

std::vector<double> numbers(const Params& p, const std::string& name) {
    return p.get_numbers(name);
}

void expect_near(const std::vector<double>& a, const std::vector<double>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5) << "entry " << i;
}

const MeshData& mesh_of(const SceneDesc& desc, const Params& shape) {
    return *desc.meshes.at(shape.get_ref("data", "mesh_data").index);
}

const char* kObj =
    "mtllib model.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "f 1 2 3\n"
    "usemtl red\nf 1 2 3\n"
    "usemtl shiny\nf 1 3 4\n"
    "usemtl red\nf 2 3 4\n"
    "usemtl glass\nf 1 2 4\n"
    "usemtl lamp\nf 1 2 3\n"
    "usemtl textured\nf 1 2 3 4\n"
    "usemtl missing\nf 1 2 3\n";

const char* kMtl =
    "# materials of a test\n"
    "newmtl red\nKa 0 0 0\nKd 0.8 0.1 0.1\n"
    "newmtl shiny\nKd 0.6 0.6 0.6\nKs 0.6 0.6 0.6\nNs 200\n"
    "newmtl glass\nillum 7\nNi 1.45\n"
    "newmtl lamp\nKe 5 5 4\n"
    "newmtl textured\nKd 1 1 1\nmap_Kd -s 2 3 tex/wood.png\nmap_Bump -bm 0.3 bump.png\n";

// A GLB container around a JSON chunk and a binary chunk.
std::string glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out;
    auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(0x46546C67);
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    u32(static_cast<uint32_t>(json.size()));
    u32(0x4E4F534A);
    out += json;
    u32(static_cast<uint32_t>(bin.size()));
    u32(0x004E4942);
    out += bin;
    return out;
}

template <typename T>
void append(std::string& bin, std::initializer_list<T> values) {
    for (T v : values) bin.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

// A quad mesh placed twice (instanced) under a translated parent, a triangle placed once
// rotated, two materials with textures and extensions, a camera and three lights.
std::string gltf_json(int position_count = 4) {
    return R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength",
                     "KHR_materials_transmission", "KHR_materials_ior"],
  "buffers": [{"byteLength": 148}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 128, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 140, "byteLength": 8}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
           std::to_string(position_count) + R"(, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
                {"bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                              "indices": 3, "material": 0}]},
             {"primitives": [{"attributes": {"POSITION": 0}, "indices": 4, "material": 1}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                          "metallicFactor": 0.25, "roughnessFactor": 0.75,
                                          "metallicRoughnessTexture": {"index": 1}},
                 "normalTexture": {"index": 1},
                 "emissiveFactor": [1, 0.5, 0],
                 "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}},
                {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1]},
                 "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                                "KHR_materials_ior": {"ior": 1.33}}}],
  "textures": [{"source": 0, "sampler": 0}, {"source": 0}],
  "samplers": [{"wrapS": 33071, "wrapT": 33071}],
  "images": [{"bufferView": 4, "mimeType": "image/png"}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}}],
  "extensions": {"KHR_lights_punctual": {"lights": [
      {"type": "point", "color": [1, 1, 1], "intensity": 10},
      {"type": "spot", "intensity": 5, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}},
      {"type": "directional", "intensity": 2, "color": [1, 0.5, 0.25]}]}},
  "nodes": [{"translation": [10, 0, 0], "children": [1, 2]},
            {"mesh": 0, "translation": [0, 1, 0]},
            {"mesh": 0, "scale": [2, 2, 2]},
            {"mesh": 1, "rotation": [0, 0, 0.70710678, 0.70710678]},
            {"camera": 0, "translation": [0, 0, 5]},
            {"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"rotation": [-0.70710678, 0, 0, 0.70710678],
             "extensions": {"KHR_lights_punctual": {"light": 2}}}],
  "scenes": [{"nodes": [0, 3, 4, 5, 6, 7]}],
  "scene": 0
})";
}

std::string gltf_bin() {
    std::string bin;
    append<float>(bin, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});  // positions
    append<float>(bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});  // normals
    append<float>(bin, {0, 0, 1, 0, 1, 0.25f, 0, 1});          // uvs (top-left origin)
    append<uint16_t>(bin, {0, 1, 2, 0, 2, 3});                 // indices
    bin += "notapng!";                                         // an embedded "image"
    return bin;
}

}  // namespace

TEST(ImportObj, MtlMaterialsMapToGlintMaterials) {
    test::TempDir dir;
    write(dir.file("model.obj"), kObj);
    write(dir.file("model.mtl"), kMtl);
    const SceneDesc desc = load("glint.import{ file = 'model.obj' }", dir);
    const std::vector<Params>& shapes = desc.groups[0].shapes;
    // Parts in order of first use: none, red, shiny, glass, lamp, textured, missing.
    ASSERT_EQ(shapes.size(), 7u);
    EXPECT_EQ(mesh_of(desc, shapes[1]).indices.size(), 6u);  // both red faces
    EXPECT_EQ(mesh_of(desc, shapes[5]).indices.size(), 6u);  // the quad, fanned
    auto material = [&](size_t shape) -> const Params& {
        return desc.materials.at(shapes[shape].get_ref("material", "material").index);
    };
    EXPECT_EQ(material(0).type(), "diffuse");
    EXPECT_EQ(material(1).type(), "diffuse");
    expect_near(numbers(material(1), "reflectance"), {0.8, 0.1, 0.1});
    EXPECT_EQ(material(2).type(), "phong");
    // Kd + Ks = 1.2 is scaled down to 1 so the surface creates no energy.
    expect_near(numbers(material(2), "diffuse"), {0.5, 0.5, 0.5});
    expect_near(numbers(material(2), "specular"), {0.5, 0.5, 0.5});
    EXPECT_EQ(material(2).get_float("exponent"), 200.0f);
    EXPECT_EQ(material(3).type(), "dielectric");
    EXPECT_FLOAT_EQ(material(3).get_float("ior"), 1.45f);
    EXPECT_EQ(material(4).type(), "emissive");
    expect_near(numbers(material(4), "radiance"), {5, 5, 4});
    EXPECT_EQ(material(5).type(), "diffuse");
    const Params& wood = desc.textures.at(material(5).get_ref("reflectance", "texture").index);
    EXPECT_EQ(wood.type(), "image");
    EXPECT_EQ(wood.get_string("file"),
              (std::filesystem::path(dir.file("")) / "tex/wood.png").lexically_normal().string());
    EXPECT_EQ(wood.get_string("encoding"), "auto");
    expect_near(numbers(wood, "scale"), {2, 3});
    const Params& bump = desc.textures.at(material(5).get_ref("bump", "texture").index);
    EXPECT_EQ(bump.get_string("encoding"), "linear");
    EXPECT_FLOAT_EQ(material(5).get_float("bump_scale"), 0.3f);
    // One material per name however often it is used; the missing one is grey and warned of.
    EXPECT_EQ(desc.materials.size(), 7u);
    EXPECT_EQ(material(6).type(), "diffuse");
    ASSERT_FALSE(desc.warnings.empty());
    EXPECT_TRUE(contains(desc.warnings.back(), "material 'missing'"));
    EXPECT_TRUE(contains(desc.warnings.back(), "model.obj:19"));
}

TEST(ImportObj, LuaMaterialOverridesAndTransformApplies) {
    test::TempDir dir;
    write(dir.file("model.obj"), kObj);
    const SceneDesc desc = load(
        "local m = glint.diffuse{}\n"
        "glint.import{ file = 'model.obj', material = m, transform = glint.translate(0, 0, 7) }",
        dir);
    // No .mtl was needed: one merged mesh with the script's material.
    ASSERT_EQ(desc.groups[0].shapes.size(), 1u);
    EXPECT_EQ(desc.groups[0].shapes[0].get_ref("material", "material").index, 0);
    EXPECT_EQ(desc.materials.size(), 1u);
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    EXPECT_EQ(scene->stats().triangles, 9u);
    EXPECT_FLOAT_EQ(scene->stats().bounds.min.z, 7.0f);
}

TEST(ImportObj, ErrorsNameTheScriptLineAndTheFile) {
    test::TempDir dir;
    write(dir.file("model.obj"), kObj);
    write(dir.file("model.mtl"), "newmtl red\nKd 0.8 x 0.1\n");
    EXPECT_TRUE(contains(error_of([&] { load("\nglint.import{ file = 'model.obj' }", dir); }),
                         "scene.lua:2: import: "));
    EXPECT_TRUE(contains(error_of([&] { load("glint.import{ file = 'model.obj' }", dir); }),
                         "model.mtl:2: 'Kd' needs one or three numbers"));
    EXPECT_TRUE(contains(error_of([&] { load("glint.import{ file = 'nothing.obj' }", dir); }),
                         "nothing.obj"));
    EXPECT_TRUE(contains(error_of([&] { load("glint.import{ file = 'model.fbx' }", dir); }),
                         "unknown file type '.fbx'"));
    EXPECT_TRUE(contains(
        error_of([&] { load("glint.import{ file = 'model.obj', colour = 1 }", dir); }), "colour"));
    write(dir.file("bad.obj"), "v 0 0 0\nf 1 2 3\n");
    EXPECT_TRUE(contains(error_of([&] { load("glint.import{ file = 'bad.obj' }", dir); }),
                         "bad.obj:2: face refers to vertex 2"));
}

TEST(ImportMtl, MapOptionsAndRanges) {
    const std::vector<MtlMaterial> m = parse_mtl(
        "newmtl a\nmap_Kd -clamp on -o 0.5 0.25 -bm 2 my texture.png\nd 0.5\nNi 1.3\n", "a.mtl");
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].map_kd->file, "my texture.png");
    EXPECT_TRUE(m[0].map_kd->clamp);
    EXPECT_EQ(m[0].map_kd->offset, Vec2(0.5f, 0.25f));
    std::vector<Params> textures;
    std::vector<std::string> warnings;
    EXPECT_EQ(mtl_to_params(m[0], "/x", textures, warnings).type(), "dielectric");
    EXPECT_TRUE(contains(error_of([] { parse_mtl("Kd 1 1 1\n", "a.mtl"); }), "a.mtl:1:"));
    EXPECT_TRUE(contains(error_of([] { parse_mtl("newmtl a\nNs -1\n", "a.mtl"); }), "a.mtl:2:"));
    EXPECT_TRUE(
        contains(error_of([] { parse_mtl("newmtl a\nmap_Kd -bm\n", "a.mtl"); }), "needs a number"));
    EXPECT_TRUE(contains(error_of([] { parse_mtl("newmtl a\nmap_Kd -s 1 1\n", "a.mtl"); }),
                         "needs a file name"));
}

TEST(ImportGltf, HierarchyInstancingMaterialsCameraAndLights) {
    test::TempDir dir;
    write(dir.file("model.glb"), glb(gltf_json(), gltf_bin()));
    const SceneDesc desc = load("glint.import{ file = 'model.glb' }", dir);
    // The quad placed twice is one group with two placements; the triangle is a shape.
    ASSERT_EQ(desc.groups.size(), 2u);
    ASSERT_EQ(desc.groups[1].shapes.size(), 1u);
    EXPECT_FALSE(desc.groups[1].shapes[0].has("transform"));
    const std::vector<InstanceDesc>& instances = desc.groups[0].instances;
    ASSERT_EQ(instances.size(), 2u);
    EXPECT_EQ(instances[0].transform.point(Vec3(1, 1, 0)), Vec3(11, 2, 0));
    EXPECT_EQ(instances[1].transform.point(Vec3(1, 1, 0)), Vec3(12, 2, 0));
    ASSERT_EQ(desc.groups[0].shapes.size(), 1u);
    const Params& triangle = desc.groups[0].shapes[0];
    const Vec3 turned = triangle.get_transform("transform").point(Vec3(1, 0, 0));
    EXPECT_NEAR(turned.x, 0.0f, 1e-6f);
    EXPECT_NEAR(turned.y, 1.0f, 1e-6f);
    EXPECT_EQ(mesh_of(desc, triangle).indices.size(), 3u);
    // uvs flip from glTF's top-left origin to glint's bottom-left.
    const MeshData& quad = mesh_of(desc, desc.groups[1].shapes[0]);
    ASSERT_EQ(quad.uvs.size(), 4u);
    EXPECT_EQ(quad.uvs[2], Vec2(1.0f, 0.75f));
    EXPECT_EQ(quad.normals.size(), 4u);

    const Params& a =
        desc.materials.at(desc.groups[1].shapes[0].get_ref("material", "material").index);
    EXPECT_EQ(a.type(), "principled");
    EXPECT_FLOAT_EQ(a.get_float("metallic"), 0.25f);
    EXPECT_FLOAT_EQ(a.get_float("roughness"), 0.75f);
    expect_near(numbers(a, "emission"), {1, 0.5, 0});
    EXPECT_FLOAT_EQ(a.get_float("emission_strength"), 4.0f);
    const Params& base = desc.textures.at(a.get_ref("base_color", "texture").index);
    EXPECT_EQ(base.get_string("encoding"), "srgb");
    EXPECT_EQ(base.get_string("wrap"), "clamp");
    const ObjectRef mr = a.get_ref("metallic_roughness", "texture");
    EXPECT_EQ(desc.textures.at(mr.index).get_string("encoding"), "linear");
    EXPECT_EQ(a.get_ref("normal_map", "texture").index, mr.index);  // one texture, linear
    EXPECT_EQ(desc.textures.size(), 2u);
    // The embedded image was written out once, with its bytes.
    std::ifstream image(base.get_string("file"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(image)), std::istreambuf_iterator<char>());
    EXPECT_EQ(bytes, "notapng!");

    const Params& b = desc.materials.at(triangle.get_ref("material", "material").index);
    expect_near(numbers(b, "base_color"), {0.2, 0.4, 0.6});
    EXPECT_FLOAT_EQ(b.get_float("transmission"), 1.0f);
    EXPECT_FLOAT_EQ(b.get_float("ior"), 1.33f);

    ASSERT_TRUE(desc.camera);
    EXPECT_TRUE(desc.camera_imported);
    expect_near(numbers(*desc.camera, "eye"), {0, 0, 5});
    expect_near(numbers(*desc.camera, "look_at"), {0, 0, 4});
    EXPECT_NEAR(desc.camera->get_float("fov"), 0.5 * 180 / 3.14159265, 1e-4);

    ASSERT_EQ(desc.lights.size(), 3u);
    EXPECT_EQ(desc.lights[0].type(), "point_light");
    expect_near(numbers(desc.lights[0], "position"), {0, 3, 0});
    expect_near(numbers(desc.lights[0], "intensity"), {10 / 683.0, 10 / 683.0, 10 / 683.0});
    EXPECT_EQ(desc.lights[1].type(), "spot_light");
    expect_near(numbers(desc.lights[1], "look_at"), {1, 2, 2});
    EXPECT_NEAR(desc.lights[1].get_float("cone_angle"), 0.4 * 180 / 3.14159265, 1e-4);
    EXPECT_NEAR(desc.lights[1].get_float("falloff_start"), 0.2 * 180 / 3.14159265, 1e-4);
    EXPECT_EQ(desc.lights[2].type(), "directional_light");
    expect_near(numbers(desc.lights[2], "direction"), {0, -1, 0});
    expect_near(numbers(desc.lights[2], "irradiance"), {2 / 683.0, 1 / 683.0, 0.5 / 683.0});
}

// With a Lua material the geometry builds today: counts, instances and bounds.
// A node's `matrix` is the same placement as its translation, rotation and scale applied as
// T * R * S (issue 28: a matrix read in the wrong order put a node translated by (10, 0, 0)
// at the origin, and no test noticed). The matrix is written column by column, as glTF
// stores it: T * R * S for T = (10, 0, 0), R = 90 degrees about z, S = (2, 1, 1).
TEST(ImportGltf, MatrixNodesPlaceAsTheSameTranslationRotationScale) {
    test::TempDir dir;
    const std::string triangle =
        "data:application/octet-stream;base64,"
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";  // (0,0,0), (1,0,0), (0,1,0)
    const float h = std::sqrt(0.5f);  // the quaternion (0, 0, sin 45, cos 45)
    write(dir.file("nodes.gltf"), fmt::format(R"({{
  "asset": {{"version": "2.0"}},
  "buffers": [{{"byteLength": 36, "uri": "{}"}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
  "nodes": [{{"mesh": 0, "matrix": [0, 2, 0, 0,  -1, 0, 0, 0,  0, 0, 1, 0,  10, 0, 0, 1]}},
            {{"mesh": 0, "translation": [10, 0, 0], "rotation": [0, 0, {}, {}],
              "scale": [2, 1, 1]}}],
  "scenes": [{{"nodes": [0, 1]}}]
}})",
                                              triangle, h, h));
    const SceneDesc desc = load("glint.import{ file = 'nodes.gltf' }", dir);
    const std::vector<InstanceDesc>& placed = desc.groups[0].instances;
    ASSERT_EQ(placed.size(), 2u);
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 2, 3)}) {
        // T * R * S: scaled along x first, then turned onto y, then moved by 10 along x.
        const Vec3 expected(10.0f - p.y, 2.0f * p.x, p.z);
        for (const InstanceDesc& instance : placed) {
            const Vec3 got = instance.transform.point(p);
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(got[axis], expected[axis], 1e-5f) << "axis " << axis;
        }
    }
}

TEST(ImportGltf, BuildsWithALuaMaterial) {
    test::TempDir dir;
    write(dir.file("model.gltf.glb"), glb(gltf_json(), gltf_bin()));
    const SceneDesc desc = load(
        "glint.import{ file = 'model.gltf.glb', material = glint.diffuse{}, light_scale = 0.5 }\n"
        "glint.camera{ eye = {0, 0, 20}, look_at = {0, 0, 0} }",
        dir);
    EXPECT_FALSE(desc.camera_imported);  // the script's camera replaced the file's
    expect_near(numbers(desc.lights[0], "intensity"), {5, 5, 5});
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    EXPECT_EQ(scene->stats().triangles, 1u + 2u * 2u);
    EXPECT_EQ(scene->stats().instances, 2u);
    EXPECT_EQ(scene->stats().groups, 1u);
    EXPECT_EQ(scene->stats().lights, 3u);
    EXPECT_FLOAT_EQ(scene->stats().bounds.max.x, 12.0f);
    EXPECT_FLOAT_EQ(scene->stats().bounds.min.x, -1.0f);
}

// To be enabled once the principled material (branch `principled`) is merged: the glTF
// materials then build as they are.
TEST(ImportGltf, BuildsWithPrincipledMaterials) {
    test::TempDir dir;
    write(dir.file("model.gltf"),
          "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 36, \"uri\": "
          "\"data:application/"
          "octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],"
          "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}],"
          "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": "
          "\"VEC3\"}],"
          "\"materials\": [{\"pbrMetallicRoughness\": {\"metallicFactor\": 0.5}}],"
          "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"material\": 0}]}],"
          "\"nodes\": [{\"mesh\": 0}], \"scenes\": [{\"nodes\": [0]}]}");
    const SceneDesc desc = load_model_scene(dir.file("model.gltf"));
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    EXPECT_EQ(scene->stats().triangles, 1u);
}

TEST(ImportGltf, MalformedAndTruncatedFilesAreErrors) {
    test::TempDir dir;
    const std::string good = glb(gltf_json(), gltf_bin());
    // Every cut of the file, also inside the JSON, gives an error naming it.
    for (size_t n = 0; n < good.size(); n += (n < 32 || n > good.size() - 64) ? 1 : 17) {
        write(dir.file("cut.glb"), good.substr(0, n));
        const std::string message =
            error_of([&] { load("glint.import{ file = 'cut.glb' }", dir); });
        ASSERT_TRUE(contains(message, "cut.glb")) << "cut at " << n << ": " << message;
        ASSERT_TRUE(contains(message, "scene.lua:1:")) << message;
    }
    // An accessor that claims more elements than its view holds.
    write(dir.file("long.glb"), glb(gltf_json(100), gltf_bin()));
    EXPECT_TRUE(contains(error_of([&] { load("glint.import{ file = 'long.glb' }", dir); }),
                         "runs past the end of buffer view 0"));
    write(dir.file("bad.gltf"), "{ \"asset\": ");
    EXPECT_TRUE(contains(error_of([&] { load("glint.import{ file = 'bad.gltf' }", dir); }),
                         "bad.gltf: not a valid glTF file"));
}

// `glint render model.obj` with no script: a camera framing the model and a background.
TEST(ImportModelScene, DefaultCameraAndBackground) {
    test::TempDir dir;
    write(dir.file("model.obj"), "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n");
    const SceneDesc desc = load_model_scene(dir.file("model.obj"));
    ASSERT_TRUE(desc.camera);
    ASSERT_TRUE(desc.background);
    expect_near(numbers(*desc.camera, "look_at"), {1, 1, 0});
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    EXPECT_EQ(scene->stats().triangles, 1u);
    // A file with lights gets no background, and its own camera.
    write(dir.file("model.glb"), glb(gltf_json(), gltf_bin()));
    const SceneDesc gltf = load_model_scene(dir.file("model.glb"));
    EXPECT_FALSE(gltf.background);
    EXPECT_TRUE(gltf.camera_imported);
    EXPECT_TRUE(is_model_file("A.GLB"));
    EXPECT_FALSE(is_model_file("a.lua"));
}

// An MTL mirror (illum 3, as Blender writes a metal) becomes a mirror that builds: its tint
// is Ks (the parameter was once named after diffuse's `reflectance`, an error at build).
TEST(ImportObj, MtlMirrorBuilds) {
    test::TempDir dir;
    write(dir.file("m.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl metal\nf 1 2 3\n");
    write(dir.file("m.mtl"), "newmtl metal\nKd 1 0.77 0.34\nKs 0.5 0.5 0.5\nillum 3\n");
    const SceneDesc desc = load("glint.import{ file = 'm.obj' }", dir);
    ASSERT_EQ(desc.materials.size(), 1u);
    EXPECT_EQ(desc.materials[0].type(), "mirror");
    expect_near(numbers(desc.materials[0], "tint"), {0.5, 0.5, 0.5});
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    EXPECT_EQ(scene->stats().triangles, 1u);
}
