#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <tbb/global_control.h>
#include <cmath>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>

namespace glint::test {

Image render_lua(const std::string& code, int threads) {
    const SceneDesc desc = load_scene_string(code, "test.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    auto integrator = make_integrator(settings);
    Film film(settings.width, settings.height, settings.aovs);
    Progress progress("test", 1, true);
    RenderStats stats;
    if (threads > 0) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        stats = integrator->render(*scene, film, progress);
    } else {
        stats = integrator->render(*scene, film, progress);
    }
    return final_image(film, stats);
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

void expect_all_pixels(const Image& image, const Spectrum& expected, double tolerance) {
    int failures = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double v = image.at(x, y, c);
                if (std::abs(v - expected[c]) > tolerance * expected[c] && failures++ < 5) {
                    ADD_FAILURE() << fmt::format("pixel ({}, {}) channel {}: {} expected {}", x, y,
                                                 c, v, expected[c]);
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

CommandResult run_glint(const std::string& arguments) {
    const char* from_environment = std::getenv("GLINT_BINARY");
    const char* binary = from_environment ? from_environment : GLINT_BINARY_PATH;
    CommandResult result;
    const std::string command = std::string(binary) + " " + arguments + " 2>&1";
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

}  // namespace glint::test
