// The viewer's real-time path without a window (issue 35): what a camera move costs in
// temporal mode and what the SVGF denoiser costs per frame. Runs a ProgressiveSession as the
// viewer does (realtime buffers, temporal mode, the scene's own integrator unless --integrator
// is given), and times each part on its own as well:
//   glint_bench_realtime [SCENE.lua] [--res WxH ...] [--threads T] [--frames N]
//                        [--integrator NAME] [--svgf-radius 1|2] [--set KEY=VALUE ...]
// Prints, per resolution, the medians over N moves of: the geometry buffer trace, the
// reprojection, one integrator pass, the whole first frame after a move (render_next after
// set_camera: geometry buffer + reprojection + pass + bookkeeping) and svgf_image(); wall
// clock and, for the first frame and SVGF, CPU time divided by the threads (what it would
// take alone on a machine shared with other work); and the two together, a frame while the
// camera moves with SVGF on. --set overrides a render setting of the scene's (e.g.
// preview_restir=unbiased, preview_bounces=1: everything on).
//
// With --converge, then: one more camera move, after which the camera stays still and
// frames follow one another as in the viewer (a pass, and with --svgf on SVGF on the shown
// image, which the time includes); the relative MSE of the shown image against `path`'s at
// 0.25, 1 and 5 s after the move (and at --converge-until S, when later). path's reference is
// rendered at that camera with
// --reference-spp samples (default 256) and max_depth = preview_bounces + 1 (what the
// preview converges to where the scene has no caustics), or read from --reference FILE
// when that file exists (and written there otherwise).
#include "settings_override.h"
#include "timing.h"

#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/film/image_io.h>
#include <glint/render/render_job.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/view/camera_controller.h>
#include <glint/view/geometry_buffer.h>
#include <glint/view/progressive_session.h>
#include <glint/view/reprojection.h>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace glint;
using bench::cpu_seconds;
using bench::median;

template <typename F>
double time_ms(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct ConvergeOptions {
    bool on = false;
    bool svgf = false;
    int reference_spp = 256;
    std::string reference;  // a file to read path's reference from, or to write it to
    double until = 0.0;     // one more checkpoint, when later than 5 s
};

// path's image at `camera`: what the preview converges to where the scene has no caustics.
Image path_reference(const SceneDesc& desc, const Params& table,
                     const RenderSettings& preview_settings, const Params& camera, int threads,
                     const ConvergeOptions& options) {
    if (!options.reference.empty() && std::filesystem::exists(options.reference))
        return read_image(options.reference);
    SceneDesc at_camera = desc;
    at_camera.camera = camera;
    RenderSettings settings = preview_settings;
    settings.integrator = "path";
    settings.spp = options.reference_spp;
    settings.threads = threads;
    const int bounces = table.has("preview_bounces") ? table.get_int("preview_bounces", 0) : 0;
    if (bounces > 0) settings.max_depth = bounces + 1;
    fmt::print("rendering path's reference: {} spp, max_depth {}\n", settings.spp,
               settings.max_depth);
    std::fflush(stdout);
    Image image = render_image(at_camera, settings).image;
    if (!options.reference.empty()) write_image(options.reference, image);
    return image;
}

// After one more camera move, frames as the viewer makes them with the camera still; the
// shown image's relative MSE against path's at 0.25, 1 and 5 s after the move.
void converge(const SceneDesc& desc, const Params& table, const RenderSettings& settings,
              const SessionOptions& options, int threads, const ConvergeOptions& converge_options) {
    CameraController controller(desc.camera ? &*desc.camera : nullptr);
    ProgressiveSession session(desc, settings, options);
    Progress progress("bench", 1, true);
    for (int i = 0; i < 3; ++i) session.render_next(progress);  // warm up, as the viewer has
    controller.orbit(1.0f, 0.2f);
    const Image reference =
        path_reference(desc, table, settings, controller.params(), threads, converge_options);
    session.set_camera(controller.params());
    std::vector<double> checkpoints = {0.25, 1.0, 5.0};
    if (converge_options.until > 5.0) checkpoints.push_back(converge_options.until);
    std::vector<std::string> results;
    double elapsed = 0.0;
    int frames = 0;
    for (const double checkpoint : checkpoints) {
        Image shown;
        while (elapsed < checkpoint || frames == 0) {
            const double ms = time_ms([&] {
                session.render_next(progress);
                shown = converge_options.svgf ? session.svgf_image() : session.image();
            });
            elapsed += 1e-3 * ms;
            ++frames;
        }
        const CompareResult r = compare_images(shown, reference);
        results.push_back(fmt::format("{:.2f} s: {:.4f} ({} frames)", elapsed, r.rel_mse, frames));
    }
    fmt::print("{}x{}, after a camera move, SVGF {}: relative MSE against path's {}\n",
               settings.width, settings.height, converge_options.svgf ? "on" : "off",
               fmt::join(results, ", "));
}

void bench_resolution(const SceneDesc& desc, const std::string& integrator, Vec2i res, int frames,
                      int threads, int svgf_radius,
                      const std::vector<std::pair<std::string, ParamValue>>& overrides,
                      const ConvergeOptions& converge_options) {
    Params table = desc.render ? *desc.render : Params("render", "render settings");
    for (const auto& [key, value] : overrides) table.set(key, value, "--set");
    table.set("width", static_cast<double>(res.x), "--res");
    table.set("height", static_cast<double>(res.y), "--res");
    table.set("integrator", integrator, "--integrator");
    table.set("spp", static_cast<double>(1 << 20), "bench");
    const RenderSettings settings = parse_render_settings(&table);
    SessionOptions options;
    options.realtime = true;
    options.temporal = true;
    options.svgf.kernel_radius = svgf_radius;
    ProgressiveSession session(desc, settings, options);
    Progress progress("bench", 1, true);
    CameraController controller(desc.camera ? &*desc.camera : nullptr);
    for (int i = 0; i < 3; ++i) session.render_next(progress);  // warm up, fill the history

    std::vector<double> gbuffer, reproject_ms, pass, first, first_cpu, svgf, svgf_cpu;
    for (int frame = 0; frame < frames; ++frame) {
        // A small orbit per frame, as a mouse drag gives.
        const Params before = controller.params();
        controller.orbit(1.0f, 0.2f);
        const auto previous_camera = make_camera(before, res);
        const auto camera = make_camera(controller.params(), res);
        GeometryBuffer previous_buffer, buffer;
        gbuffer.push_back(time_ms(
            [&] { buffer = trace_geometry_buffer(session.scene(), *camera, res.x, res.y); }));
        previous_buffer = trace_geometry_buffer(session.scene(), *previous_camera, res.x, res.y);
        reproject_ms.push_back(
            time_ms([&] { reproject(buffer, *camera, previous_buffer, *previous_camera); }));

        session.set_camera(controller.params());
        const double cpu_start = cpu_seconds();
        first.push_back(time_ms([&] { session.render_next(progress); }));
        first_cpu.push_back(1e3 * (cpu_seconds() - cpu_start) / threads);
        pass.push_back(1e3 * session.last_stats().seconds);
        const double svgf_cpu_start = cpu_seconds();
        svgf.push_back(time_ms([&] { (void)session.svgf_image(); }));
        svgf_cpu.push_back(1e3 * (cpu_seconds() - svgf_cpu_start) / threads);
    }
    std::vector<double> moving(first.size());
    for (size_t i = 0; i < first.size(); ++i) moving[i] = first[i] + svgf[i];
    fmt::print(
        "{}x{} {} threads, {} moves, median ms: geometry buffer {:.1f}, reprojection {:.1f}, "
        "{} pass {:.1f}, first frame after a move {:.1f} (CPU/threads {:.1f}), SVGF {}x{} {:.1f} "
        "(CPU/threads {:.1f}); moving frame with SVGF {:.1f} ({:.1f} fps)\n",
        res.x, res.y, threads, frames, median(gbuffer), median(reproject_ms), settings.integrator,
        median(pass), median(first), median(first_cpu), 2 * svgf_radius + 1, 2 * svgf_radius + 1,
        median(svgf), median(svgf_cpu), median(moving), 1e3 / median(moving));
    if (converge_options.on) converge(desc, table, settings, options, threads, converge_options);
}

int run(int argc, char** argv) {
    std::string path = "examples/cornell-box.lua";
    std::vector<Vec2i> resolutions;
    int threads = 2, frames = 20, svgf_radius = 2;
    std::string integrator;
    std::vector<std::pair<std::string, ParamValue>> overrides;
    ConvergeOptions converge_options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw Error(fmt::format("{} needs a value", arg));
            return argv[++i];
        };
        if (arg == "--res") {
            Vec2i r;
            const std::string text = next();
            if (std::sscanf(text.c_str(), "%dx%d", &r.x, &r.y) != 2)
                throw Error("--res takes WIDTHxHEIGHT");
            resolutions.push_back(r);
        } else if (arg == "--threads") {
            threads = std::stoi(next());
        } else if (arg == "--frames") {
            frames = std::stoi(next());
        } else if (arg == "--svgf-radius") {
            svgf_radius = std::stoi(next());
        } else if (arg == "--integrator") {
            integrator = next();
        } else if (arg == "--set") {
            overrides.push_back(bench::parse_setting_override(next()));
        } else if (arg == "--converge") {
            converge_options.on = true;
        } else if (arg == "--svgf") {
            const std::string value = next();
            if (value != "on" && value != "off") throw Error("--svgf takes on or off");
            converge_options.svgf = value == "on";
        } else if (arg == "--reference") {
            converge_options.reference = next();
        } else if (arg == "--converge-until") {
            converge_options.until = std::stod(next());
        } else if (arg == "--reference-spp") {
            converge_options.reference_spp = std::stoi(next());
        } else {
            path = arg;
        }
    }
    if (resolutions.empty()) resolutions = {Vec2i(640, 480), Vec2i(1280, 720)};
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const SceneDesc desc = load_scene_file(path);
    fmt::print("{}\n", path);
    for (const Vec2i& res : resolutions)
        bench_resolution(desc, integrator.empty() ? "preview" : integrator, res, frames, threads,
                         svgf_radius, overrides, converge_options);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint_bench_realtime: {}\n", e.what());
        return 1;
    }
}
