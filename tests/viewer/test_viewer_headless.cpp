// `glint view` in a real window under Xvfb: after N passes the screenshot shows what
// `glint render --spp N` writes, a scripted camera move restarts accumulation, and without
// a display the viewer says so and exits 1.
#include <glint/film/image_io.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cstdio>
#include <filesystem>

namespace glint {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = std::string(GLINT_SOURCE_DIR) + "/examples/cornell-box.lua";

// The command line prefix that runs glint in a virtual X server with software OpenGL, or
// the reason the test cannot run here.
std::string xvfb_prefix(std::string& why_not) {
#ifndef GLINT_HAVE_VIEWER
    why_not = "glint was built without the viewer (libglfw3-dev, libimgui-dev not found)";
    return {};
#else
    if (test::run_command("command -v xvfb-run").exit_code != 0) {
        why_not = "xvfb-run is not installed (package xvfb)";
        return {};
    }
    // Under the sanitizers (the CI's second build), leak checking is off for the window's
    // process alone: Mesa's software driver, which libGL loads and unloads itself, leaves
    // 240 bytes that LeakSanitizer reports from an "<unknown module>" (unloaded before the
    // report), so no suppression can name them. Its address and UB checks still run; in
    // other builds the variable is not read.
    return "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" "
           "LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s '-screen 0 640x480x24' ";
#endif
}

fs::path temp(const std::string& name) {
    return fs::path(testing::TempDir()) / name;
}

// The log's "frame F: S spp" lines, as S by F.
std::vector<int> spp_by_frame(const std::string& log) {
    std::vector<int> spp;
    // (Not std::regex: GCC 12 warns falsely inside it under the sanitizers.)
    for (size_t at = log.find("frame "); at != std::string::npos; at = log.find("frame ", at + 1)) {
        int frame = 0, samples = 0;
        if (std::sscanf(log.c_str() + at, "frame %d: %d spp", &frame, &samples) != 2) continue;
        EXPECT_EQ(frame, static_cast<int>(spp.size()) + 1);
        spp.push_back(samples);
    }
    return spp;
}

TEST(ViewerHeadless, ScreenshotShowsTheRender) {
    std::string why_not;
    const std::string xvfb = xvfb_prefix(why_not);
    if (xvfb.empty()) GTEST_SKIP() << why_not;
    const fs::path shot = temp("viewer_shot.png"), reference = temp("viewer_reference.png");
    const test::CommandResult view = test::run_command(
        xvfb + test::glint_binary() + " view " + kCornell +
        " --res 64x48 --spp 6 --frames 6 --threads 2 --hide-panel --screenshot " + shot.string());
    ASSERT_EQ(view.exit_code, 0) << view.output;
    EXPECT_EQ(spp_by_frame(view.output), (std::vector<int>{1, 2, 3, 4, 5, 6})) << view.output;
    const test::CommandResult render = test::run_glint(
        "render " + kCornell + " --res 64x48 --spp 6 --quiet -o " + reference.string());
    ASSERT_EQ(render.exit_code, 0) << render.output;

    const Image shown = read_image(shot.string()), rendered = read_image(reference.string());
    ASSERT_EQ(shown.width, 64);
    ASSERT_EQ(shown.height, 48);
    // The window shows 8-bit sRGB pixels, as the PNG holds them; the linear images are the
    // same bits, so only the texture's path through OpenGL could differ. Off by one 8-bit
    // step at every pixel would give a relative MSE of about 1e-4 in the box's mid tones;
    // the bound is ten times below that.
    const CompareResult r = compare_images(shown, rendered);
    EXPECT_LT(r.rel_mse, 1e-5) << view.output;
    fs::remove(shot);
    fs::remove(reference);
}

// With the scene's denoise = true, the window shows the network's image once the camera has
// stood still for the target's passes: the frame after the last pass is `glint render
// --denoise`'s denoised image.
TEST(ViewerHeadless, StillCameraShowsTheDenoisedImage) {
    std::string why_not;
    const std::string xvfb = xvfb_prefix(why_not);
    if (xvfb.empty()) GTEST_SKIP() << why_not;
    const std::string scene = GLINT_SOURCE_DIR "/examples/denoise.lua";
    const fs::path shot = temp("viewer_denoised.png"), reference = temp("viewer_denoised_ref.png");
    const test::CommandResult view = test::run_command(
        xvfb + test::glint_binary() + " view " + scene +
        " --res 64x48 --spp 4 --frames 5 --threads 2 --hide-panel --screenshot " + shot.string());
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const test::CommandResult render = test::run_glint(
        "render " + scene + " --res 64x48 --spp 4 --threads 2 --quiet -o " + reference.string());
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const fs::path denoised = temp("viewer_denoised_ref.denoised.png");
    const Image shown = read_image(shot.string()), rendered = read_image(denoised.string());
    const CompareResult r = compare_images(shown, rendered);
    EXPECT_LT(r.rel_mse, 1e-5) << view.output;
    // And it is not the noisy image.
    EXPECT_GT(compare_images(read_image(reference.string()), rendered).rel_mse, 1e-3);
    for (const fs::path& p : {shot, reference, denoised}) fs::remove(p);
}

TEST(ViewerHeadless, ScriptedOrbitRestartsAccumulation) {
    std::string why_not;
    const std::string xvfb = xvfb_prefix(why_not);
    if (xvfb.empty()) GTEST_SKIP() << why_not;
    const fs::path still = temp("viewer_still.png"), moved = temp("viewer_moved.png");
    const std::string common = " view " + kCornell + " --res 48x48 --spp 64 --threads 2 --frames 6";
    const test::CommandResult a =
        test::run_command(xvfb + test::glint_binary() + common + " --screenshot " + still.string());
    ASSERT_EQ(a.exit_code, 0) << a.output;
    const test::CommandResult b =
        test::run_command(xvfb + test::glint_binary() + common + " --orbit 30 --orbit-after 4" +
                          " --screenshot " + moved.string());
    ASSERT_EQ(b.exit_code, 0) << b.output;
    // Four passes, then the move: the counter starts again at the pass after it.
    EXPECT_EQ(spp_by_frame(b.output), (std::vector<int>{1, 2, 3, 4, 1, 2})) << b.output;
    EXPECT_NE(b.output.find("orbit 30 degrees: glint.camera{"), std::string::npos) << b.output;
    // The moved view is another picture.
    EXPECT_GT(compare_images(read_image(moved.string()), read_image(still.string())).rel_mse, 1e-2);
    fs::remove(still);
    fs::remove(moved);
}

TEST(ViewerHeadless, TemporalModeAndSvgfAfterAnOrbit) {
    std::string why_not;
    const std::string xvfb = xvfb_prefix(why_not);
    if (xvfb.empty()) GTEST_SKIP() << why_not;
    const fs::path shot = temp("viewer_temporal.png");
    const test::CommandResult r = test::run_command(
        xvfb + test::glint_binary() + " view " + kCornell +
        " --res 48x48 --spp 64 --threads 2 --frames 6 --orbit 5 --orbit-after 3 --temporal on "
        "--svgf on --screenshot " +
        shot.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // No reduced pass after the move: the reprojected history fills the view.
    EXPECT_EQ(spp_by_frame(r.output), (std::vector<int>{1, 2, 3, 1, 2, 3})) << r.output;
    EXPECT_NE(r.output.find("frame 4: 1 spp, path pass"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("with reprojected history, SVGF"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(shot));
    fs::remove(shot);
#ifdef GLINT_HAVE_VIEWER
    const test::CommandResult bad =
        test::run_glint("view " + kCornell + " --frames 2 --temporal maybe");
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("--temporal"), std::string::npos) << bad.output;
#endif
}

TEST(ViewerHeadless, NoDisplayIsAClearError) {
#ifndef GLINT_HAVE_VIEWER
    GTEST_SKIP() << "glint was built without the viewer";
#endif
    const test::CommandResult r =
        test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + test::glint_binary() + " view " +
                          kCornell + " --frames 1");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("needs a display"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("xvfb-run"), std::string::npos) << r.output;
}

TEST(ViewerHeadless, BadFlagsNameTheFlag) {
    const test::CommandResult r = test::run_glint("view " + kCornell + " --screenshot x.png");
    EXPECT_NE(r.exit_code, 0);
#ifdef GLINT_HAVE_VIEWER
    EXPECT_NE(r.output.find("--screenshot"), std::string::npos) << r.output;
    const test::CommandResult tone = test::run_glint("view " + kCornell + " --tonemap aces");
    EXPECT_EQ(tone.exit_code, 2);
    EXPECT_NE(tone.output.find("--tonemap"), std::string::npos) << tone.output;
#endif
}

}  // namespace
}  // namespace glint
