// The `glint` command: render, info, compare, merge, view and warp, one file each
// (*_command.cpp). The only place that catches glint::Error and turns it into an exit code.
#include "compare_command.h"
#include "flags.h"
#include "info_command.h"
#include "merge_command.h"
#include "render_command.h"
#include "signals.h"
#include "view_command.h"
#include "warp_command.h"

#include <glint/cluster/cluster.h>
#include <glint/core/error.h>
#include <glint/geometry/accel.h>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <csignal>
#include <memory>
#include <new>

int main(int argc, char** argv) {
    using namespace glint::cli;
    // First: MPI_Init may take its own arguments out of argv. A single process unless
    // started by mpirun.
    const std::unique_ptr<glint::Cluster> cluster = glint::make_cluster(argc, argv);
    CLI::App app{"glint: a physically based renderer driven by Lua scenes"};
    app.require_subcommand(1);
    app.set_version_flag("--version",
                         fmt::format("glint 0.1.0 (Embree {})", glint::Accel::embree_version()));

    RenderOptions render;
    const CLI::App* render_cmd = add_render_command(app, render);
    InfoOptions info;
    const CLI::App* info_cmd = add_info_command(app, info);
    CompareOptions compare;
    const CLI::App* compare_cmd = add_compare_command(app, compare);
    MergeOptions merge;
    const CLI::App* merge_cmd = add_merge_command(app, merge);
    ViewOptions view;
    const CLI::App* view_cmd = add_view_command(app, view);
    WarpOptions warp;
    const CLI::App* warp_cmd = add_warp_command(app, warp);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kExitUsageError;
    }

    install_signal_handlers();
    try {
        if (render_cmd->parsed()) return run_render(render, *cluster);
        if (info_cmd->parsed()) return run_info(info);
        if (compare_cmd->parsed()) return run_compare(compare);
        if (merge_cmd->parsed()) return run_merge(merge);
        if (view_cmd->parsed()) return run_view(view);
        if (warp_cmd->parsed()) return run_warp(warp);
    } catch (const CLI::ValidationError& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return kExitUsageError;
    } catch (const glint::Interrupted& e) {
        fmt::print(stderr, "glint: interrupted by {}; no output written\n",
                   signal_name(e.signal()));
        return 128 + e.signal();
    } catch (const glint::Error& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return kExitInputError;
    } catch (const std::bad_alloc&) {
        // The budget checks (core/memory.h) catch the big buffers; this is the last resort.
        fmt::print(stderr,
                   "glint: error: out of memory; reduce the resolution, the number of photons "
                   "or the textures' sizes\n");
        return kExitInputError;
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint: internal error: {}\n", e.what());
        return kExitInputError;
    }
    return kExitUsageError;
}
