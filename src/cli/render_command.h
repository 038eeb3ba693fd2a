#pragma once
// `glint render`: a scene to EXR and/or PNG files.
#include "render_options.h"

#include <glint/cluster/cluster.h>

#include <CLI/CLI.hpp>

namespace glint::cli {

/// Adds the subcommand and its flags, which fill `options` when parsed.
CLI::App* add_render_command(CLI::App& app, RenderOptions& options);

/// Renders as one process, or as this rank's part of an MPI job when `cluster` has several
/// ranks (docs/cluster.md).
int run_render(const RenderOptions& options, Cluster& cluster);

}  // namespace glint::cli
