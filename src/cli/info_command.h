#pragma once
// `glint info`: counts of shapes, triangles, lights, memory and bounds of a scene.
#include <CLI/CLI.hpp>

#include <string>

namespace glint::cli {

struct InfoOptions {
    std::string scene;
    bool trusted_scene = false;
    std::string script_time_limit;
};

/// Adds the subcommand and its flags, which fill `options` when parsed.
CLI::App* add_info_command(CLI::App& app, InfoOptions& options);

int run_info(const InfoOptions& options);

}  // namespace glint::cli
