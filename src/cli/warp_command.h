#pragma once
// `glint warp`: a rendered image with a depth AOV seen from a nearby viewpoint (3D image
// warping, view/image_warp.h), disocclusions marked (docs/cli.md).
#include <CLI/CLI.hpp>

#include <string>

namespace glint::cli {

struct WarpOptions {
    std::string image;
    std::string camera;
    std::string output;
    std::string scene;
    std::string exposure;
    std::string tone_map = "clip";
    bool trusted_scene = false;
};

/// Adds the subcommand and its arguments, which fill `options` when parsed.
CLI::App* add_warp_command(CLI::App& app, WarpOptions& options);

int run_warp(const WarpOptions& options);

}  // namespace glint::cli
