// pbrt-v4 scene files, lexical and syntactic layer: tokens, every parameter type, nested
// attributes, includes, named spectra, and malformed input reported with file and line.
#include <glint/core/error.h>
#include <glint/scene/import/pbrt/parser.h>
#include <glint/scene/import/pbrt/spectra.h>
#include <glint/scene/import/pbrt/tokenizer.h>

#include <gtest/gtest.h>
#include <support/test_util.h>

#include <fstream>

using namespace glint;
using glint::test::contains;
using glint::test::error_of;

namespace {

PbrtScene parse(const std::string& text) {
    return parse_pbrt_text(text, "scene.pbrt", ".");
}

const PbrtParam& param(const PbrtScene& s, const std::string& name) {
    const PbrtParam* p = s.shapes.at(0).entity.params.find(name);
    if (!p) throw Error("no parameter " + name);
    return *p;
}

}  // namespace

TEST(PbrtTokenizer, WordsStringsBracketsCommentsAndLines) {
    PbrtTokenizer t("Shape \"sphere\" # a comment [ \"x\"\n [ 1.5 -2e3 ] \"a\\\"b\\n\"", "f.pbrt");
    std::vector<PbrtToken> tokens;
    for (PbrtToken k = t.next(); k.kind != PbrtToken::Kind::End; k = t.next()) tokens.push_back(k);
    ASSERT_EQ(tokens.size(), 7u);
    EXPECT_EQ(tokens[0].text, "Shape");
    EXPECT_EQ(tokens[1].kind, PbrtToken::Kind::String);
    EXPECT_EQ(tokens[1].text, "sphere");
    EXPECT_EQ(tokens[2].kind, PbrtToken::Kind::Open);
    EXPECT_EQ(tokens[2].line, 2);
    EXPECT_EQ(tokens[3].text, "1.5");
    EXPECT_EQ(tokens[4].text, "-2e3");
    EXPECT_EQ(tokens[5].kind, PbrtToken::Kind::Close);
    EXPECT_EQ(tokens[6].text, "a\"b\n");
    PbrtTokenizer s("\"a\\\"b\\n\"", "f.pbrt");
    EXPECT_EQ(s.next().text, "a\"b\n");
}

TEST(PbrtTokenizer, UnterminatedStringNamesFileAndLine) {
    PbrtTokenizer t("Shape\n\n\"sphere", "f.pbrt");
    t.next();
    EXPECT_TRUE(contains(error_of([&] { t.next(); }), "f.pbrt:3: unterminated string"));
    PbrtTokenizer u("\"ab\ncd\"", "g.pbrt");
    EXPECT_TRUE(contains(error_of([&] { u.next(); }), "g.pbrt:1: unterminated string"));
}

TEST(PbrtParser, EveryParameterType) {
    test::TempDir dir;
    std::ofstream(dir.file("s.spd")) << "# wavelength value\n400 0.5\n700 1.5\n";
    const PbrtScene s = parse_pbrt_text(
        "WorldBegin\nShape \"x\" \"integer i\" [ 1 2 ] \"float f\" 2.5 \"point2 p2\" [1 2]\n"
        "\"vector2 v2\" [3 4] \"point3 p3\" [1 2 3] \"vector3 v3\" [4 5 6] \"normal n\" [0 0 1]\n"
        "\"point p\" [7 8 9] \"vector v\" [1 1 1] \"normal3 n3\" [0 1 0]\n"
        "\"rgb c\" [0.1 0.2 0.3] \"color c2\" [1 1 1] \"spectrum named\" \"metal-Au-eta\"\n"
        "\"spectrum pairs\" [400 1 500 2] \"spectrum file\" \"s.spd\" \"blackbody bb\" 3000\n"
        "\"bool b1\" true \"bool b2\" \"false\" \"string s\" \"hello\" \"texture t\" \"tex\"\n",
        "scene.pbrt", dir.file(""));
    ASSERT_EQ(s.shapes.size(), 1u);
    EXPECT_EQ(param(s, "i").numbers, (std::vector<double>{1, 2}));
    EXPECT_EQ(param(s, "f").numbers, (std::vector<double>{2.5}));
    EXPECT_EQ(param(s, "p2").type, "point2");
    EXPECT_EQ(param(s, "v2").numbers.size(), 2u);
    EXPECT_EQ(param(s, "p3").numbers, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(param(s, "v3").type, "vector3");
    EXPECT_EQ(param(s, "n").type, "normal3");  // "normal" is pbrt's normal3
    EXPECT_EQ(param(s, "p").type, "point3");
    EXPECT_EQ(param(s, "v").type, "vector3");
    EXPECT_EQ(param(s, "n3").numbers, (std::vector<double>{0, 1, 0}));
    EXPECT_EQ(param(s, "c").type, "rgb");
    EXPECT_EQ(param(s, "c2").type, "rgb");  // "color" is pbrt-v3's rgb
    EXPECT_EQ(param(s, "named").strings, (std::vector<std::string>{"metal-Au-eta"}));
    EXPECT_EQ(param(s, "pairs").numbers, (std::vector<double>{400, 1, 500, 2}));
    EXPECT_EQ(param(s, "file").strings, (std::vector<std::string>{"s.spd"}));
    EXPECT_EQ(read_spectrum_file(dir.file("s.spd")), (std::vector<double>{400, 0.5, 700, 1.5}));
    EXPECT_EQ(param(s, "bb").numbers, (std::vector<double>{3000}));
    EXPECT_EQ(param(s, "b1").bools, (std::vector<bool>{true}));
    EXPECT_EQ(param(s, "b2").bools, (std::vector<bool>{false}));
    EXPECT_EQ(param(s, "s").strings, (std::vector<std::string>{"hello"}));
    EXPECT_EQ(param(s, "t").strings, (std::vector<std::string>{"tex"}));
    EXPECT_EQ(param(s, "t").where.line, 7);
    EXPECT_EQ(s.shapes[0].entity.params.get_vec3s("p3").at(0), Vec3(1, 2, 3));
    EXPECT_TRUE(contains(error_of([&] { s.shapes[0].entity.params.get_float("s", 0); }),
                         "scene.pbrt:7: parameter 's': declared as 'string', expected 'float'"));
}

TEST(PbrtParser, NestedAttributesRestoreTransformMaterialAndOrientation) {
    const PbrtScene s = parse(
        "WorldBegin\nMaterial \"conductor\"\nAttributeBegin\n Translate 1 0 0\n"
        " Material \"dielectric\"\n ReverseOrientation\n AttributeBegin\n  Scale 2 2 2\n"
        "  AreaLightSource \"diffuse\"\n  Shape \"sphere\"\n AttributeEnd\n Shape \"sphere\"\n"
        "AttributeEnd\nShape \"sphere\"\n");
    ASSERT_EQ(s.shapes.size(), 3u);
    EXPECT_EQ(s.shapes[0].to_world * Vec4(1, 0, 0, 1), Vec4(3, 0, 0, 1));
    EXPECT_TRUE(s.shapes[0].area_light.has_value());
    EXPECT_TRUE(s.shapes[0].reverse_orientation);
    EXPECT_EQ(s.shapes[1].to_world * Vec4(1, 0, 0, 1), Vec4(2, 0, 0, 1));
    EXPECT_FALSE(s.shapes[1].area_light.has_value());
    EXPECT_EQ(s.materials.at(s.shapes[1].material.index).type, "dielectric");
    EXPECT_EQ(s.shapes[2].to_world, Mat4(1.0f));
    EXPECT_FALSE(s.shapes[2].reverse_orientation);
    EXPECT_EQ(s.materials.at(s.shapes[2].material.index).type, "conductor");
}

TEST(PbrtParser, NamedMaterialsObjectsAndTextures) {
    const PbrtScene s = parse(
        "WorldBegin\nMakeNamedMaterial \"gold\" \"string type\" \"conductor\"\n"
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 4\n"
        "ObjectBegin \"thing\"\n NamedMaterial \"gold\"\n Shape \"sphere\"\nObjectEnd\n"
        "Translate 0 5 0\nObjectInstance \"thing\"\n");
    EXPECT_EQ(s.named_materials.at("gold").type, "conductor");
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].value_kind, "spectrum");
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.objects[0].shapes.size(), 1u);
    EXPECT_EQ(s.objects[0].shapes[0].material.name, "gold");
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].to_world * Vec4(0, 0, 0, 1), Vec4(0, 5, 0, 1));
    EXPECT_TRUE(s.shapes.empty());
}

TEST(PbrtParser, IncludesResolveFromTheMainFileAndReportTheirOwnLines) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("sub"));
    std::ofstream(dir.file("main.pbrt")) << "WorldBegin\nInclude \"sub/geometry.pbrt\"\n"
                                            "Import \"sub/more.pbrt\"\nShape \"sphere\"\n";
    std::ofstream(dir.file("sub/geometry.pbrt")) << "# geometry\nShape \"disk\"\n";
    std::ofstream(dir.file("sub/more.pbrt")) << "Shape \"cylinder\"\n";
    const PbrtScene s = parse_pbrt_file(dir.file("main.pbrt"));
    ASSERT_EQ(s.shapes.size(), 3u);
    EXPECT_EQ(s.shapes[0].entity.type, "disk");
    EXPECT_EQ(s.shapes[0].entity.where.line, 2);
    EXPECT_TRUE(contains(s.shapes[0].entity.where.file, "geometry.pbrt"));
    EXPECT_EQ(s.shapes[1].entity.type, "cylinder");
    EXPECT_EQ(s.shapes[2].entity.where.line, 4);
    EXPECT_TRUE(contains(s.shapes[2].entity.where.file, "main.pbrt"));

    std::ofstream(dir.file("sub/bad.pbrt")) << "Shape \"disk\"\n\nTranslate 1 2\n";
    std::ofstream(dir.file("bad.pbrt")) << "Include \"sub/bad.pbrt\"\n";
    const std::string bad = error_of([&] { parse_pbrt_file(dir.file("bad.pbrt")); });
    EXPECT_TRUE(contains(bad, "bad.pbrt:3: Translate: expected 3 numbers")) << bad;
    std::ofstream(dir.file("loop.pbrt")) << "Include \"loop.pbrt\"\n";
    EXPECT_TRUE(contains(error_of([&] { parse_pbrt_file(dir.file("loop.pbrt")); }),
                         "loop.pbrt:1: Include: "));
    std::ofstream(dir.file("missing.pbrt")) << "\nInclude \"nothere.pbrt\"\n";
    EXPECT_TRUE(contains(error_of([&] { parse_pbrt_file(dir.file("missing.pbrt")); }),
                         "missing.pbrt:2: Include"));
}

TEST(PbrtParser, MalformedInputIsAnErrorWithFileAndLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"WorldBegin\nShape \"sphere\" \"float radius\" [ 1\n",
         "scene.pbrt:2: parameter \"float radius\": '[' is not closed"},
        {"WorldBegin\n\nShape \"x\" \"rgb L\" [ 1 2 ]\n",
         "scene.pbrt:3: parameter \"rgb L\": 2 values, expected 3"},
        {"Translate 1 2\n", "scene.pbrt:1: Translate: expected 3 numbers"},
        {"\nFrobnicate 1\n", "scene.pbrt:2: unknown directive 'Frobnicate'"},
        {"Shape \"x\" \"floaty r\" 1\n",
         "scene.pbrt:1: parameter \"floaty r\": unknown type 'floaty'"},
        {"Shape \"x\" \"float\" 1\n", "scene.pbrt:1: parameter \"float\": expected \"TYPE NAME\""},
        {"Shape \"x\" \"float r\" abc\n", "scene.pbrt:1: 'abc' is not a finite number"},
        {"Shape \"x\" \"bool b\" yes\n",
         "scene.pbrt:1: parameter \"bool b\": 'yes' is not true or false"},
        {"Shape \"x\" \"integer n\" 1.5\n",
         "scene.pbrt:1: parameter \"integer n\": 1.5 is not an integer"},
        {"AttributeBegin\nAttributeEnd\nAttributeEnd\n",
         "scene.pbrt:3: AttributeEnd without a matching AttributeBegin"},
        {"ObjectBegin \"a\"\nAttributeEnd\n",
         "scene.pbrt:2: AttributeEnd closes the ObjectBegin at scene.pbrt:1"},
        {"Transform [ 1 0 0 ]\n", "scene.pbrt:1: Transform: expected 16 numbers, got 3"},
        {"[ 1 ]\n", "scene.pbrt:1: expected a directive, got '['"},
        {"Rotate 30 0 0 0\n", "scene.pbrt:1: Rotate: the axis is zero"},
        {"LookAt 0 0 0  0 0 1  0 0 1\n",
         "scene.pbrt:1: LookAt: the up vector and the viewing direction are parallel"},
        {"Shape \"x\" \"spectrum s\" [ 400 ]\n",
         "scene.pbrt:1: parameter \"spectrum s\": 1 values, expected pairs"},
        {"ObjectBegin \"a\"\nObjectInstance \"a\"\n",
         "scene.pbrt:2: ObjectInstance inside an object definition"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string message = error_of([&] { parse(text); });
        EXPECT_TRUE(contains(message, expected)) << text << "\ngave: " << message;
    }
}

TEST(PbrtParser, UnsupportedDirectivesAreWarningsWithFileAndLine) {
    const PbrtScene s = parse(
        "Accelerator \"bvh\"\nWorldBegin\nMakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "MediumInterface \"fog\" \"\"\nAttribute \"shape\" \"float radius\" 2\n"
        "ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\nShape \"sphere\"\n"
        "AttributeBegin\n");
    const std::vector<std::string> expected = {"scene.pbrt:1: Accelerator:",
                                               "scene.pbrt:3: MakeNamedMedium: participating media",
                                               "scene.pbrt:4: MediumInterface:",
                                               "scene.pbrt:5: Attribute:",
                                               "scene.pbrt:6: ActiveTransform: motion blur",
                                               "scene.pbrt:10: AttributeBegin: not closed"};
    for (const std::string& e : expected) {
        bool found = false;
        for (const std::string& w : s.warnings) found = found || contains(w, e);
        EXPECT_TRUE(found) << e;
    }
    // The end-time transform was not applied.
    EXPECT_EQ(s.shapes.at(0).to_world, Mat4(1.0f));
}

TEST(PbrtSpectra, NamedSpectraMatchTheirSources) {
    // Metals: glint's conductor presets (pbrt-v4's measured data at 650, 550, 450 nm).
    const auto au = named_spectrum("metal-Au-eta");
    ASSERT_TRUE(au);
    EXPECT_NEAR(au->rgb.y, 0.3504f, 1e-4f);
    EXPECT_NEAR(named_spectrum("metal-Cu-k")->rgb.x, 3.6377f, 1e-4f);
    // Glasses: Sellmeier fits, checked against the catalogue's index at 550 nm (BK7:
    // 1.51852) and, through the green channel's neighbour, its ordering.
    const auto bk7 = named_spectrum("glass-BK7");
    ASSERT_TRUE(bk7);
    EXPECT_NEAR(bk7->rgb.y, 1.51852f, 2e-4f);
    EXPECT_LT(bk7->rgb.x, bk7->rgb.y);  // normal dispersion: red bends least
    EXPECT_LT(bk7->rgb.y, bk7->rgb.z);
    EXPECT_EQ(named_spectrum("stdillum-D65")->rgb, Vec3(1.0f));
    EXPECT_FALSE(named_spectrum("metal-unobtainium-eta"));
}

TEST(PbrtSpectra, BlackbodyChromaticityAndLuminance) {
    // The CIE 1931 chromaticities of the Planckian locus (CIE 15:2004): the colour matching
    // fit of Wyman et al. is within 0.0012 in x and y of them.
    const std::pair<double, Vec2> locus[] = {
        {2856.0, {0.44757f, 0.40745f}}, {4000.0, {0.3805f, 0.3768f}}, {6500.0, {0.3135f, 0.3236f}}};
    for (const auto& [kelvin, xy] : locus) {
        const Vec3 rgb = blackbody_rgb(kelvin);
        // Back to XYZ through the inverse of the Rec.709 matrix.
        const Vec3 xyz(0.4124564f * rgb.x + 0.3575761f * rgb.y + 0.1804375f * rgb.z,
                       0.2126729f * rgb.x + 0.7151522f * rgb.y + 0.0721750f * rgb.z,
                       0.0193339f * rgb.x + 0.1191920f * rgb.y + 0.9503041f * rgb.z);
        const float sum = xyz.x + xyz.y + xyz.z;
        EXPECT_NEAR(xyz.x / sum, xy.x, 0.0015f) << kelvin;
        EXPECT_NEAR(xyz.y / sum, xy.y, 0.0015f) << kelvin;
        EXPECT_NEAR(xyz.y, 1.0f, 1e-4f) << kelvin;  // pbrt's photometric normalisation
    }
    EXPECT_GT(blackbody_rgb(2000).x, blackbody_rgb(2000).z);  // warm is red
    EXPECT_LT(blackbody_rgb(12000).x, blackbody_rgb(12000).z);
    EXPECT_FALSE(error_of([] { blackbody_rgb(0); }).empty());
}

TEST(PbrtParser, EveryTruncationOfTheExampleParsesOrFailsWithALocation) {
    const std::string text = [] {
        std::ifstream in(std::string(GLINT_SOURCE_DIR) + "/examples/still-life.pbrt");
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    ASSERT_GT(text.size(), 1000u);
    int errors = 0;
    for (size_t n = 0; n <= text.size(); n += 3) {
        try {
            parse(text.substr(0, n));
        } catch (const Error& e) {
            ++errors;
            EXPECT_TRUE(contains(e.what(), "scene.pbrt:")) << n << ": " << e.what();
        }
    }
    EXPECT_GT(errors, 0);  // cut inside a string or a bracket
}
