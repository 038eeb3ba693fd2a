#pragma once
// `glint render`: a scene to EXR and/or PNG files.
#include "render_options.h"

#include <CLI/CLI.hpp>

namespace glint::cli {

/// Adds the subcommand and its flags, which fill `options` when parsed.
CLI::App* add_render_command(CLI::App& app, RenderOptions& options);

int run_render(const RenderOptions& options);

}  // namespace glint::cli
