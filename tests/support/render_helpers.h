#pragma once
// Renders scene scripts in-process for tests, and runs the glint binary for CLI tests.
#include <glint/core/spectrum.h>
#include <glint/film/image.h>
#include <glint/scene/render_settings.h>

#include <string>

namespace glint::test {

// Loads a Lua scene from `code`, renders it with its own settings and `threads`
// (0 = all), and returns the resolved image.
Image render_lua(const std::string& code, int threads = 0);

// The whole content of a text file (throws glint::Error when it cannot be read).
std::string read_text(const std::string& path);

// Every pixel's RGB must be within `tolerance` (relative) of `expected`; reports the
// first few that are not as test failures.
void expect_all_pixels(const Image& image, const Spectrum& expected, double tolerance);

// Mean of channel `c` over a rectangle of the image.
double mean_channel(const Image& image, int c, int x0, int y0, int x1, int y1);

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};
// Runs the glint binary ($GLINT_BINARY, else the one this build made) with `arguments`.
CommandResult run_glint(const std::string& arguments);

}  // namespace glint::test
