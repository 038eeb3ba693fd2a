#include "view_command.h"

#include "flags.h"
#include "signals.h"

#include <glint/core/error.h>
#include <glint/core/strict_number.h>

#ifdef GLINT_HAVE_VIEWER
#include <viewer/viewer.h>
#endif

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <optional>

namespace glint::cli {

namespace {

constexpr int kDefaultViewSpp = 1024;

}  // namespace

CLI::App* add_view_command(CLI::App& app, ViewOptions& view) {
    CLI::App* view_cmd = app.add_subcommand(
        "view", "Show a scene in a window as it renders, pass by pass (docs/viewer.md)");
    view_cmd->add_option("scene", view.render.scene, "Scene script (.lua)")->required();
    view_cmd->add_option("--spp", view.render.spp,
                         fmt::format("Passes after which accumulation stops (default {}); after "
                                     "N passes the image is `glint render --spp N`'s",
                                     kDefaultViewSpp));
    view_cmd->add_option("--res", view.render.resolution, "Resolution WIDTHxHEIGHT");
    view_cmd->add_option("--threads", view.render.threads, "Worker threads (default: all cores)");
    view_cmd->add_option("--seed", view.render.seed, "Random seed, 0 to 2^64 - 1");
    view_cmd->add_option("--integrator", view.render.integrator,
                         "Light transport algorithm that renders pass by pass, e.g. path");
    view_cmd->add_option("--exposure", view.render.exposure, "Display exposure in stops");
    view_cmd->add_option("--tonemap", view.tone_map,
                         "Display tone mapping: clip, reinhard or filmic (as render's PNG output)");
    view_cmd->add_option("--frames", view.frames,
                         "Headless: render N full passes, write --screenshot, exit");
    view_cmd->add_option("--screenshot", view.screenshot,
                         "Headless: write what the window shows after --frames N (.png)");
    view_cmd->add_option("--orbit", view.orbit,
                         "Headless: orbit the camera by DEG degrees after --orbit-after K frames");
    view_cmd->add_option("--orbit-after", view.orbit_after, "Frames before the --orbit move");
    view_cmd->add_option("--reduced-scale", view.reduced_scale,
                         "The first pass after a change renders at 1/N size (1 to 64, default 4)");
    view_cmd->add_option("--temporal", view.temporal,
                         "on|off: blend the reprojected history of earlier views after a camera "
                         "move (default: on for the preview integrator)");
    view_cmd->add_option("--svgf", view.svgf,
                         "on|off: filter every frame with the real-time denoiser (default off; "
                         "the viewer only, never `glint render`)");
    view_cmd->add_flag("--spectral", view.render.spectral,
                       "Spectral mode: each pass carries four wavelengths (preview: its camera "
                       "paths and caustic photons alike), so dispersion shows its colours");
    view_cmd->add_flag("--hide-panel", view.hide_panel, "Start with the panel hidden (key H)");
    view_cmd->add_flag("--trusted-scene", view.render.trusted_scene, trusted_scene_help());
    view_cmd->add_option("--script-time-limit", view.render.script_time_limit,
                         script_time_limit_help());
    return view_cmd;
}

int run_view(const ViewOptions& view) {
#ifndef GLINT_HAVE_VIEWER
    (void)view;
    throw Error(
        "this glint was built without the viewer: install libglfw3-dev and libimgui-dev "
        "(scripts/install-deps.sh) and build again");
#else
    viewer::ViewerOptions options;
    options.scene_path = view.render.scene;
    options.tone_map = view.tone_map;
    if (options.tone_map != "clip" && options.tone_map != "reinhard" &&
        options.tone_map != "filmic")
        bad_flag("--tonemap", view.tone_map, "clip, reinhard or filmic");
    options.frames = int_flag("--frames", view.frames, 1, 1 << 20).value_or(0);
    options.screenshot = view.screenshot;
    if (!options.screenshot.empty() && options.frames == 0)
        bad_flag("--screenshot", view.screenshot, "usable without --frames N");
    if (!view.orbit.empty()) {
        const auto degrees = parse_finite(view.orbit);
        if (!degrees || std::abs(*degrees) > 360.0)
            bad_flag("--orbit", view.orbit, "a number of degrees from -360 to 360");
        options.orbit_degrees = static_cast<float>(*degrees);
        options.orbit_after = int_flag("--orbit-after", view.orbit_after, 1, 1 << 20).value_or(1);
        if (options.frames == 0 || options.orbit_after >= options.frames) {
            bad_flag("--orbit-after", view.orbit_after.empty() ? "1" : view.orbit_after,
                     "a number of frames below --frames N (the move is scripted for headless use)");
        }
    }
    options.reduced_scale = int_flag("--reduced-scale", view.reduced_scale, 1, 64).value_or(4);
    options.hide_panel = view.hide_panel;
    auto on_off = [](const char* flag, const std::string& value) -> std::optional<bool> {
        if (value.empty()) return std::nullopt;
        if (value == "on") return true;
        if (value == "off") return false;
        bad_flag(flag, value, "on or off");
        return std::nullopt;
    };
    options.temporal = on_off("--temporal", view.temporal);
    options.svgf = on_off("--svgf", view.svgf).value_or(false);
    options.interrupt = &g_signal;

    // A model file (.glb, .obj, ...) is shown as `glint render MODEL` renders it, not read
    // as Lua.
    const SceneDesc desc =
        load_scene(view.render.scene,
                   loader_options(view.render.trusted_scene, view.render.script_time_limit));
    RenderOptions render = view.render;
    if (render.spp.empty()) render.spp = std::to_string(kDefaultViewSpp);
    const RenderSettings settings =
        with_flag_errors_as_usage_errors([&] { return settings_for(desc, render); });
    options.exposure = settings.exposure;
    const int threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const int code = viewer::run_viewer(desc, settings, options);
    throw_if_interrupted();  // the window closed on SIGINT or SIGTERM
    return code;
#endif
}

}  // namespace glint::cli
