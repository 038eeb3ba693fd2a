// `glint warp`: an image rendered with --aovs seen from a nearby viewpoint, and the errors for
// images it cannot warp.
#include <glint/film/image_io.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <filesystem>

using namespace glint;
using glint::test::run_glint;
namespace fs = std::filesystem;

namespace {

const std::string kSmallScene = GLINT_SOURCE_DIR "/tests/scenes/small.lua";

class WarpCommand : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir =
            fs::temp_directory_path() / fmt::format("glint-warp-{}-{}", info->name(), ::getpid());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string out(const std::string& name) const { return (m_dir / name).string(); }

    fs::path m_dir;
};

TEST_F(WarpCommand, WarpsAnImageRenderedWithDepthAndCountsDisocclusions) {
    ASSERT_EQ(
        run_glint(fmt::format("render {} --aovs -o {} --quiet", kSmallScene, out("a.exr"))).exit_code,
        0);
    const auto result = run_glint(
        fmt::format("warp {} --camera \"eye=0.6,2.2,7.8\" -o {}", out("a.exr"), out("b.png")));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("pixels disoccluded"), std::string::npos) << result.output;
    const Image warped = read_image(out("b.png"));
    EXPECT_EQ(warped.width, 32);
    EXPECT_EQ(warped.height, 24);

    // The same viewpoint gives the image back: nothing disoccluded.
    const auto same =
        run_glint(fmt::format("warp {} --camera \"fov=40\" -o {}", out("a.exr"), out("same.exr")));
    EXPECT_EQ(same.exit_code, 0) << same.output;
    EXPECT_NE(same.output.find(": 0 of 768 pixels disoccluded"), std::string::npos) << same.output;
}

TEST_F(WarpCommand, ImagesWithoutDepthOrCameraAreRefusedClearly) {
    ASSERT_EQ(run_glint(fmt::format("render {} -o {} --quiet", kSmallScene, out("plain.exr"))).exit_code,
              0);
    auto result = run_glint(
        fmt::format("warp {} --camera \"eye=0,2,7\" -o {}", out("plain.exr"), out("b.png")));
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("plain.exr: the image has no depth AOV"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(out("b.png")));

    // Depth but no camera in the header: the scene must say which camera it was.
    Image image = make_image(32, 24, {"R", "G", "B", "depth.Z"});
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 5.0f;
    write_image(out("nocamera.exr"), image);
    result = run_glint(
        fmt::format("warp {} --camera \"eye=0,2,7\" -o {}", out("nocamera.exr"), out("b.png")));
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("--scene"), std::string::npos) << result.output;
    result = run_glint(fmt::format("warp {} --scene {} --camera \"eye=0,2,7\" -o {}",
                                   out("nocamera.exr"), kSmallScene, out("b.png")));
    EXPECT_EQ(result.exit_code, 0) << result.output;

    result = run_glint(
        fmt::format("warp {} --camera \"eye=0,2,7\" -o {}", out("absent.exr"), out("b.png")));
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("absent.exr"), std::string::npos) << result.output;
}

TEST_F(WarpCommand, BadFlagsAreUsageErrors) {
    ASSERT_EQ(
        run_glint(fmt::format("render {} --aovs -o {} --quiet", kSmallScene, out("a.exr"))).exit_code,
        0);
    for (const char* camera : {"eye=1,2", "bogus=3", "fov=abc", "", "eye=0,0.5,0"}) {
        const auto result = run_glint(
            fmt::format("warp {} --camera \"{}\" -o {}", out("a.exr"), camera, out("b.png")));
        EXPECT_EQ(result.exit_code, 2) << camera << ": " << result.output;
        EXPECT_NE(result.output.find("--camera"), std::string::npos) << result.output;
    }
    EXPECT_EQ(run_glint(fmt::format("warp {} -o {}", out("a.exr"), out("b.png"))).exit_code, 2);
}

}  // namespace
