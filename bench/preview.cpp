// The preview integrator's frame times and convergence, as the viewer would see them: it
// calls render_pass() in a loop, as the viewer does each frame, and times each pass.
//   glint_bench_preview SCENE.lua --res WxH [--threads T] [--frames N] [--moves M]
//                       [--set KEY=VALUE ...] [--packets 0|1]
//                       [--snapshots "0.25 1 4" --prefix OUT]
// Prints the median ms per pass, split into the photon pass and the camera pass, the
// frames per second that gives, and the median ms of the first pass after a camera move
// (scene_changed(camera), a cleared film, one pass) and after a light move (the same with
// scene_changed(lights_or_objects): the photons are dropped). --packets 0 traces the camera pass
// one ray at a time (the same image; to measure what the packets gain). --set takes a number, true,
// false or else a string (e.g. --set preview_restir=off). With --snapshots, then renders
// from no photons for the longest of the times and writes OUT.<t>.exr after the last pass that
// ended within each time t (seconds), for glint_bench_region_error.
// Last, what the viewer shows after a light move (ProgressiveSession, as `glint view` runs
// it): the scene's first movable light is moved 5 cm back and forth, and the bench prints the
// median ms from the move to the first image (the scene rebuilt, the photons dropped, and
// the reduced pass at a quarter of the size on each side) and to the first full pass after it.
#include "settings_override.h"
#include "timing.h"

#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/preview.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/view/light_edits.h>
#include <glint/view/progressive_session.h>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace glint;
using bench::cpu_seconds;
using bench::median;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The viewer's latency after a light move (see the header comment); prints nothing for a
// scene without a movable light.
void print_viewer_light_moves(const SceneDesc& desc, const RenderSettings& settings, int moves) {
    LightEdits edits(desc);
    const auto movable = std::find_if(edits.lights().begin(), edits.lights().end(),
                                      [](const EditableLight& light) { return light.movable; });
    if (movable == edits.lights().end() || moves < 1) return;
    ProgressiveSession session(desc, settings);
    Progress progress("preview", 1, true);
    session.render_next(progress);  // the reduced pass after loading
    session.render_next(progress);  // and a full one
    std::vector<double> first_image_ms, first_full_ms;
    for (int move = 0; move < moves; ++move) {
        movable->offset.x = move % 2 == 0 ? 0.05f : 0.0f;
        session.set_lights(edits);
        const auto start = std::chrono::steady_clock::now();
        if (session.render_next(progress) != PassKind::reduced)
            throw Error("bench: the viewer's first pass after a light move was not reduced");
        first_image_ms.push_back(1e3 * seconds_since(start));
        session.render_next(progress);
        first_full_ms.push_back(1e3 * seconds_since(start));
    }
    fmt::print(
        "in the viewer, after a light move ({}): first image (scene rebuilt, reduced pass) "
        "{:.1f} ms, first full pass {:.1f} ms after the move; medians of {} moves\n",
        movable->name, median(first_image_ms), median(first_full_ms), moves);
}

int run(int argc, char** argv) {
    if (argc < 2)
        throw Error(
            "usage: glint_bench_preview SCENE.lua --res WxH [--threads T] "
            "[--frames N] [--moves M] [--set KEY=VALUE] [--packets 0|1] "
            "[--snapshots \"0.25 1 4\" --prefix OUT]");
    const std::string path = argv[1];
    int width = 640, height = 480, threads = 0, frames = 30, moves = 5;
    std::vector<double> snapshots;
    std::string prefix;
    bool packets = true;
    std::vector<std::pair<std::string, ParamValue>> overrides;
    for (int i = 2; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) throw Error(fmt::format("{} needs a value", flag));
        const std::string value = argv[++i];
        if (flag == "--res") {
            if (std::sscanf(value.c_str(), "%dx%d", &width, &height) != 2 || width < 1 ||
                height < 1)
                throw Error(fmt::format("--res: '{}' is not WIDTHxHEIGHT", value));
        } else if (flag == "--threads") {
            threads = std::stoi(value);
        } else if (flag == "--frames") {
            frames = std::max(1, std::stoi(value));
        } else if (flag == "--moves") {
            moves = std::max(0, std::stoi(value));
        } else if (flag == "--snapshots") {
            std::istringstream in(value);
            for (double t; in >> t;) snapshots.push_back(t);
            std::sort(snapshots.begin(), snapshots.end());
        } else if (flag == "--set") {
            overrides.push_back(bench::parse_setting_override(value));
        } else if (flag == "--packets") {
            packets = value != "0";
        } else if (flag == "--prefix") {
            prefix = value;
        } else {
            throw Error(fmt::format("unknown flag {}", flag));
        }
    }
    if (!snapshots.empty() && prefix.empty()) throw Error("--snapshots needs --prefix");

    const SceneDesc desc = load_scene_file(path);
    Params table = desc.render ? *desc.render : Params("render", "render settings");
    table.set("width", static_cast<double>(width), "--res");
    table.set("height", static_cast<double>(height), "--res");
    table.set("integrator", std::string("preview"), "bench");
    for (const auto& [key, value] : overrides) table.set(key, value, "--set");
    const RenderSettings settings = parse_render_settings(&table);
    const auto scene = build_scene(desc, settings);
    const int used_threads = threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, used_threads);
    Progress progress("preview", 1, true);

    auto integrator = make_integrator(settings);
    auto& preview = dynamic_cast<PreviewIntegrator&>(*integrator);
    preview.set_packets(packets);
    Film film(width, height, false);
    std::vector<double> photon_ms, camera_ms, total_ms, moved_ms, cpu_ms;
    for (int pass = 0; pass < frames; ++pass) {
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = cpu_seconds();
        preview.render_pass(*scene, film, pass, progress);
        total_ms.push_back(1e3 * seconds_since(start));
        cpu_ms.push_back(1e3 * (cpu_seconds() - cpu_start) / used_threads);
        photon_ms.push_back(1e3 * preview.last_pass_timing().photons);
        camera_ms.push_back(1e3 * preview.last_pass_timing().camera);
    }
    // What the viewer does after a change: tell the integrator, clear the film, one pass. A
    // camera move keeps the photons; after a light move they are dropped, and the first pass
    // traces a new batch alone.
    const auto first_passes_after = [&](SceneChange change) {
        std::vector<double> ms;
        for (int move = 0; move < moves; ++move) {
            preview.scene_changed(change);
            film.clear();
            const auto start = std::chrono::steady_clock::now();
            preview.render_pass(*scene, film, 0, progress);
            ms.push_back(1e3 * seconds_since(start));
        }
        return ms;
    };
    moved_ms = first_passes_after(SceneChange::camera);
    const std::vector<double> relit_ms = first_passes_after(SceneChange::lights_or_objects);
    const double total = median(total_ms);
    fmt::print(
        "{} {}x{} threads {}: {:.1f} fps, {:.1f} ms/frame (photon pass {:.1f} ms, camera "
        "pass {:.1f} ms, display: measured in the viewer), first pass after a camera "
        "move {:.1f} ms, after a light move {:.1f} ms; CPU time per frame / threads {:.1f} ms; "
        "{} photons kept ({} in media); medians of {} passes and {} moves\n",
        path, width, height, used_threads, 1e3 / total, total, median(photon_ms), median(camera_ms),
        median(moved_ms), median(relit_ms), median(cpu_ms), preview.stored_photons(),
        preview.stored_volume_photons(), frames, moves);

    print_viewer_light_moves(desc, settings, moves);

    if (!snapshots.empty()) {
        preview.scene_changed(SceneChange::lights_or_objects);  // from no photons
        film.clear();
        Image image = film.resolve();
        size_t next = 0;
        int passes = 0;
        const auto start = std::chrono::steady_clock::now();
        while (next < snapshots.size()) {
            preview.render_pass(*scene, film, passes, progress);
            const double elapsed = seconds_since(start);
            // The image to keep for a time is the last one finished within it.
            while (next < snapshots.size() && elapsed > snapshots[next]) {
                write_image(fmt::format("{}.{}.exr", prefix, snapshots[next]), image, {});
                fmt::print("  {} s: {} passes\n", snapshots[next], passes);
                ++next;
            }
            ++passes;
            image = film.resolve();
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
