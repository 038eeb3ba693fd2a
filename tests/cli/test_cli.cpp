// End-to-end tests of the glint command: exit codes, messages, outputs.
#include <glint/film/image_io.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

using namespace glint;
using glint::test::run_glint;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = GLINT_SOURCE_DIR "/tests/scenes/";

// A fresh empty directory per test, removed afterwards.
class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir =
            fs::temp_directory_path() / fmt::format("glint-cli-{}-{}", info->name(), ::getpid());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string out(const std::string& name) const { return (m_dir / name).string(); }
    size_t files_in_dir() const {
        return static_cast<size_t>(
            std::distance(fs::directory_iterator(m_dir), fs::directory_iterator()));
    }

    fs::path m_dir;
};

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

// Each kind of bad input names the file and line, exits with 1 and writes nothing.
TEST_F(CliTest, BadInputGivesFileLineExitOneAndNoOutput) {
    struct Case {
        const char* scene;
        const char* location;
        const char* what;
    };
    const Case cases[] = {
        {"syntax_error.lua", "syntax_error.lua:3:", "expected"},
        {"unknown_parameter.lua", "unknown_parameter.lua:4:", "unknown parameter 'iorr'"},
        {"wrong_type.lua", "wrong_type.lua:4:", "must be a number"},
        {"missing_obj.lua", "missing_obj.lua:5:", "does-not-exist.obj"},
        {"missing_texture.lua", "missing_texture.lua:4:", "textures/does-not-exist.png"},
        {"unreadable_texture.lua", "unreadable_texture.lua:5:", "triangle.obj"},
        {"runtime_error.lua", "runtime_error.lua:3:", "nil value"},
    };
    for (const Case& c : cases) {
        const auto result = run_glint(fmt::format("render {}{} -o {} -o {} --quiet", kScenes,
                                                  c.scene, out("image.exr"), out("image.png")));
        EXPECT_EQ(result.exit_code, 1) << c.scene << ": " << result.output;
        EXPECT_NE(result.output.find(c.location), std::string::npos) << result.output;
        EXPECT_NE(result.output.find(c.what), std::string::npos) << result.output;
        EXPECT_EQ(files_in_dir(), 0u) << c.scene << " left a file behind";
    }
}

namespace {

// A scene whose glint.render{...} is on line 5, with `render` inside its braces.
std::string settings_scene(const fs::path& dir, const std::string& render) {
    const std::string path = (dir / "settings.lua").string();
    std::ofstream(path) << "-- render settings are on line 5\n"
                           "glint.camera{ eye = {0, 2, 8}, look_at = {0, 0.5, 0}, fov = 40 }\n"
                           "local white = glint.diffuse{ reflectance = 0.7 }\n"
                           "glint.quad{ vertices = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, "
                           "-4}}, material = white }\n"
                        << "glint.render{ width = 8, height = 8, spp = 1, " << render << " }\n"
                        << "glint.point_light{ position = {0, 5, 0}, intensity = 10 }\n";
    return path;
}

size_t count_of(const std::string& text, const std::string& what) {
    size_t count = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++count;
    return count;
}

}  // namespace

// Each error names where the offending value came from: the flag that gave it, or the
// scene's line of glint.render{...}, whichever other flags are given.
TEST_F(CliTest, SettingErrorsNameTheirSource) {
    auto result =
        run_glint(fmt::format("render {} --integrator bogus --adaptive sobel -o {} --quiet",
                              settings_scene(m_dir, "seed = 1"), out("a.exr")));
    EXPECT_EQ(result.exit_code, 2) << result.output;  // a flag's bad value
    EXPECT_NE(result.output.find("--integrator: unknown integrator 'bogus'"), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("--adaptive"), std::string::npos) << result.output;

    result = run_glint(fmt::format("render {} --integrator path -o {} --quiet",
                                   settings_scene(m_dir, "sampler = 'x'"), out("a.exr")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("settings.lua:5:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("'x'"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("--integrator"), std::string::npos) << result.output;

    // An integrator's own setting, read by its own create(), from the scene or a flag.
    for (const char* integrator : {"", "--integrator whitted"}) {
        result = run_glint(
            fmt::format("render {} {} -o {} --quiet",
                        settings_scene(m_dir, "integrator = 'whitted', shadow_samples = 0"),
                        integrator, out("a.exr")));
        EXPECT_EQ(result.exit_code, 1) << result.output;
        EXPECT_NE(result.output.find("settings.lua:5: render: 'shadow_samples' must be in [1, 64]"),
                  std::string::npos)
            << result.output;
    }
    result = run_glint(fmt::format("render {} --integrator sppm --adaptive bogus -o {} --quiet",
                                   settings_scene(m_dir, "photon_radius = -1"), out("a.exr")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("settings.lua:5: render: 'photon_radius'"), std::string::npos)
        << result.output;
    EXPECT_EQ(files_in_dir(), 1u);  // the scene only
}

// Keys of glint.render{...} that only another integrator reads get one warning line; a key
// no integrator reads stays an error.
TEST_F(CliTest, ForeignRenderSettingsWarnOnce) {
    const std::string scene = settings_scene(m_dir, "caustics = false, penumbra_shortcut = true");
    auto result =
        run_glint(fmt::format("render {} --integrator path -o {} --quiet", scene, out("a.exr")));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(count_of(result.output, "warning:"), 1u) << result.output;
    EXPECT_NE(result.output.find("settings.lua:5: render: 'caustics', 'penumbra_shortcut' are "
                                 "not used by integrator 'path'"),
              std::string::npos)
        << result.output;

    result =
        run_glint(fmt::format("render {} --integrator whitted -o {} --quiet", scene, out("a.exr")));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(count_of(result.output, "warning"), 0u) << result.output;

    result = run_glint(fmt::format("render {} --integrator path --photons 10 -o {} --quiet",
                                   settings_scene(m_dir, "seed = 2"), out("a.exr")));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(count_of(result.output, "warning:"), 1u) << result.output;
    EXPECT_NE(result.output.find("'caustic_photons' (--photons), 'photons' (--photons)"),
              std::string::npos)
        << result.output;

    result =
        run_glint(fmt::format("render {} --integrator path -o {} --quiet",
                              settings_scene(m_dir, "penumbra_shortcuts = true"), out("a.exr")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("settings.lua:5: render: unknown parameter 'penumbra_shortcuts'"),
              std::string::npos)
        << result.output;
}

TEST_F(CliTest, UsageErrorsExitWithTwo) {
    EXPECT_EQ(run_glint("").exit_code, 2);
    EXPECT_EQ(run_glint("render").exit_code, 2);
    EXPECT_EQ(run_glint(fmt::format("render {}small.lua --res 12", kScenes)).exit_code, 2);
    EXPECT_EQ(run_glint(fmt::format("render {}small.lua --spp 0", kScenes)).exit_code, 2);
    EXPECT_EQ(run_glint("frobnicate").exit_code, 2);
    EXPECT_EQ(run_glint("--help").exit_code, 0);
}

// A scene with fog rendered by an integrator that ignores scattering media is one warning
// that says which integrators render them; volpath and light give none.
TEST_F(CliTest, FogOnAnIntegratorWithoutMediaWarns) {
    const std::string scene = GLINT_SOURCE_DIR "/examples/foggy-cornell.lua";
    auto result = run_glint(fmt::format(
        "render {} --integrator path --res 8x8 --spp 1 -o {} --quiet", scene, out("a.exr")));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(count_of(result.output, "warning:"), 1u) << result.output;
    EXPECT_NE(result.output.find("the 'path' integrator ignores participating media"),
              std::string::npos)
        << result.output;
    for (const char* integrator : {"volpath", "light"}) {
        result = run_glint(fmt::format("render {} --integrator {} --res 8x8 --spp 1 -o {} --quiet",
                                       scene, integrator, out("a.exr")));
        EXPECT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(count_of(result.output, "warning"), 0u) << integrator << ": " << result.output;
    }
    // A glowing medium in a shape: 'light' starts paths in it, volpath collects it; neither
    // warns. Around the camera, filling no shape, 'light' cannot start paths in it, and says
    // so; volpath does not.
    const auto write = [](const std::string& path, const std::string& medium_place) {
        std::ofstream file(path);
        file << "local glow = glint.medium{ sigma_a = 1, emission = 2 }\n"
                "glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}"
             << (medium_place == "camera" ? ", medium = glow" : "")
             << " }\n"
                "glint.render{ width = 8, height = 8, spp = 1 }\n"
                "glint.sphere{ radius = 1, material = "
             << (medium_place == "sphere" ? "glint.interface{ interior = glow }"
                                          : "glint.diffuse{}")
             << " }\n"
                "glint.point_light{ position = {0, 2, 2}, intensity = 1 }\n";
    };
    const std::string in_sphere = out("glow.lua"), around_camera = out("air.lua");
    write(in_sphere, "sphere");
    write(around_camera, "camera");
    for (const char* integrator : {"light", "volpath"}) {
        result = run_glint(fmt::format("render {} --integrator {} -o {} --quiet", in_sphere,
                                       integrator, out("b.exr")));
        EXPECT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(count_of(result.output, "warning"), 0u) << integrator << ": " << result.output;
    }
    result = run_glint(
        fmt::format("render {} --integrator light -o {} --quiet", around_camera, out("b.exr")));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("ignores the light of a glowing medium that fills no shape"),
              std::string::npos)
        << result.output;
    result = run_glint(
        fmt::format("render {} --integrator volpath -o {} --quiet", around_camera, out("b.exr")));
    EXPECT_EQ(count_of(result.output, "warning"), 0u) << result.output;
}

// Every integrator renders spectral = true (issue 30: photon, radiosity and preview were the
// last), so none warns that it renders in RGB; a bad value of wavelength_sets names its line.
TEST_F(CliTest, SpectralOnEveryIntegratorRendersWithoutWarning) {
    const std::string scene = settings_scene(m_dir, "spectral = true, wavelength_sets = 2");
    for (const char* integrator : {"path", "photon", "radiosity", "preview"}) {
        auto result = run_glint(fmt::format("render {} --integrator {} --photons 100 -o {} --quiet",
                                            scene, integrator, out("a.exr")));
        EXPECT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(count_of(result.output, "renders in RGB"), 0u)
            << integrator << ": " << result.output;
    }
    const std::string bad = settings_scene(m_dir, "spectral = true, wavelength_sets = 0");
    auto result =
        run_glint(fmt::format("render {} --integrator photon -o {} --quiet", bad, out("b.exr")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("settings.lua:5: render: 'wavelength_sets' must be in [1, 256]"),
              std::string::npos)
        << result.output;
}

TEST_F(CliTest, MissingSceneAndBadOutputFormatExitWithOne) {
    auto result = run_glint(fmt::format("render {} --quiet", out("absent.lua")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("absent.lua"), std::string::npos);
    result = run_glint(fmt::format("render {}small.lua -o {} --quiet", kScenes, out("image.jpg")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(CliTest, RendersExrAndPngWithOverrides) {
    const auto result =
        run_glint(fmt::format("render {}small.lua -o {} -o {} --res 20x10 --spp 2 --aovs --quiet",
                              kScenes, out("a.exr"), out("a.png")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(result.output.empty()) << "--quiet printed: " << result.output;
    const Image exr = read_image(out("a.exr"));
    EXPECT_EQ(exr.width, 20);
    EXPECT_EQ(exr.height, 10);
    EXPECT_GE(exr.channel_index("albedo.R"), 0);
    EXPECT_GE(exr.channel_index("normal.X"), 0);
    EXPECT_GE(exr.channel_index("depth.Z"), 0);
    EXPECT_TRUE(fs::exists(out("a.png")));
    EXPECT_EQ(files_in_dir(), 2u);  // no temporary files left
}

TEST_F(CliTest, ThreadCountDoesNotChangeTheImage) {
    for (int threads : {1, 2}) {
        // A second apart, so a time stamp in the file would show as a difference.
        if (threads == 2) std::this_thread::sleep_for(std::chrono::milliseconds(1100));
        const auto result =
            run_glint(fmt::format("render {}small.lua -o {} --threads {} --spp 3 --quiet", kScenes,
                                  out(fmt::format("t{}.exr", threads)), threads));
        ASSERT_EQ(result.exit_code, 0) << result.output;
    }
    const std::string one = read_bytes(out("t1.exr"));
    EXPECT_FALSE(one.empty());
    EXPECT_TRUE(one == read_bytes(out("t2.exr"))) << "EXR files differ between 1 and 2 threads";
}

// The same with everything the appearance work added: mipmapped image textures,
// procedural textures, bump and normal maps, rough materials and the environment light.
TEST_F(CliTest, ThreadCountDoesNotChangeTheTexturedImage) {
    for (int threads : {1, 2}) {
        const auto result = run_glint(fmt::format(
            "render {}/examples/textures.lua -o {} --threads {} --res 96x54 --spp 2 --quiet",
            GLINT_SOURCE_DIR, out(fmt::format("t{}.exr", threads)), threads));
        ASSERT_EQ(result.exit_code, 0) << result.output;
    }
    const std::string one = read_bytes(out("t1.exr"));
    EXPECT_FALSE(one.empty());
    EXPECT_TRUE(one == read_bytes(out("t2.exr"))) << "EXR files differ between 1 and 2 threads";
}

// sppm writes the image so far every N passes on request, next to each output, and the
// early image already estimates the same picture as the final one.
TEST_F(CliTest, SppmWritesIntermediateImages) {
    const auto result = run_glint(fmt::format(
        "render {}/examples/caustics.lua --integrator sppm --spp 4 --intermediate 2 --res 48x36 "
        "--photons 20000 -o {} -o {} --quiet",
        GLINT_SOURCE_DIR, out("c.exr"), out("c.png")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::exists(out("c.pass0002.exr")));
    EXPECT_TRUE(fs::exists(out("c.pass0002.png")));
    EXPECT_FALSE(fs::exists(out("c.pass0004.exr")));  // the last pass is the output itself
    const Image early = read_image(out("c.pass0002.exr"));
    const Image final = read_image(out("c.exr"));
    const CompareResult c = compare_images(early, final);
    EXPECT_NEAR(c.test_mean[1], c.ref_mean[1], 0.1 * c.ref_mean[1]);
    EXPECT_GT(c.ref_mean[1], 0.0);
}

TEST_F(CliTest, ProgressAndSummaryGoToStderr) {
    const auto result = run_glint(fmt::format("render {}small.lua -o {}", kScenes, out("p.exr")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("samples/s"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("rays/s"), std::string::npos) << result.output;
}

// The exact totals line that bench/instructions.sh divides instruction counts by.
TEST_F(CliTest, SummaryGivesExactSampleAndRayTotals) {
    const auto result =
        run_glint(fmt::format("render {}small.lua --res 8x6 --spp 3 -o {}", kScenes, out("t.exr")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    // "N samples and M rays in all": N is the digits before " samples and ".
    // (Not std::regex: GCC 12 warns falsely inside it under the sanitizers.)
    const size_t words = result.output.find(" samples and ");
    ASSERT_NE(words, std::string::npos) << result.output;
    size_t number = words;
    while (number > 0 && std::isdigit(static_cast<unsigned char>(result.output[number - 1])))
        --number;
    unsigned long long samples = 0, rays = 0;
    ASSERT_EQ(std::sscanf(result.output.c_str() + number, "%llu samples and %llu rays in all",
                          &samples, &rays),
              2)
        << result.output;
    EXPECT_EQ(samples, 8u * 6u * 3u);
    EXPECT_GE(rays, 8u * 6u * 3u);  // at least one camera ray per sample
}

TEST_F(CliTest, InfoPrintsCounts) {
    const auto result = run_glint(fmt::format("info {}small.lua", kScenes));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("shapes:     8"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("triangles:  41"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("lights:     4"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("bounds:"), std::string::npos) << result.output;
}

// Media are listed, each with the script line that made it and its coefficients.
TEST_F(CliTest, InfoListsMedia) {
    const auto result =
        run_glint(fmt::format("info {}/examples/foggy-cornell.lua", GLINT_SOURCE_DIR));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("media:      1"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("foggy-cornell.lua:5: homogeneous"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("the camera's"), std::string::npos) << result.output;
}

TEST_F(CliTest, CompareReportsErrorAgainstReference) {
    ASSERT_EQ(
        run_glint(fmt::format("render {}small.lua -o {} --spp 2 --quiet", kScenes, out("low.exr")))
            .exit_code,
        0);
    ASSERT_EQ(run_glint(fmt::format("render {}small.lua -o {} --spp 32 --quiet", kScenes,
                                    out("high.exr")))
                  .exit_code,
              0);
    auto same = run_glint(fmt::format("compare {} {}", out("high.exr"), out("high.exr")));
    EXPECT_EQ(same.exit_code, 0);
    EXPECT_NE(same.output.find("relative MSE: 0\n"), std::string::npos) << same.output;
    auto differ =
        run_glint(fmt::format("compare {} {} --threshold 1e-9", out("low.exr"), out("high.exr")));
    EXPECT_EQ(differ.exit_code, 1) << differ.output;
    EXPECT_NE(differ.output.find("ref mean"), std::string::npos) << differ.output;
}

// --debug photons with whitted's caustics writes its caustic map's view: bright in the
// caustic, black elsewhere; without caustics = true it is refused, naming the setting.
TEST_F(CliTest, DebugPhotonsWithWhittedCaustics) {
    const std::string scene = out("whitted-caustics.lua");
    {
        std::ofstream f(scene);
        f << "glint.camera{ eye = {0, 5.5, 6.5}, look_at = {0, 0.3, 0}, fov = 38 }\n"
             "glint.render{ integrator = 'whitted', caustics = true, caustic_photons = 100000 }\n"
             "glint.quad{ vertices = {{-8, 0, 8}, {8, 0, 8}, {8, 0, -8}, {-8, 0, -8}},\n"
             "            material = glint.diffuse{ reflectance = 0.7 } }\n"
             "glint.sphere{ center = {-1.4, 0.8, 0.3}, radius = 0.8,\n"
             "              material = glint.dielectric{ ior = 1.5 } }\n"
             "glint.spot_light{ position = {-4.5, 5, 0}, look_at = {0.4, 0, 0}, intensity = 260,\n"
             "                  cone_angle = 28 }\n";
    }
    auto result =
        run_glint(fmt::format("render {} --debug photons --res 64x48 --spp 1 -o {} -o {} --quiet",
                              scene, out("w.exr"), out("w.png")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    ASSERT_TRUE(fs::exists(out("w.photons.png")));
    const Image view = read_image(out("w.photons.png"));
    const Image beauty = read_image(out("w.png"));
    float brightest = 0.0f;
    double view_sum = 0.0, beauty_sum = 0.0;
    int black = 0;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            view_sum += view.at(x, y, 1);
            beauty_sum += beauty.at(x, y, 1);
            brightest = std::max(brightest, view.at(x, y, 1));
            black += view.at(x, y, 1) == 0.0f;
        }
    }
    EXPECT_GT(brightest, 0.1f);                       // the caustic
    EXPECT_GT(black, view.width * view.height / 20);  // no direct light: dark away from it
    EXPECT_LT(view_sum, 0.5 * beauty_sum) << "the view holds more than the caustic map";

    result = run_glint(fmt::format("render {} --integrator whitted --debug photons -o {} --quiet",
                                   kScenes + "small.lua", out("s.exr")));
    EXPECT_NE(result.exit_code, 0);
    EXPECT_NE(result.output.find("needs caustics = true"), std::string::npos) << result.output;
}

// --crop writes the window at its own size, with the full render's pixels; a window outside
// the image names the flag, a malformed one is a usage error.
TEST_F(CliTest, CropWritesTheWindowOfTheFullRender) {
    auto result = run_glint(fmt::format("render {}small.lua -o {} --res 20x10 --spp 2 --quiet",
                                        kScenes, out("full.exr")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    result = run_glint(fmt::format(
        "render {}small.lua -o {} --res 20x10 --spp 2 --crop 3,2,15,9 --threads 1 --quiet", kScenes,
        out("crop.exr")));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image full = read_image(out("full.exr"));
    const Image crop = read_image(out("crop.exr"));
    ASSERT_EQ(crop.width, 12);
    ASSERT_EQ(crop.height, 7);
    for (int y = 0; y < crop.height; ++y) {
        for (int x = 0; x < crop.width; ++x) {
            for (int c = 0; c < 3; ++c) ASSERT_EQ(crop.at(x, y, c), full.at(x + 3, y + 2, c));
        }
    }
    result = run_glint(fmt::format("render {}small.lua -o {} --res 20x10 --crop 0,0,21,4 --quiet",
                                   kScenes, out("bad.exr")));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--crop: render: 'crop' must be"), std::string::npos)
        << result.output;
    EXPECT_EQ(run_glint(fmt::format("render {}small.lua --crop 1,2,3", kScenes)).exit_code, 2);
}
