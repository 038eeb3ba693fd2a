// pbrt-v4 scene files, translated: transforms against hand-computed matrices, pbrt's
// left-handed world rendered unmirrored, radiometric normalisations, and each supported
// material, light and shape rendered like the same scene written in Lua.
#include <glint/core/progress.h>
#include <glint/film/image_io.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/build.h>
#include <glint/scene/import/import.h>
#include <glint/scene/import/pbrt/loop_subdivision.h>
#include <glint/scene/import/pbrt/parser.h>
#include <glint/scene/import/pbrt/translator.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>
#include <glm/gtc/matrix_transform.hpp>

#include <fstream>
#include <map>

using namespace glint;
using glint::test::error_of;
using glint::test::contains;

namespace {

bool any_contains(const std::vector<std::string>& lines, const std::string& part) {
    for (const std::string& l : lines)
        if (contains(l, part)) return true;
    return false;
}

SceneDesc import_text(const test::TempDir& dir, const std::string& text,
                      const std::string& name = "scene.pbrt") {
    std::ofstream(dir.file(name)) << text;
    return load_model_scene(dir.file(name));
}

Image render(const SceneDesc& desc) {
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    auto integrator = make_integrator(settings);
    Film film(settings.output_width(), settings.output_height(), settings.aovs,
              settings.output_origin());
    Progress progress("test", 1, true);
    const RenderStats stats = integrator->render(*scene, film, progress);
    return final_image(film, stats);
}

double relative_mse(const Image& a, const Image& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    double sum = 0.0;
    size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c, ++n) {
                const double d = a.at(x, y, c) - b.at(x, y, c);
                sum += d * d / (double(b.at(x, y, c)) * b.at(x, y, c) + 0.01);
            }
    return sum / static_cast<double>(n);
}

// The pbrt file and the Lua scene give the same image: their difference is well below the
// noise of one render (measured between two seeds of the pbrt render itself).
void expect_same_image(const test::TempDir& dir, const std::string& pbrt, const std::string& lua) {
    const Image a = render(import_text(dir, pbrt));
    std::string reseeded = pbrt;
    reseeded.replace(reseeded.find("Sampler \"independent\""), 21,
                     "Sampler \"independent\" \"integer seed\" 7");
    const Image noise = render(import_text(dir, reseeded, "reseeded.pbrt"));
    const Image b = render(load_scene_string(lua, "same.lua"));
    const double noise_level = relative_mse(a, noise);
    const double difference = relative_mse(a, b);
    EXPECT_GT(noise_level, 0.0);
    EXPECT_LT(difference, 0.25 * noise_level) << "noise " << noise_level;
}

Vec3 numbers3(const Params& p, const std::string& name) {
    const std::vector<double> v = p.get_numbers(name);
    return Vec3(v.at(0), v.at(1), v.at(2));
}

void expect_vec(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

const char* kSettings =
    "Film \"rgb\" \"integer xresolution\" [ 48 ] \"integer yresolution\" [ 32 ]\n"
    "Sampler \"independent\" \"integer pixelsamples\" 4\n"
    "Integrator \"path\" \"integer maxdepth\" [ 1 ]\n";

std::string markers(const std::string& camera) {
    return camera + "Camera \"perspective\" \"float fov\" [ 40 ]\n" + kSettings +
           "WorldBegin\n"
           "AttributeBegin\n AreaLightSource \"diffuse\" \"rgb L\" [ 1 0 0 ]\n"
           " Translate 1.2 0 0\n Shape \"sphere\" \"float radius\" 0.3\nAttributeEnd\n"
           "AttributeBegin\n AreaLightSource \"diffuse\" \"rgb L\" [ 0 1 0 ]\n"
           " Translate 0 1 0\n Shape \"sphere\" \"float radius\" 0.3\nAttributeEnd\n"
           "AttributeBegin\n AreaLightSource \"diffuse\" \"rgb L\" [ 0 0 1 ]\n"
           " Translate -1.2 -0.8 0\n Shape \"sphere\" \"float radius\" 0.3\nAttributeEnd\n";
}

// The centre of the pixels where channel c dominates.
Vec2 centroid(const Image& image, int c) {
    Vec2 sum(0.0f);
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float v = image.at(x, y, c);
            if (v > 0.3f &&
                v > 4.0f * (image.at(x, y, (c + 1) % 3) + image.at(x, y, (c + 2) % 3))) {
                sum += Vec2(x + 0.5f, y + 0.5f);
                ++count;
            }
        }
    EXPECT_GT(count, 4) << "channel " << c;
    return sum / static_cast<float>(std::max(count, 1));
}

}  // namespace

TEST(PbrtTransforms, TranslateScaleRotateTransformAgainstHandComputedMatrices) {
    const PbrtScene s = parse_pbrt_text(
        "WorldBegin\nAttributeBegin\nTranslate 1 2 3\nScale 2 2 2\nShape \"a\"\nAttributeEnd\n"
        "AttributeBegin\nRotate 90 0 0 1\nShape \"b\"\nAttributeEnd\n"
        "AttributeBegin\nTransform [ 1 0 0 0  0 1 0 0  0 0 1 0  5 6 7 1 ]\nShape \"c\"\n"
        "Translate 1 0 0\nConcatTransform [ 0 1 0 0  -1 0 0 0  0 0 1 0  0 0 0 1 ]\nShape \"d\"\n"
        "AttributeEnd\n",
        "t.pbrt", ".");
    ASSERT_EQ(s.shapes.size(), 4u);
    // Translate then Scale: a point is scaled first, p' = T S p.
    EXPECT_EQ(s.shapes[0].to_world * Vec4(1, 1, 1, 1), Vec4(3, 4, 5, 1));
    // Rotate 90 about z: x -> y, y -> -x (the matrix [[0 -1 0] [1 0 0] [0 0 1]]).
    expect_vec(Vec3(s.shapes[1].to_world * Vec4(1, 0, 0, 0)), Vec3(0, 1, 0));
    expect_vec(Vec3(s.shapes[1].to_world * Vec4(0, 1, 0, 0)), Vec3(-1, 0, 0));
    // Transform's 16 numbers are the columns in turn: the translation is the 13th-15th.
    EXPECT_EQ(s.shapes[2].to_world * Vec4(0, 0, 0, 1), Vec4(5, 6, 7, 1));
    const Mat4& d = s.shapes[3].to_world;
    // ConcatTransform multiplies on the right: its columns map x -> y, y -> -x.
    EXPECT_EQ(d * Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0));
    EXPECT_EQ(d * Vec4(0, 0, 0, 1), Vec4(6, 6, 7, 1));
}

TEST(PbrtTransforms, LookAtAndNamedCoordinateSystems) {
    const PbrtScene s = parse_pbrt_text(
        "LookAt 1 2 3  2 2 3  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "Translate 0 0 9\nCoordinateSystem \"mine\"\nIdentity\nShape \"a\"\n"
        "CoordSysTransform \"mine\"\nShape \"b\"\nCoordSysTransform \"camera\"\nShape \"c\"\n",
        "t.pbrt", ".");
    ASSERT_TRUE(s.camera);
    // Looking along +x with +y up, pbrt's (left-handed) camera has its +x, the image's
    // right, along up x dir = y x x = -z, and +z along the view: world-from-camera has
    // the columns (0 0 -1), (0 1 0), (1 0 0) and the eye (1 2 3).
    const Mat4& c = s.camera->camera_to_world;
    expect_vec(Vec3(c * Vec4(1, 0, 0, 0)), Vec3(0, 0, -1));
    expect_vec(Vec3(c * Vec4(0, 1, 0, 0)), Vec3(0, 1, 0));
    expect_vec(Vec3(c * Vec4(0, 0, 1, 0)), Vec3(1, 0, 0));
    expect_vec(Vec3(c * Vec4(0, 0, 0, 1)), Vec3(1, 2, 3));
    ASSERT_EQ(s.shapes.size(), 3u);
    EXPECT_EQ(s.shapes[0].to_world, Mat4(1.0f));
    EXPECT_EQ(s.shapes[1].to_world * Vec4(0, 0, 0, 1), Vec4(0, 0, 9, 1));
    EXPECT_EQ(s.shapes[2].to_world, c);
}

TEST(PbrtHandedness, WorldMirrorCancelsAMirroringCamera) {
    const Mat4 mirror = glm::scale(Mat4(1.0f), Vec3(-1, 1, 1));
    EXPECT_EQ(PbrtTranslator::world_mirror(std::nullopt), mirror);
    const PbrtScene plain =
        parse_pbrt_text("LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\"\n", "a.pbrt", ".");
    EXPECT_EQ(PbrtTranslator::world_mirror(plain.camera), mirror);
    const PbrtScene flipped = parse_pbrt_text(
        "Scale -1 1 1\nLookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\"\n", "a.pbrt", ".");
    EXPECT_EQ(PbrtTranslator::world_mirror(flipped.camera), Mat4(1.0f));
}

TEST(PbrtHandedness, ThreeMarkersRenderUnmirroredAsTheLuaScene) {
    test::TempDir dir;
    const Image pbrt = render(import_text(dir, markers("LookAt 0 0 -5   0 0 0   0 1 0\n")));
    // pbrt's camera puts +x (red) on the right, +y (green) at the top, and blue at the lower left.
    const Vec2 red = centroid(pbrt, 0), green = centroid(pbrt, 1), blue = centroid(pbrt, 2);
    EXPECT_GT(red.x, 34.0f);
    EXPECT_NEAR(red.y, 16.0f, 1.0f);
    EXPECT_NEAR(green.x, 24.0f, 1.0f);
    EXPECT_LT(green.y, 8.0f);
    EXPECT_LT(blue.x, 14.0f);
    EXPECT_GT(blue.y, 20.0f);
    // The same picture written for glint, whose camera looking along +z has +x on the left.
    const Image lua = render(load_scene_string(R"(
        glint.camera{ eye = {0, 0, -5}, look_at = {0, 0, 0}, fov = 40 }
        glint.render{ width = 48, height = 32, spp = 4, max_depth = 1, sampler = "independent",
                      filter = "gaussian", filter_radius = 1.5 }
        glint.sphere{ center = {-1.2, 0, 0}, radius = 0.3, material = glint.emissive{ radiance = {1, 0, 0} } }
        glint.sphere{ center = {0, 1, 0}, radius = 0.3, material = glint.emissive{ radiance = {0, 1, 0} } }
        glint.sphere{ center = {1.2, -0.8, 0}, radius = 0.3, material = glint.emissive{ radiance = {0, 0, 1} } }
    )",
                                               "markers.lua"));
    for (int c = 0; c < 3; ++c) {
        const Vec2 a = centroid(pbrt, c), b = centroid(lua, c);
        EXPECT_NEAR(a.x, b.x, 0.25f) << c;
        EXPECT_NEAR(a.y, b.y, 0.25f) << c;
    }
    // "Scale -1 1 1" before the LookAt mirrors pbrt's own image: red goes to the left.
    const Image flipped =
        render(import_text(dir, markers("Scale -1 1 1\nLookAt 0 0 -5  0 0 0  0 1 0\n"), "f.pbrt"));
    EXPECT_LT(centroid(flipped, 0).x, 14.0f);
    EXPECT_LT(centroid(flipped, 1).y, 8.0f);
    EXPECT_GT(centroid(flipped, 2).x, 34.0f);
}

TEST(PbrtCamera, FieldOfViewIsOnTheShorterSide) {
    test::TempDir dir;
    const std::string head =
        "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 40 "
        "\"float lensradius\" 0.1 \"float focaldistance\" 3\n";
    const SceneDesc wide = import_text(
        dir, head + "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 32\n");
    EXPECT_NEAR(wide.camera->get_float("fov"), 40.0f, 1e-4f);
    EXPECT_NEAR(wide.camera->get_float("aperture"), 0.1f, 1e-6f);
    EXPECT_NEAR(wide.camera->get_float("focus_distance"), 3.0f, 1e-6f);
    const SceneDesc tall = import_text(
        dir, head + "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 64\n");
    // The 40 degrees span the width; the height is twice as tall: 2 atan(2 tan 20 deg) =
    // 2 atan(0.727940) = 72.1048 degrees.
    EXPECT_NEAR(tall.camera->get_float("fov"), 72.1048f, 1e-3f);
    EXPECT_EQ(tall.render->get_int("width", 0), 32);
    EXPECT_EQ(tall.render->get_int("height", 0), 64);
    const SceneDesc ortho = import_text(dir,
                                        "Camera \"orthographic\"\nFilm \"rgb\" \"integer "
                                        "xresolution\" 32 \"integer yresolution\" 64\n");
    EXPECT_EQ(ortho.camera->get_string("type"), "orthographic");
    EXPECT_NEAR(ortho.camera->get_float("scale"), 4.0f, 1e-6f);
}

TEST(PbrtRadiometry, ScalePowerIlluminanceBlackbodyAndIso) {
    test::TempDir dir;
    const SceneDesc d = import_text(
        dir,
        "Film \"rgb\" \"float iso\" 200\nWorldBegin\n"
        "LightSource \"point\" \"rgb I\" [1 2 3] \"float power\" 100 \"point3 from\" [1 0 0]\n"
        "LightSource \"spot\" \"float power\" 10 \"float coneangle\" 30 \"float conedeltaangle\" "
        "10\n"
        "LightSource \"distant\" \"blackbody L\" 6500 \"float illuminance\" 5 \"point3 to\" [0 -1 "
        "0]\n"
        "LightSource \"infinite\" \"rgb L\" [1 1 1] \"float illuminance\" 3.14159265\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [2 2 2] \"float power\" 6.28318531\n"
        "Shape \"trianglemesh\" \"point3 P\" [0 0 0  1 0 0  1 1 0  0 1 0] \"integer indices\" [0 1 "
        "2 0 2 3]\n"
        "AttributeEnd\nAttributeBegin\nAreaLightSource \"diffuse\" \"float scale\" 3\n"
        "Shape \"sphere\" \"float radius\" 2\nAttributeEnd\n");
    ASSERT_EQ(d.lights.size(), 3u);
    const float iso = 2.0f;
    // Point: power / 4 pi, times the RGB (pbrt normalises only the illuminant), mirrored x.
    expect_vec(numbers3(d.lights[0], "intensity"), iso * Vec3(1, 2, 3) * 100.0f / (4.0f * kPi),
               1e-4f);
    expect_vec(numbers3(d.lights[0], "position"), Vec3(-1, 0, 0));
    // Spot: power over 2 pi ((1 - cos 20) + (cos 20 - cos 30) / 2).
    const float cone = 2.0f * kPi *
                       ((1 - std::cos(glm::radians(20.0f))) +
                        (std::cos(glm::radians(20.0f)) - std::cos(glm::radians(30.0f))) / 2);
    expect_vec(numbers3(d.lights[1], "intensity"), Vec3(iso * 10.0f / cone), 1e-3f);
    EXPECT_NEAR(d.lights[1].get_float("falloff_start"), 20.0f, 1e-5f);
    // Distant: illuminance on a patch facing it; a blackbody has luminance 1 per unit.
    const Vec3 e = numbers3(d.lights[2], "irradiance");
    EXPECT_NEAR(0.2126f * e.x + 0.7152f * e.y + 0.0722f * e.z, iso * 5.0f, 1e-3f);
    expect_vec(numbers3(d.lights[2], "direction"), Vec3(0, -1, 0));
    // Infinite: illuminance pi L.
    expect_vec(numbers3(*d.background, "radiance"), Vec3(iso * 1.0f), 1e-5f);
    // Area: power / (pi area) for the unit square (both triangles of area 1/2: per triangle).
    int emissive = 0;
    for (const Params& m : d.materials) {
        if (m.type() != "emissive") continue;
        const Vec3 radiance = numbers3(m, "radiance");
        if (emissive++ == 0)
            expect_vec(radiance, Vec3(iso * 2.0f * 6.28318531f / (kPi * 0.5f)), 1e-3f);
        else
            expect_vec(radiance, Vec3(iso * 3.0f), 1e-5f);  // default L: the illuminant, 1
    }
    EXPECT_EQ(emissive, 2);
}

TEST(PbrtMaterials, RoughnessRemappingAndReflectance) {
    test::TempDir dir;
    const SceneDesc d = import_text(
        dir,
        "WorldBegin\nMaterial \"conductor\" \"float roughness\" 0.01\nShape \"sphere\"\n"
        "Material \"conductor\" \"float roughness\" 0.04 \"bool remaproughness\" false "
        "\"rgb reflectance\" [0.5 0.5 0.5]\nShape \"sphere\"\n"
        "Material \"conductor\" \"float uroughness\" 0.04 \"float vroughness\" 0.01 "
        "\"bool remaproughness\" false\nShape \"sphere\"\n"
        "Material \"dielectric\" \"spectrum eta\" \"glass-BK7\"\nShape \"sphere\"\n");
    std::vector<const Params*> m;
    for (const Params& p : d.materials) m.push_back(&p);
    ASSERT_EQ(m.size(), 4u);
    // pbrt's alpha = sqrt(roughness) when remapped; glint's roughness = sqrt(alpha).
    EXPECT_NEAR(m[0]->get_float("roughness"), std::pow(0.01f, 0.25f), 1e-6f);
    expect_vec(numbers3(*m[0], "eta"), Vec3(0.2166f, 0.9582f, 1.1658f), 1e-4f);  // copper
    EXPECT_NEAR(m[1]->get_float("roughness"), 0.2f, 1e-6f);
    // eta 1, k = 2 sqrt(r) / sqrt(1 - r): the normal-incidence reflectance is r.
    const float k = numbers3(*m[1], "k").x;
    EXPECT_NEAR(k * k / (4.0f + k * k), 0.5f, 1e-4f);
    // Anisotropic: alpha 0.2 = sqrt(0.04 * 0.01); u twice as rough as v.
    EXPECT_NEAR(m[2]->get_float("roughness"), std::sqrt(0.02f), 1e-6f);
    EXPECT_NEAR(m[2]->get_float("anisotropy"), (1.0f - 0.25f) / 0.9f, 1e-5f);
    EXPECT_NEAR(m[3]->get_float("ior"), 1.5185f, 2e-4f);
}

TEST(PbrtImport, UnsupportedIsWarnedWithFileAndLineAndNotesSumUp) {
    test::TempDir dir;
    const SceneDesc d = import_text(
        dir,
        "WorldBegin\nMaterial \"measured\" \"string filename\" \"x.bsdf\"\nShape \"sphere\"\n"
        "Material \"diffuse\" \"float sigma\" 3\nShape \"curve\" \"point3 P\" [0 0 0 1 1 1 2 2 2 3 "
        "3 3]\n"
        "Shape \"sphere\" \"float alpha\" 0.5 \"float radius\" 0.5\n"
        "LightSource \"goniometric\"\n");
    EXPECT_TRUE(
        any_contains(d.warnings, "scene.pbrt:2: Material: material \"measured\" is not supported"));
    EXPECT_TRUE(any_contains(
        d.warnings,
        "scene.pbrt:4: Material \"diffuse\": parameter \"float sigma\" is not supported"));
    EXPECT_TRUE(any_contains(d.warnings, "scene.pbrt:5: Shape: shape \"curve\" is not supported"));
    EXPECT_TRUE(any_contains(d.warnings, "scene.pbrt:6: Shape: \"alpha\" cut-outs"));
    EXPECT_TRUE(any_contains(d.warnings, "scene.pbrt:7: LightSource: light \"goniometric\""));
    EXPECT_TRUE(any_contains(d.notes, "2 Material"));
    EXPECT_TRUE(any_contains(d.notes, "1 shapes"));
}

TEST(PbrtImport, ErrorsNameTheFileAndLine) {
    test::TempDir dir;
    EXPECT_TRUE(contains(error_of([&] {
                             import_text(dir,
                                         "WorldBegin\nNamedMaterial \"nope\"\nShape \"sphere\"\n");
                         }),
                         "scene.pbrt:3: NamedMaterial \"nope\" is not defined"));
    EXPECT_TRUE(contains(error_of([&] {
                             import_text(dir,
                                         "WorldBegin\n\nShape \"trianglemesh\" \"point3 P\" [0 0 0 "
                                         "1 0 0 0 1 0] \"integer indices\" [0 1 3]\n");
                         }),
                         "scene.pbrt:3: parameter 'indices': index 3 is outside the 3 vertices"));
    EXPECT_TRUE(
        contains(error_of([&] { import_text(dir, "WorldBegin\nObjectInstance \"ghost\"\n"); }),
                 "scene.pbrt:2: ObjectInstance \"ghost\": no object of that name"));
    EXPECT_TRUE(contains(
        error_of([&] {
            import_text(dir, "WorldBegin\nShape \"plymesh\" \"string filename\" \"none.ply\"\n");
        }),
        "scene.pbrt:2: Shape \"plymesh\""));
    // Through the command line: exit status 1, the message, and no output file.
    std::ofstream(dir.file("bad.pbrt")) << "WorldBegin\nShape \"sphere\" \"float radius\" [ 1\n";
    const auto result = test::run_glint(fmt::format("render {} -o {} --res 8x8 --spp 1",
                                                    dir.file("bad.pbrt"), dir.file("bad.exr")));
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(
        contains(result.output, "bad.pbrt:2: parameter \"float radius\": '[' is not closed"))
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.exr")));
    std::ofstream(dir.file("ok.pbrt")) << "WorldBegin\nAccelerator \"bvh\"\nShape \"sphere\"\n";
    const auto info = test::run_glint("info " + dir.file("ok.pbrt"));
    EXPECT_EQ(info.exit_code, 0);
    EXPECT_TRUE(contains(info.output, "ok.pbrt:2: Accelerator: ignored")) << info.output;
    EXPECT_TRUE(contains(info.output, "note: ")) << info.output;
}

TEST(PbrtImages, MaterialsAndAnAreaLightAsInLua) {
    test::TempDir dir;
    const std::string pbrt = R"(
LookAt 0 1 -6  0 0.5 0  0 1 0
Camera "perspective" "float fov" 35
Film "rgb" "integer xresolution" 32 "integer yresolution" 24
Sampler "independent" "integer pixelsamples" 8
Integrator "path" "integer maxdepth" 3
WorldBegin
LightSource "infinite" "rgb L" [0.3 0.3 0.3]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4]
  Shape "trianglemesh" "point3 P" [-1 3 -1  1 3 -1  1 3 1  -1 3 1] "integer indices" [0 1 2 0 2 3]
AttributeEnd
Texture "checks" "spectrum" "checkerboard" "float uscale" 4 "float vscale" 4
    "rgb tex1" [0.8 0.8 0.8] "rgb tex2" [0.1 0.1 0.1]
AttributeBegin
  Material "diffuse" "texture reflectance" "checks"
  Shape "bilinearmesh" "point3 P" [-4 0 4  4 0 4  -4 0 -4  4 0 -4]
AttributeEnd
AttributeBegin
  Material "diffuse" "rgb reflectance" [0.8 0.2 0.2]
  Translate -1.5 0.5 0
  Shape "sphere" "float radius" 0.5
AttributeEnd
AttributeBegin
  Material "coateddiffuse" "rgb reflectance" [0.2 0.6 0.2] "float roughness" 0.01
  Translate -0.5 0.5 0
  Shape "sphere" "float radius" 0.5
AttributeEnd
AttributeBegin
  Material "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k" "float roughness" 0.04
  Translate 0.5 0.5 0
  Shape "sphere" "float radius" 0.5
AttributeEnd
AttributeBegin
  Material "dielectric" "float eta" 1.5
  Translate 1.5 0.5 0
  Shape "sphere" "float radius" 0.5
AttributeEnd
)";
    // glint's world is pbrt's with x negated; a mirrored mesh keeps its front by reversing
    // its winding.
    const std::string lua = R"(
glint.camera{ eye = {0, 1, -6}, look_at = {0, 0.5, 0}, fov = 35 }
glint.render{ width = 32, height = 24, spp = 8, max_depth = 3, sampler = "independent",
              filter = "gaussian", filter_radius = 1.5 }
glint.background{ radiance = 0.3 }
glint.mesh{ vertices = {{1, 3, -1}, {-1, 3, -1}, {-1, 3, 1}, {1, 3, 1}}, indices = {1, 3, 2, 1, 4, 3},
            material = glint.emissive{ radiance = 4 } }
-- A bilinear patch without uvs spans [0, 1]^2: corners p00, p10, p11, p01 in that order.
local checks = glint.texture.checker{ even = 0.8, odd = 0.1, scale = {4, 4} }
glint.mesh{ vertices = {{4, 0, 4}, {-4, 0, 4}, {-4, 0, -4}, {4, 0, -4}}, indices = {1, 3, 2, 1, 4, 3},
            uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, material = glint.diffuse{ reflectance = checks } }
glint.sphere{ center = {1.5, 0.5, 0}, radius = 0.5, material = glint.diffuse{ reflectance = {0.8, 0.2, 0.2} } }
glint.sphere{ center = {0.5, 0.5, 0}, radius = 0.5,
              material = glint.plastic{ diffuse = {0.2, 0.6, 0.2}, ior = 1.5, roughness = 0.316227766 } }
glint.sphere{ center = {-0.5, 0.5, 0}, radius = 0.5, material = glint.conductor{ preset = "gold", roughness = 0.447213595 } }
glint.sphere{ center = {-1.5, 0.5, 0}, radius = 0.5, material = glint.dielectric{ ior = 1.5 } }
)";
    expect_same_image(dir, pbrt, lua);
}

TEST(PbrtImages, PointSpotDistantLightsPlyAndInstancesAsInLua) {
    test::TempDir dir;
    std::ofstream(dir.file("tet.ply"))
        << "ply\nformat ascii 1.0\nelement vertex 4\n"
           "property float x\nproperty float y\nproperty float z\nelement face 4\n"
           "property list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    const std::string pbrt = R"(
LookAt 1 2 -5  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 32 "integer yresolution" 24
Sampler "independent" "integer pixelsamples" 8
Integrator "path" "integer maxdepth" 2
WorldBegin
LightSource "point" "rgb I" [1 0.8 0.6] "float power" 200 "point3 from" [2 3 -1]
LightSource "spot" "rgb I" [5 5 5] "point3 from" [-2 4 0] "point3 to" [-1 0 0] "float coneangle" 25 "float conedeltaangle" 5
LightSource "distant" "rgb L" [0.5 0.5 0.6] "point3 from" [1 2 -1] "point3 to" [0 0 0]
Shape "bilinearmesh" "point3 P" [-4 0 4  4 0 4  -4 0 -4  4 0 -4]
ObjectBegin "tet"
  Material "diffuse" "rgb reflectance" [0.7 0.7 0.2]
  Shape "plymesh" "string filename" "tet.ply"
ObjectEnd
AttributeBegin
  Translate -1 0 0
  ObjectInstance "tet"
AttributeEnd
AttributeBegin
  Translate 1 0 0
  Rotate 30 0 1 0
  ObjectInstance "tet"
AttributeEnd
)";
    const std::string lua = R"(
local pi = math.pi
glint.camera{ eye = {-1, 2, -5}, look_at = {0, 0.5, 0}, fov = 45 }
glint.render{ width = 32, height = 24, spp = 8, max_depth = 2, sampler = "independent",
              filter = "gaussian", filter_radius = 1.5 }
glint.point_light{ position = {-2, 3, -1}, intensity = {200 / (4 * pi), 0.8 * 200 / (4 * pi), 0.6 * 200 / (4 * pi)} }
glint.spot_light{ position = {2, 4, 0}, look_at = {1, 0, 0}, intensity = 5, cone_angle = 25, falloff_start = 20 }
glint.directional_light{ direction = {1, -2, 1}, irradiance = {0.5, 0.5, 0.6} }
glint.mesh{ vertices = {{4, 0, 4}, {-4, 0, 4}, {-4, 0, -4}, {4, 0, -4}}, indices = {1, 3, 2, 1, 4, 3},
            uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, material = glint.diffuse{ reflectance = 0.5 } }
local tet = glint.group()
tet:mesh{ file = "tet.ply", material = glint.diffuse{ reflectance = {0.7, 0.7, 0.2} } }
local mirror = glint.scale(-1, 1, 1)
glint.place(tet, mirror * glint.translate(-1, 0, 0))
glint.place(tet, mirror * glint.translate(1, 0, 0) * glint.rotate(30, {0, 1, 0}))
)";
    std::ofstream(dir.file("same.lua")) << lua;
    const Image a = render(import_text(dir, pbrt));
    std::string reseeded = pbrt;
    reseeded.replace(reseeded.find("Sampler \"independent\""), 21,
                     "Sampler \"independent\" \"integer seed\" 7");
    const Image noise = render(import_text(dir, reseeded, "reseeded.pbrt"));
    const Image b = render(load_scene_string(lua, "same.lua", dir.file("")));
    EXPECT_LT(relative_mse(a, b), 0.25 * relative_mse(a, noise));
}

namespace {

// pbrt-v4's square-to-sphere map, written out from Clarberg's equal-area construction, as
// the reference the importer's inverse must undo.
Vec3 equal_area_sphere_of(const Vec2& p) {
    const float u = 2 * p.x - 1, v = 2 * p.y - 1, up = std::abs(u), vp = std::abs(v);
    const float signed_distance = 1 - (up + vp), r = 1 - std::abs(signed_distance);
    const float phi = (r == 0 ? 1 : (vp - up) / r + 1) * kPi / 4;
    const float z = std::copysign(1 - r * r, signed_distance);
    const float s = r * std::sqrt(std::max(0.0f, 2 - r * r));
    return Vec3(std::copysign(std::cos(phi), u) * s, std::copysign(std::sin(phi), v) * s, z);
}

}  // namespace

TEST(PbrtEnvironment, EqualAreaSquareRoundTripsAndKeepsPbrtsOrientation) {
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const Vec2 uv(i / 20.0f, j / 20.0f);
            const Vec2 back = pbrt_equal_area_square_of(equal_area_sphere_of(uv));
            const Vec3 w = equal_area_sphere_of(uv);
            // The square's edges fold onto each other (both are the -z pole's ring).
            if (std::abs(w.z) > 0.999f) continue;
            EXPECT_NEAR(back.x, uv.x, 1e-4f) << i << " " << j;
            EXPECT_NEAR(back.y, uv.y, 1e-4f) << i << " " << j;
        }
    // A square bright only near its centre (+z of the light) and one pixel right of the
    // middle of its right edge (+x). In glint's world (pbrt's mirrored in x) +z stays +z, at
    // the lat-long image's left edge, middle row; pbrt's +x is glint's -x, a quarter across.
    Image square = make_image(33, 33, {"R", "G", "B"});
    square.at(16, 16, 0) = 1.0f;
    square.at(32, 16, 1) = 1.0f;
    const Mat3 light_from_world = Mat3(glm::scale(Mat4(1.0f), Vec3(-1, 1, 1)));
    const Image latlong = latlong_from_equal_area(square, glm::inverse(light_from_world), "test");
    auto brightest = [&](int c) {
        Vec2 best(0.0f);
        float value = -1.0f;
        for (int y = 0; y < latlong.height; ++y)
            for (int x = 0; x < latlong.width; ++x)
                if (latlong.at(x, y, c) > value) {
                    value = latlong.at(x, y, c);
                    best = Vec2((x + 0.5f) / latlong.width, (y + 0.5f) / latlong.height);
                }
        return best;
    };
    const Vec2 z = brightest(0), x = brightest(1);
    EXPECT_TRUE(z.x < 0.05f || z.x > 0.95f) << z.x;
    EXPECT_NEAR(z.y, 0.5f, 0.05f);
    EXPECT_NEAR(x.x, 0.25f, 0.05f);
    EXPECT_NEAR(x.y, 0.5f, 0.05f);
}

TEST(PbrtEnvironment, ImageInfiniteLightBecomesAnEnvironment) {
    test::TempDir dir;
    Image square = make_image(8, 8, {"R", "G", "B"});
    for (float& v : square.pixels) v = 0.5f;
    write_image(dir.file("sky.exr"), square);
    const SceneDesc d = import_text(
        dir,
        "WorldBegin\nLightSource \"infinite\" \"string filename\" \"sky.exr\" \"float scale\" 2\n");
    ASSERT_EQ(d.lights.size(), 1u);
    EXPECT_EQ(d.lights[0].type(), "environment");
    EXPECT_NEAR(d.lights[0].get_float("intensity"), 2.0f, 1e-6f);
    const Image latlong = read_image(d.lights[0].get_string("file"));
    EXPECT_NEAR(latlong.at(3, 5, 1), 0.5f, 1e-6f);
    write_image(dir.file("wide.exr"), make_image(8, 4, {"R", "G", "B"}));
    EXPECT_TRUE(contains(
        error_of([&] {
            import_text(dir,
                        "WorldBegin\nLightSource \"infinite\" \"string filename\" \"wide.exr\"\n");
        }),
        "scene.pbrt:2: LightSource \"infinite\": "));
}

TEST(PbrtShapes, DiskCylinderOrientationAlphaAndInterface) {
    test::TempDir dir;
    const SceneDesc d =
        import_text(dir,
                    "LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                    "Shape \"disk\" \"float radius\" 2 \"float height\" 1\n"
                    "ReverseOrientation\nShape \"cylinder\" \"float radius\" 1 \"float zmin\" 0 "
                    "\"float zmax\" 3\n"
                    "Shape \"sphere\" \"float alpha\" 0\n"
                    "Material \"interface\"\nShape \"sphere\"\n");
    ASSERT_EQ(d.groups[0].shapes.size(), 2u);  // alpha 0 and the interface are left out
    auto mesh_area_and_normal = [&](const Params& shape, Vec3& normal_sum) {
        const MeshData& m = *d.meshes.at(shape.get_ref("data", "mesh_data").index);
        const Transform t = shape.get_transform("transform");
        double area = 0.0;
        normal_sum = Vec3(0.0f);
        for (size_t i = 0; i < m.indices.size(); i += 3) {
            const Vec3 a = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]],
                       c = m.positions[m.indices[i + 2]];
            area += 0.5 * glm::length(glm::cross(b - a, c - a));
            // The side glint treats as the front, in the world (normals of the object-space
            // winding transformed as normals).
            normal_sum += t.normal(glm::cross(b - a, c - a));
        }
        return area;
    };
    Vec3 n;
    // The disk: area pi r^2 (the polygon's radius is enlarged to match), front +z (pbrt's),
    // which the mirror x -> -x keeps at +z.
    EXPECT_NEAR(mesh_area_and_normal(d.groups[0].shapes[0], n), kPi * 4.0, 1e-3);
    EXPECT_GT(n.z, 0.0f);
    // The cylinder: lateral area 2 pi r h; reversed, so its triangles face inwards and its
    // normals point in.
    EXPECT_NEAR(mesh_area_and_normal(d.groups[0].shapes[1], n), 2.0 * kPi * 3.0, 1e-2);
    const MeshData& cyl = *d.meshes.at(d.groups[0].shapes[1].get_ref("data", "mesh_data").index);
    EXPECT_LT(glm::dot(cyl.normals[0], Vec3(cyl.positions[0].x, cyl.positions[0].y, 0)), 0.0f);
}

TEST(PbrtImport, IntoALuaSceneWithItsCameraButTheScriptsSettings) {
    test::TempDir dir;
    std::ofstream(dir.file("part.pbrt"))
        << "LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
        << "Film \"rgb\" \"integer xresolution\" 99 \"integer yresolution\" 50\n"
        << "WorldBegin\nShape \"sphere\"\n";
    const SceneDesc d = load_scene_string(
        "glint.import{ file = 'part.pbrt', transform = glint.translate(1, 2, 0) }\n"
        "glint.render{ width = 16, height = 16 }\n",
        "scene.lua", dir.file(""));
    ASSERT_TRUE(d.camera);
    EXPECT_NEAR(d.camera->get_float("fov"), 30.0f, 1e-4f);
    // The import's transform is in glint's world: +1 in x is +1 in x after the mirror.
    expect_vec(numbers3(*d.camera, "eye"), Vec3(1, 2, -5));
    EXPECT_EQ(d.render->get_int("width", 0), 16);
    ASSERT_EQ(d.groups[0].shapes.size(), 1u);
    expect_vec(d.groups[0].shapes[0].get_transform("transform").point(Vec3(0.0f)), Vec3(1, 2, 0));
    EXPECT_TRUE(contains(error_of([&] {
                             load_scene_string(
                                 "glint.import{ file = 'part.pbrt', material = glint.diffuse{} }",
                                 "scene.lua", dir.file(""));
                         }),
                         "scene.lua:1: import: "));
}

TEST(PbrtShapes, LoopSubdivisionSplitsSmoothsAndStaysClosed) {
    // A regular tetrahedron about the origin.
    MeshData tet;
    tet.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    tet.indices = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    const MeshData m = loop_subdivide(tet, 2);
    EXPECT_EQ(m.indices.size(), 12u * 16u);
    EXPECT_EQ(m.positions.size(), 4u + 6u + 24u);  // V - E + F = 2 at each level
    // Closed: every edge is used once in each direction.
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t i = 0; i < m.indices.size(); i += 3)
        for (int k = 0; k < 3; ++k) ++uses[{m.indices[i + k], m.indices[i + (k + 1) % 3]}];
    for (const auto& [edge, count] : uses) {
        EXPECT_EQ(count, 1);
        EXPECT_EQ(uses.count({edge.second, edge.first}), 1u);
    }
    // Smoothing shrinks the control polyhedron towards its centre, symmetrically.
    Vec3 centroid(0.0f);
    for (const Vec3& p : m.positions) {
        EXPECT_LT(glm::length(p), std::sqrt(3.0f));
        centroid += p / static_cast<float>(m.positions.size());
    }
    expect_vec(centroid, Vec3(0.0f), 1e-5f);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_GT(glm::dot(m.normals[v], m.positions[v]), 0.0f);  // outwards
    // A flat open patch stays flat.
    MeshData square;
    square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.indices = {0, 1, 2, 0, 2, 3};
    for (const Vec3& p : loop_subdivide(square, 3).positions) EXPECT_EQ(p.z, 0.0f);
    EXPECT_FALSE(error_of([&] { loop_subdivide(tet, 9); }).empty());
}

TEST(PbrtEnvironment, AMapIsSeenWherePbrtPutsIt) {
    // Red straight ahead of pbrt's light space (+z), green 45 degrees to its +x side: a camera
    // looking along +z sees red in the middle and green to the right (pbrt's +x).
    test::TempDir dir;
    const int n = 128;
    Image square = make_image(n, n, {"R", "G", "B"});
    // Every texel whose direction (pbrt's map, above) lies within 8 degrees of `w`.
    auto paint = [&](const Vec3& w, int c) {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const Vec3 d = equal_area_sphere_of(Vec2((x + 0.5f) / n, (y + 0.5f) / n));
                if (glm::dot(d, glm::normalize(w)) > std::cos(glm::radians(8.0f)))
                    square.at(x, y, c) = 1.0f;
            }
    };
    paint(Vec3(0, 0, 1), 0);
    paint(Vec3(1, 0, 1), 1);
    write_image(dir.file("map.exr"), square);
    const Image image = render(
        import_text(dir,
                    "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 120\n"
                    "Film \"rgb\" \"integer xresolution\" 48 \"integer yresolution\" 48\n"
                    "Sampler \"independent\" \"integer pixelsamples\" 4\nPixelFilter \"box\"\n"
                    "WorldBegin\nLightSource \"infinite\" \"string filename\" \"map.exr\"\n"));
    const Vec2 red = centroid(image, 0), green = centroid(image, 1);
    EXPECT_NEAR(red.x, 24.0f, 1.5f);
    EXPECT_NEAR(red.y, 24.0f, 1.5f);
    // 45 degrees right of the axis with a 120 degree view: tan 45 / tan 60 of the half width.
    EXPECT_NEAR(green.x, 24.0f + 24.0f / std::sqrt(3.0f), 1.5f);
    EXPECT_NEAR(green.y, 24.0f, 1.5f);
}
