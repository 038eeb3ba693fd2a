#pragma once
// `glint merge`: adds partial renders (`glint render --samples A:B`) into one image.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace glint::cli {

struct MergeOptions {
    std::vector<std::string> parts;
    std::vector<std::string> outputs;
    std::string exposure;
    std::string tonemap;
    bool quiet = false;
};

/// Adds the subcommand and its arguments, which fill `options` when parsed.
CLI::App* add_merge_command(CLI::App& app, MergeOptions& options);

int run_merge(const MergeOptions& options);

}  // namespace glint::cli
