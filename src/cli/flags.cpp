#include "flags.h"

#include "signals.h"

#include <glint/core/strict_number.h>
#include <glint/scene/import/import.h>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <string_view>

namespace glint::cli {

void bad_flag(const std::string& flag, const std::string& text, const std::string& expected) {
    throw CLI::ValidationError(flag, fmt::format("'{}' is not {}", text, expected));
}

std::optional<int> int_flag(const std::string& flag, const std::string& text, int min, int max) {
    if (text.empty()) return std::nullopt;
    const auto value = parse_integer(text, min, max);
    if (!value) bad_flag(flag, text, fmt::format("an integer from {} to {}", min, max));
    return static_cast<int>(*value);
}

std::vector<double> parse_crop(const std::string& text) {
    std::vector<double> corners;
    std::string_view rest = text;
    for (int i = 0; i < 4; ++i) {
        const size_t comma = i < 3 ? rest.find(',') : rest.size();
        const auto value = comma == std::string_view::npos
                               ? std::nullopt
                               : parse_integer(rest.substr(0, comma), 0, kMaxResolution);
        if (!value) bad_flag("--crop", text, "x0,y0,x1,y1 in pixels, e.g. 64,32,128,96");
        corners.push_back(static_cast<double>(*value));
        rest = comma < rest.size() ? rest.substr(comma + 1) : std::string_view();
    }
    return corners;
}

Vec2i parse_resolution_flag(const std::string& text) {
    const auto res = glint::parse_resolution(text, kMaxResolution);
    if (!res) {
        bad_flag(
            "--res", text,
            fmt::format("WIDTHxHEIGHT with each side from 1 to {}, e.g. 512x512", kMaxResolution));
    }
    return Vec2i(res->first, res->second);
}

LoaderOptions loader_options(bool trusted_scene, const std::string& time_limit) {
    LoaderOptions options;
    options.interrupt = &g_signal;
    if (trusted_scene) {
        options.trusted = true;
        options.memory_limit = 0;
        options.instruction_limit = 0;
        options.time_limit = 0;
    }
    if (!time_limit.empty()) {
        const auto seconds = parse_finite(time_limit);
        if (!seconds || *seconds < 0 || *seconds > kMaxScriptTimeLimit) {
            bad_flag(
                "--script-time-limit", time_limit,
                fmt::format("a number of seconds from 0 (no limit) to {:g}", kMaxScriptTimeLimit));
        }
        options.time_limit = *seconds;
    }
    return options;
}

SceneDesc load_scene(const std::string& path, const LoaderOptions& options) {
    SceneDesc desc = is_model_file(path) ? load_model_scene(path) : load_scene_file(path, options);
    for (const std::string& warning : desc.warnings) fmt::print(stderr, "warning: {}\n", warning);
    return desc;
}

const char* trusted_scene_help() {
    return "Run the scene script with Lua's full standard library (io, os, debug, package) and "
           "without memory, instruction or time limits: only for scenes you trust";
}

std::string script_time_limit_help() {
    return fmt::format(
        "Seconds the scene script may run (default {:g}; 0 = no limit); a script past it ends "
        "with an error naming its line",
        LoaderOptions{}.time_limit);
}

}  // namespace glint::cli
