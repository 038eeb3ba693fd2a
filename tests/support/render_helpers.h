#pragma once
// Renders scene scripts in-process for tests, and runs the glint binary for CLI tests.
#include <glint/core/spectrum.h>
#include <glint/film/image.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene.h>
#include <glint/scene/scene_desc.h>

#include <string>

namespace glint::test {

// Loads a Lua scene from `code`, renders it with its own settings and `threads`
// (0 = all), and returns the resolved image.
Image render_lua(const std::string& code, int threads = 0);

// render_lua, with the integrator's statistics (rays traced, samples) as well.
struct RenderResult {
    Image image;
    RenderStats stats;
};
RenderResult render_lua_with_stats(const std::string& code, int threads = 0);

// The whole content of a text file (throws glint::Error when it cannot be read).
std::string read_text(const std::string& path);

// A scene script loaded and built, with what it was built from, for tests that drive an
// integrator or the scene directly. `name` stands for the script's file in messages.
struct BuiltScene {
    SceneDesc desc;
    RenderSettings settings;
    std::unique_ptr<Scene> scene;
};
BuiltScene build_lua(const std::string& code, const std::string& name = "test.lua");

// The example scene examples/`name` with its glint.render{...} call replaced by
// glint.render{ `settings` } (a second glint.render would be an error).
std::string example_with_settings(const std::string& name, const std::string& settings);

// Every pixel's RGB must be within `tolerance` (relative) of `expected`; reports the
// first few that are not as test failures.
void expect_all_pixels(const Image& image, const Spectrum& expected, double tolerance);

// Mean of channel `c` over a rectangle of the image.
double mean_channel(const Image& image, int c, int x0, int y0, int x1, int y1);

// Standard error of mean_channel() over a rectangle of one render, estimated from two
// independent renders `a` and `b` of the same scene and settings (different seeds): each
// pixel's variance is E[(a - b)^2] / 2, and pixels are independent. Also right when `a`
// and `b` have different sample counts, given them: the variance returned is for `a`.
double standard_error_of_mean(const Image& a, const Image& b, int c, int x0, int y0, int x1, int y1,
                              double spp_a = 1.0, double spp_b = 1.0);

// Standard error of the mean of channel `c` over the whole image, for an image whose pixels
// all have the same expected value: the pixels' spread divided by the square root of their
// number.
double standard_error_of_uniform_mean(const Image& image, int c);

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};
// Runs the glint binary ($GLINT_BINARY, else the one this build made) with `arguments`.
CommandResult run_glint(const std::string& arguments);
// The path of that binary.
std::string glint_binary();
// Runs a shell command line, capturing stdout and stderr together.
CommandResult run_command(const std::string& command_line);

}  // namespace glint::test
