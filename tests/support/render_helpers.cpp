#include <glint/core/error.h>
#include <glint/integrator/integrator.h>
#include <glint/render/render_job.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cmath>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>

namespace glint::test {

Image render_lua(const std::string& code, int threads) {
    return render_lua_with_stats(code, threads).image;
}

RenderResult render_lua_with_stats(const std::string& code, int threads) {
    const SceneDesc desc = load_scene_string(code, "test.lua");
    RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    settings.threads = threads;
    RenderControl control;
    control.quiet = true;
    control.warn = [](const std::string&) {};  // keys of other integrators: not a test's concern
    RenderedImage rendered = render_image(desc, settings, control);
    return {std::move(rendered.image), std::move(rendered.stats)};
}

std::string read_text(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw Error("cannot open " + path);
    std::string text;
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, n);
    std::fclose(file);
    return text;
}

std::string example_with_settings(const std::string& name, const std::string& settings) {
    const std::string code = read_text(std::string(GLINT_SOURCE_DIR) + "/examples/" + name);
    // The call spans its output list's braces: it ends at the first '}' after that list's.
    const size_t start = code.find("glint.render{");
    if (start == std::string::npos) throw Error(name + " has no glint.render{...}");
    const size_t output = code.find("output", start);
    const size_t output_end = code.find('}', output);
    const size_t end = code.find('}', output_end + 1);
    if (output == std::string::npos || output_end == std::string::npos || end == std::string::npos)
        throw Error(name + ": glint.render{...} has no output list");
    return code.substr(0, start) + "glint.render{ " + settings + " }" + code.substr(end + 1);
}

void expect_all_pixels(const Image& image, const Spectrum& expected, double tolerance) {
    int failures = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double v = image.at(x, y, c);
                if (std::abs(v - to_rgb(expected)[c]) > tolerance * to_rgb(expected)[c] &&
                    failures++ < 5) {
                    ADD_FAILURE() << fmt::format("pixel ({}, {}) channel {}: {} expected {}", x, y,
                                                 c, v, to_rgb(expected)[c]);
                }
            }
        }
    }
    EXPECT_EQ(failures, 0);
}

double mean_channel(const Image& image, int c, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) sum += image.at(x, y, c);
    }
    return sum / (static_cast<double>(x1 - x0) * (y1 - y0));
}

double standard_error_of_mean(const Image& a, const Image& b, int c, int x0, int y0, int x1, int y1,
                              double spp_a, double spp_b) {
    // With per-sample variance s^2, E[(a - b)^2] = s^2 (1/spp_a + 1/spp_b).
    double sum = 0.0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const double d = static_cast<double>(a.at(x, y, c)) - b.at(x, y, c);
            sum += d * d;
        }
    }
    const double n = static_cast<double>(x1 - x0) * (y1 - y0);
    const double sample_variance = sum / n / (1.0 / spp_a + 1.0 / spp_b);
    return std::sqrt(sample_variance / spp_a / n);
}

double standard_error_of_uniform_mean(const Image& image, int c) {
    const double n = static_cast<double>(image.width) * image.height;
    const double mean = mean_channel(image, c, 0, 0, image.width, image.height);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double d = image.at(x, y, c) - mean;
            sum += d * d;
        }
    }
    return std::sqrt(sum / (n - 1.0) / n);
}

std::string glint_binary() {
    const char* from_environment = std::getenv("GLINT_BINARY");
    return from_environment ? from_environment : GLINT_BINARY_PATH;
}

CommandResult run_command(const std::string& command_line) {
    CommandResult result;
    const std::string command = command_line + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        result.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

CommandResult run_glint(const std::string& arguments) {
    return run_command(glint_binary() + " " + arguments);
}

BuiltScene build_lua(const std::string& code, const std::string& name) {
    BuiltScene b;
    b.desc = load_scene_string(code, name);
    b.settings = parse_render_settings(b.desc.render ? &*b.desc.render : nullptr);
    b.scene = build_scene(b.desc, b.settings);
    return b;
}

}  // namespace glint::test
