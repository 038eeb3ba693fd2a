#pragma once
// `glint view`: a scene in a window as it renders, pass by pass (docs/viewer.md).
#include "render_options.h"

#include <CLI/CLI.hpp>

#include <string>

namespace glint::cli {

/// The render flags that make sense in a window, and the viewer's own.
struct ViewOptions {
    RenderOptions render;  // scene, spp (the target), res, threads, seed, integrator, exposure
    std::string tone_map = "clip";
    std::string frames;
    std::string screenshot;
    std::string orbit;
    std::string orbit_after;
    std::string reduced_scale;
    bool hide_panel = false;
    std::string temporal;
    std::string svgf;
};

/// Adds the subcommand and its flags, which fill `options` when parsed.
CLI::App* add_view_command(CLI::App& app, ViewOptions& options);

int run_view(const ViewOptions& options);

}  // namespace glint::cli
