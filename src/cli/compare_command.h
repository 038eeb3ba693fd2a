#pragma once
// `glint compare`: relative MSE of an image against a reference, optionally as a gate.
#include <CLI/CLI.hpp>

#include <string>

namespace glint::cli {

struct CompareOptions {
    std::string test_image;
    std::string reference_image;
    std::string threshold;
};

/// Adds the subcommand and its arguments, which fill `options` when parsed.
CLI::App* add_compare_command(CLI::App& app, CompareOptions& options);

int run_compare(const CompareOptions& options);

}  // namespace glint::cli
