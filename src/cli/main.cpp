// The `glint` command: render, info, compare and view. The only place that catches
// glint::Error.
#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/progress.h>
#include <glint/core/strict_number.h>
#include <glint/denoise/film_denoiser.h>
#include <glint/film/image_io.h>
#include <glint/film/output_batch.h>
#include <glint/geometry/accel.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/build.h>
#include <glint/scene/import/import.h>
#include <glint/scene/lua/lua_loader.h>

#ifdef GLINT_HAVE_VIEWER
#include <viewer/viewer.h>
#endif

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <climits>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <new>
#include <optional>

namespace {

using namespace glint;

constexpr int kExitInputError = 1;
constexpr int kExitUsageError = 2;
constexpr int kMaxResolution = 65536;  // as glint.render{width, height}
constexpr int kMaxThreads = 4096;
constexpr double kMaxScriptTimeLimit = 1e6;  // seconds, about 11 days

// The number of the first SIGINT or SIGTERM received, 0 before. The one global of the
// program: a signal handler can reach nothing else. The handler only stores to it (a
// lock-free atomic store is async-signal-safe); the render polls it once per tile through
// Progress, and the output code before each file and before the renames.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int signal) {
    int expected = 0;
    g_signal.compare_exchange_strong(expected, signal);
}

void install_signal_handlers() {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

void throw_if_interrupted() {
    if (const int signal = g_signal.load(); signal != 0) throw Interrupted(signal);
}

// SIGINT and SIGTERM held back while the outputs are renamed into place, so that a run
// ends either with every output renamed or with none.
class SignalBlock {
public:
    SignalBlock() {
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGINT);
        sigaddset(&set, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &set, &m_old);
    }
    ~SignalBlock() { pthread_sigmask(SIG_SETMASK, &m_old, nullptr); }
    SignalBlock(const SignalBlock&) = delete;
    SignalBlock& operator=(const SignalBlock&) = delete;

private:
    sigset_t m_old;
};

// Numeric flags are taken as text and parsed strictly (core/strict_number.h): CLI11's
// conversions wrap 4294967312 to 16 and -1 to 2^64 - 1.
struct RenderOptions {
    std::string scene;
    std::vector<std::string> outputs;
    std::string spp;
    std::string resolution;
    std::string threads;
    std::string seed;
    std::string crop;
    std::string integrator;
    std::string exposure;
    std::string tonemap;
    bool denoise = false;
    std::string denoiser;  // --denoise's value: "network" (the default) or "nlm"
    std::string denoise_quality;
    std::string adaptive;
    std::string photons;
    bool no_mipmap = false;
    std::string intermediate;
    std::vector<std::string> debug;
    bool aovs = false;
    bool quiet = false;
    bool trusted_scene = false;
    std::string script_time_limit;
};

// A Lua scene script, or a model file (.obj, .ply, .gltf, .glb) rendered as it is with a
// default camera and light where it has none. The importers' warnings are printed here.
SceneDesc load_scene(const std::string& path, const LoaderOptions& options) {
    SceneDesc desc = is_model_file(path) ? load_model_scene(path) : load_scene_file(path, options);
    for (const std::string& warning : desc.warnings) fmt::print(stderr, "warning: {}\n", warning);
    return desc;
}

[[noreturn]] void bad_flag(const std::string& flag, const std::string& text,
                           const std::string& expected) {
    throw CLI::ValidationError(flag, fmt::format("'{}' is not {}", text, expected));
}

// A scene runs sandboxed with bounded memory, instructions and time unless the user vouches
// for it; --script-time-limit sets the time limit either way.
LoaderOptions loader_options(bool trusted_scene, const std::string& time_limit) {
    LoaderOptions options;
    options.interrupt = &g_signal;  // SIGINT and SIGTERM stop a script too
    if (trusted_scene) {
        options.trusted = true;
        options.memory_limit = 0;
        options.instruction_limit = 0;
        options.time_limit = 0;
    }
    if (!time_limit.empty()) {
        const auto seconds = parse_finite(time_limit);
        if (!seconds || *seconds < 0 || *seconds > kMaxScriptTimeLimit) {
            bad_flag(
                "--script-time-limit", time_limit,
                fmt::format("a number of seconds from 0 (no limit) to {:g}", kMaxScriptTimeLimit));
        }
        options.time_limit = *seconds;
    }
    return options;
}

// x0,y0,x1,y1 as numbers; render settings check them against the resolution.
std::vector<double> parse_crop(const std::string& text) {
    std::vector<double> corners;
    std::string_view rest = text;
    for (int i = 0; i < 4; ++i) {
        const size_t comma = i < 3 ? rest.find(',') : rest.size();
        const auto value = comma == std::string_view::npos
                               ? std::nullopt
                               : parse_integer(rest.substr(0, comma), 0, kMaxResolution);
        if (!value) bad_flag("--crop", text, "x0,y0,x1,y1 in pixels, e.g. 64,32,128,96");
        corners.push_back(static_cast<double>(*value));
        rest = comma < rest.size() ? rest.substr(comma + 1) : std::string_view();
    }
    return corners;
}

std::optional<int> int_flag(const std::string& flag, const std::string& text, int min, int max) {
    if (text.empty()) return std::nullopt;
    const auto value = parse_integer(text, min, max);
    if (!value) bad_flag(flag, text, fmt::format("an integer from {} to {}", min, max));
    return static_cast<int>(*value);
}

Vec2i parse_resolution_flag(const std::string& text) {
    const auto res = glint::parse_resolution(text, kMaxResolution);
    if (!res) {
        bad_flag(
            "--res", text,
            fmt::format("WIDTHxHEIGHT with each side from 1 to {}, e.g. 512x512", kMaxResolution));
    }
    return Vec2i(res->first, res->second);
}

// The scene's settings with the flags' values written into its glint.render{...} table,
// each with the flag's name as its location, so that an error about a value names the
// flag that gave it and anything else names the scene's line.
RenderSettings settings_for(const SceneDesc& desc, const RenderOptions& options) {
    Params table = desc.render ? *desc.render : Params("render", "render settings");
    if (const auto spp = int_flag("--spp", options.spp, 1, INT_MAX))
        table.set("spp", static_cast<double>(*spp), "--spp");
    if (!options.resolution.empty()) {
        const Vec2i res = parse_resolution_flag(options.resolution);
        table.set("width", static_cast<double>(res.x), "--res");
        table.set("height", static_cast<double>(res.y), "--res");
    }
    if (!options.crop.empty()) table.set("crop", parse_crop(options.crop), "--crop");
    if (!options.integrator.empty()) table.set("integrator", options.integrator, "--integrator");
    if (!options.exposure.empty()) {
        const auto stops = parse_finite(options.exposure);
        if (!stops || std::abs(*stops) > 100.0)
            bad_flag("--exposure", options.exposure, "a number of stops from -100 to 100");
        table.set("exposure", *stops, "--exposure");
    }
    if (!options.tonemap.empty()) table.set("tonemap", options.tonemap, "--tonemap");
    if (options.aovs) table.set("aovs", true, "--aovs");
    if (options.denoise) table.set("denoise", true, "--denoise");
    if (!options.denoiser.empty()) table.set("denoiser", options.denoiser, "--denoise");
    if (!options.denoise_quality.empty())
        table.set("denoise_quality", options.denoise_quality, "--denoise-quality");
    if (options.no_mipmap) table.set("mipmapping", false, "--no-mipmap");
    if (const auto every = int_flag("--intermediate", options.intermediate, 0, INT_MAX))
        table.set("intermediate", static_cast<double>(*every), "--intermediate");
    if (!options.adaptive.empty()) table.set("adaptive", options.adaptive, "--adaptive");
    if (!options.debug.empty()) table.set("debug", options.debug, "--debug");
    if (const auto photons = int_flag("--photons", options.photons, 1, INT_MAX)) {
        table.set("photons", static_cast<double>(*photons), "--photons");
        table.set("caustic_photons", static_cast<double>(*photons), "--photons");
    }
    if (!options.outputs.empty()) table.set("output", options.outputs, "--output");
    RenderSettings settings = parse_render_settings(&table);
    // Not table values: the seed may exceed what a table's integer holds, threads is no
    // scene setting.
    if (const auto threads = int_flag("--threads", options.threads, 1, kMaxThreads))
        settings.threads = *threads;
    if (!options.seed.empty()) {
        const auto seed = parse_unsigned(options.seed, UINT64_MAX);
        if (!seed) bad_flag("--seed", options.seed, "an integer from 0 to 2^64 - 1");
        settings.seed = *seed;
    }
    if (settings.outputs.empty()) {
        settings.outputs = {std::filesystem::path(options.scene).stem().string() + ".exr"};
    }
    return settings;
}

// Samples the render will take: exact for uniform sampling, an upper bound when adaptive.
uint64_t expected_samples(const RenderSettings& settings) {
    const uint64_t pixels =
        static_cast<uint64_t>(settings.output_width()) * settings.output_height();
    if (settings.adaptive == "sobel")
        return pixels * (2 + static_cast<uint64_t>(settings.supersample * settings.supersample));
    if (settings.adaptive == "variance") {
        return pixels * static_cast<uint64_t>(settings.max_spp > 0
                                                  ? std::max(settings.max_spp, settings.spp)
                                                  : 8 * settings.spp);
    }
    return pixels * settings.spp;
}

void check_debug_views(const RenderSettings& settings) {
    const std::string& where = settings.where_of("debug");
    for (const std::string& view : settings.debug) {
        if (view == "edges" && settings.adaptive != "sobel")
            throw Error(fmt::format("{}: debug view 'edges' needs --adaptive sobel", where));
        if (view == "photons" && settings.integrator != "photon" &&
            settings.integrator != "whitted") {
            throw Error(fmt::format(
                "{}: debug view 'photons' needs --integrator photon (or whitted with caustics = "
                "true)",
                where));
        }
        if (view == "strategies" && settings.integrator != "bdpt")
            throw Error(fmt::format("{}: debug view 'strategies' needs --integrator bdpt", where));
        if (view != "edges" && view != "photons" && view != "strategies") {
            throw Error(fmt::format(
                "{}: unknown debug view '{}' (known: edges, photons, strategies)", where, view));
        }
    }
}

// Debug views (`--debug edges`, photons) go next to the first output as NAME.<view>.png;
// integrators' debug images (bdpt's strategies) as NAME.<name>.exr, in radiance.
std::filesystem::path debug_image_path(const RenderSettings& settings, const std::string& name,
                                       const std::string& extension = ".png") {
    std::filesystem::path path = settings.outputs.front();
    path.replace_extension("." + name + extension);
    return path;
}

// The denoised image of output NAME.EXT goes beside it as NAME.denoised.EXT.
std::string denoised_path(const std::string& output) {
    std::filesystem::path path = output;
    const std::string extension = path.extension().string();
    path.replace_extension(".denoised" + extension);
    return path.string();
}

// What the denoiser needs, checked before any work: an integrator that fills the film's
// halves, and two samples in every pixel's each half.
void check_denoise(const RenderSettings& settings, const Integrator& integrator) {
    if (!settings.denoise) return;
    const std::string& where = settings.where_of("denoise");
    if (!integrator.records_halves()) {
        throw Error(fmt::format(
            "{}: the denoiser needs an integrator that renders pixel by pixel (path, whitted, "
            "photon); '{}' adds light paths to the image, which carry no first-hit features "
            "and cannot be split into halves",
            where, settings.integrator));
    }
    if (settings.denoiser != "nlm") return;
    if (settings.adaptive == "sobel") {
        throw Error(
            fmt::format("{}: the denoiser cannot use --adaptive sobel (its flat pixels "
                        "get one sample, which cannot be split into two halves)",
                        where));
    }
    if (settings.spp < 2)
        throw Error(fmt::format("{}: the denoiser needs at least 2 samples per pixel", where));
}

void add_debug_images(const RenderSettings& settings, const RenderStats& stats, OutputBatch& batch,
                      std::vector<std::string>& written) {
    for (const NamedImage& named : stats.images) {
        const std::string path = debug_image_path(settings, named.name, ".exr").string();
        batch.add(path, named.image);
        written.push_back(path);
    }
    for (const std::string& view : settings.debug) {
        for (const ExtraChannel& channel : stats.channels) {
            if (channel.name != view + ".Y") continue;
            batch.add(
                debug_image_path(settings, view).string(),
                grey_image(settings.output_width(), settings.output_height(), channel.values));
        }
    }
}

int run_render(const RenderOptions& options) {
    const SceneDesc desc =
        load_scene(options.scene, loader_options(options.trusted_scene, options.script_time_limit));
    const RenderSettings settings = settings_for(desc, options);
    check_debug_views(settings);
    // Every output's directory is checked before the work: a bad path fails now, not
    // after an hour of rendering, and writes nothing.
    std::vector<std::string> targets = settings.outputs;
    for (const std::string& view : settings.debug)
        targets.push_back(debug_image_path(settings, view).string());
    if (settings.denoise) {
        for (const std::string& output : settings.outputs) targets.push_back(denoised_path(output));
    }
    try {
        OutputBatch::check_targets(targets);
    } catch (const Error& e) {
        // Name where the paths came from: a flag, or the scene's line.
        throw Error(fmt::format("{}: {}", settings.where_of("output"), e.what()));
    }
    // The denoisers read the AOVs, the non-local means filter also the film's two halves;
    // the outputs get the AOVs only when asked for.
    const bool film_aovs = settings.aovs || settings.denoise;
    const bool film_halves = settings.denoise && settings.denoiser == "nlm";
    check_memory(Film::memory_bytes(settings.width, settings.height, film_aovs, film_halves),
                 fmt::format("the film ({}x{}{})", settings.width, settings.height,
                             film_halves        ? " with AOVs and halves for the denoiser"
                             : settings.denoise ? " with AOVs for the denoiser"
                             : settings.aovs    ? " with AOVs"
                                                : ""));
    std::vector<std::string> warnings;
    auto integrator = make_integrator(settings, &warnings);
    check_denoise(settings, *integrator);
    check_denoiser_ready(settings);
    for (const std::string& warning : warnings) fmt::print(stderr, "warning: {}\n", warning);
    const auto scene = build_scene(desc, settings);
    for (const std::string& warning : scene->stats().warnings)
        fmt::print(stderr, "warning: {}\n", warning);
    throw_if_interrupted();

    const int threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Film film(settings.output_width(), settings.output_height(), film_aovs,
              settings.output_origin(), film_halves);
    Progress progress("rendering", expected_samples(settings), options.quiet);
    progress.set_cancel_flag(&g_signal);
    // Processor time of the render (all threads), besides its wall-clock time: a benchmark on
    // a busy machine compares methods by it (bench/bidirectional.sh, CLOCK=cpu).
    const std::clock_t cpu_start = std::clock();
    const RenderStats stats = integrator->render(*scene, film, progress);
    const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    throw_if_interrupted();
    progress.finish();

    // All or nothing: each output is written to a temporary and verified; only when all
    // are good are they renamed into place. The batch removes its temporaries on any
    // exception, an interruption included.
    Image image = final_image(film, stats);
    if (film_aovs && !settings.aovs)
        image = without_channels(image, {"albedo.", "normal.", "depth."});
    const WriteOptions write_options{settings.exposure, settings.tonemap};
    OutputBatch batch;
    for (const std::string& path : settings.outputs) {
        batch.add(path, image, write_options);
        throw_if_interrupted();
    }
    double denoise_seconds = 0.0;
    if (settings.denoise) {
        const auto start = std::chrono::steady_clock::now();
        Progress denoising(
            "denoising",
            static_cast<uint64_t>(denoise_steps(film.width(), film.height(), settings)),
            options.quiet, "tiles");
        denoising.set_cancel_flag(&g_signal);
        const Image denoised = denoise_film(film, settings, threads, denoising);
        denoising.finish();
        denoise_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        throw_if_interrupted();
        for (const std::string& path : settings.outputs) {
            batch.add(denoised_path(path), denoised, write_options);
            throw_if_interrupted();
        }
    }
    add_debug_images(settings, stats, batch, targets);
    {
        const SignalBlock block;
        throw_if_interrupted();
        batch.commit();
    }
    if (!options.quiet) {
        for (const std::string& note : stats.notes) fmt::print(stderr, "{}\n", note);
    }
    if (!options.quiet && settings.adaptive != "none") {
        fmt::print(stderr, "adaptive ({}): {:.2f} samples per pixel on average\n",
                   settings.adaptive,
                   static_cast<double>(stats.samples) /
                       (static_cast<double>(settings.output_width()) * settings.output_height()));
    }
    if (!options.quiet) {
        fmt::print(stderr,
                   "{}x{}, {} spp, {} threads: {:.2f} s, {:.3f} M samples/s, {:.2f} M rays/s\n",
                   settings.width, settings.height, settings.spp, threads, stats.seconds,
                   stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6);
        fmt::print(stderr, "{} samples and {} rays in all, {:.2f} s of processor time\n",
                   stats.samples, stats.rays, cpu_seconds);
        if (settings.denoise) fmt::print(stderr, "denoised in {:.2f} s\n", denoise_seconds);
        for (const std::string& path : targets) {
            if (std::filesystem::exists(path)) fmt::print(stderr, "wrote {}\n", path);
        }
    }
    if (film.non_finite_samples() > 0) {
        fmt::print(stderr, "warning: {} samples were not finite and were skipped\n",
                   film.non_finite_samples());
    }
    if (scene->accel().dropped_rays() > 0) {
        fmt::print(stderr, "warning: {} rays were not finite and were dropped\n",
                   scene->accel().dropped_rays());
    }
    return 0;
}

int run_info(const std::string& scene_path, const LoaderOptions& loader) {
    const SceneDesc desc = load_scene(scene_path, loader);
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    for (const std::string& warning : scene->stats().warnings)
        fmt::print(stderr, "warning: {}\n", warning);
    const SceneStats& s = scene->stats();
    fmt::print("scene:      {}\n", scene_path);
    fmt::print("shapes:     {}\n", s.shapes);
    fmt::print("triangles:  {}\n", s.triangles);
    fmt::print("lights:     {}\n", s.lights);
    fmt::print("groups:     {} ({} instances)\n", s.groups, s.instances);
    fmt::print("materials:  {}\n", desc.materials.size());
    // Memory of the geometry: glint's own arrays (positions, normals, uvs, indices and the
    // per-triangle frames) and Embree's (BVH and its copies of vertices and indices), per
    // triangle built (a group placed many times is built once).
    const double mib = 1.0 / (1024.0 * 1024.0);
    const double per_triangle =
        s.unique_triangles
            ? static_cast<double>(s.mesh_bytes + std::max<int64_t>(s.embree_bytes, 0)) /
                  static_cast<double>(s.unique_triangles)
            : 0.0;
    fmt::print(
        "memory:     {:.1f} MiB meshes + {:.1f} MiB Embree = {:.1f} bytes per triangle "
        "({} triangles built)\n",
        s.mesh_bytes * mib, s.embree_bytes * mib, per_triangle, s.unique_triangles);
    fmt::print("textures:   {}\n", desc.textures.size());
    if (scene->environment())
        fmt::print("environment: yes (lights the scene and is seen behind it)\n");
    if (s.bounds.is_empty()) {
        fmt::print("bounds:     empty\n");
    } else {
        fmt::print("bounds:     ({:g}, {:g}, {:g}) to ({:g}, {:g}, {:g})\n", s.bounds.min.x,
                   s.bounds.min.y, s.bounds.min.z, s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
    }
    fmt::print("render:     {}x{}, {} spp, integrator {}\n", settings.width, settings.height,
               settings.spp, settings.integrator);
    return 0;
}

int run_compare(const std::string& test_path, const std::string& reference_path,
                const std::string& threshold_text) {
    std::optional<double> threshold;
    if (!threshold_text.empty()) {
        threshold = parse_finite(threshold_text);
        if (!threshold || *threshold < 0.0)
            bad_flag("--threshold", threshold_text, "a finite number >= 0");
    }
    const CompareResult r = compare_images(read_image(test_path), read_image(reference_path));
    fmt::print("relative MSE: {:.6g}\n", r.rel_mse);
    fmt::print("RMSE:         {:.6g}\n", r.rmse);
    fmt::print("test mean:    ({:.6g}, {:.6g}, {:.6g})\n", r.test_mean[0], r.test_mean[1],
               r.test_mean[2]);
    fmt::print("ref mean:     ({:.6g}, {:.6g}, {:.6g})\n", r.ref_mean[0], r.ref_mean[1],
               r.ref_mean[2]);
    if (r.non_finite > 0) {
        fmt::print(stderr, "{} values are NaN or infinite; no threshold can pass\n", r.non_finite);
    }
    // Written so that NaN fails: NaN <= threshold is false.
    if (threshold && !(r.rel_mse <= *threshold)) {
        fmt::print(stderr, "relative MSE {:.6g} exceeds the threshold {:.6g}\n", r.rel_mse,
                   *threshold);
        return kExitInputError;
    }
    return 0;
}

// `glint view`: the render flags that make sense in a window, and the viewer's own.
struct ViewOptions {
    RenderOptions render;  // scene, spp (the target), res, threads, seed, integrator, exposure
    std::string tone_map = "clip";
    std::string frames;
    std::string screenshot;
    std::string orbit;
    std::string orbit_after;
    std::string reduced_scale;
    bool hide_panel = false;
};

constexpr int kDefaultViewSpp = 1024;

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
    options.interrupt = &g_signal;

    const SceneDesc desc =
        load_scene_file(view.render.scene,
                        loader_options(view.render.trusted_scene, view.render.script_time_limit));
    RenderOptions render = view.render;
    if (render.spp.empty()) render.spp = std::to_string(kDefaultViewSpp);
    const RenderSettings settings = settings_for(desc, render);
    options.exposure = settings.exposure;
    const int threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const int code = viewer::run_viewer(desc, settings, options);
    throw_if_interrupted();  // the window closed on SIGINT or SIGTERM
    return code;
#endif
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"glint: a physically based renderer driven by Lua scenes"};
    app.require_subcommand(1);
    app.set_version_flag("--version",
                         fmt::format("glint 0.1.0 (Embree {})", Accel::embree_version()));

    RenderOptions render;
    CLI::App* render_cmd = app.add_subcommand("render", "Render a scene to EXR and/or PNG");
    render_cmd
        ->add_option("scene", render.scene,
                     "Scene script (.lua) or model file (.obj, .ply, .gltf, .glb)")
        ->required();
    render_cmd->add_option("-o,--output", render.outputs, "Output image, .exr or .png (repeatable)")
        ->allow_extra_args(false);  // `-o a.png scene.lua`: the scene is not a second output
    render_cmd->add_option("--spp", render.spp, "Samples per pixel (1 to 2^31 - 1)");
    render_cmd->add_option("--res", render.resolution,
                           "Resolution WIDTHxHEIGHT, each side 1 to 65536");
    render_cmd->add_option("--threads", render.threads,
                           "Worker threads, 1 to 4096 (default: all cores)");
    render_cmd->add_option("--seed", render.seed, "Random seed, 0 to 2^64 - 1");
    render_cmd->add_option("--crop", render.crop,
                           "Render only pixels [x0, x1) x [y0, y1) of the image, given as "
                           "x0,y0,x1,y1; the output is that window");
    render_cmd->add_option("--integrator", render.integrator,
                           "Light transport algorithm, e.g. path");
    render_cmd->add_option("--exposure", render.exposure, "Exposure in stops for PNG output");
    render_cmd->add_option("--tonemap", render.tonemap,
                           "Tone curve of PNG output: clip (default), reinhard, filmic (ACES fit)");
    CLI::Option* denoise_option =
        render_cmd
            ->add_option("--denoise", render.denoiser,
                         "Also write each output denoised, as NAME.denoised.EXT (path, whitted "
                         "and photon integrators): by Open Image Denoise's trained network "
                         "(default; weights from scripts/install-deps.sh), or 'nlm' for glint's "
                         "own non-local means filter")
            ->expected(0, 1)
            ->check(CLI::IsMember({"network", "nlm"}));
    render_cmd
        ->add_option("--denoise-quality", render.denoise_quality,
                     "The network's size: fast, balanced (default), high")
        ->check(CLI::IsMember({"fast", "balanced", "high"}));
    render_cmd->add_flag("--aovs", render.aovs,
                         "Add albedo, normal and depth channels to EXR output");
    render_cmd->add_option(
        "--adaptive", render.adaptive,
        "Adaptive sampling: none, sobel (supersample edges), variance (stop converged pixels)");
    render_cmd->add_option("--photons", render.photons,
                           "Photons per pass (sppm) or per photon map (photon), 1 to 2^31 - 1");
    render_cmd
        ->add_option("--debug", render.debug,
                     "Also write a debug view: edges (with --adaptive sobel), photons (with "
                     "--integrator photon, or whitted with caustics = true), strategies (with "
                     "--integrator bdpt)")
        ->allow_extra_args(false);
    render_cmd->add_option("--intermediate", render.intermediate,
                           "sppm: also write the image every N passes (NAME.passNNNN.EXT)");
    render_cmd->add_flag("--no-mipmap", render.no_mipmap,
                         "Look image textures up in their full-resolution level only");
    render_cmd->add_flag("-q,--quiet", render.quiet, "No progress or summary on stderr");
    const char* trusted_help =
        "Run the scene script with Lua's full standard library (io, os, debug, package) and "
        "without memory, instruction or time limits: only for scenes you trust";
    render_cmd->add_flag("--trusted-scene", render.trusted_scene, trusted_help);
    const std::string time_limit_help = fmt::format(
        "Seconds the scene script may run (default {:g}; 0 = no limit); a script past it ends "
        "with an error naming its line",
        LoaderOptions{}.time_limit);
    render_cmd->add_option("--script-time-limit", render.script_time_limit, time_limit_help);

    std::string info_scene;
    CLI::App* info_cmd =
        app.add_subcommand("info", "Print counts of shapes, triangles, lights and bounds");
    info_cmd
        ->add_option("scene", info_scene,
                     "Scene script (.lua) or model file (.obj, .ply, .gltf, .glb)")
        ->required();
    bool info_trusted = false;
    info_cmd->add_flag("--trusted-scene", info_trusted, trusted_help);
    std::string info_time_limit;
    info_cmd->add_option("--script-time-limit", info_time_limit, time_limit_help);

    std::string test_image, reference_image;
    std::string threshold;
    CLI::App* compare_cmd = app.add_subcommand("compare", "Compare an image with a reference");
    compare_cmd->add_option("test", test_image, "Image to check (.exr)")->required();
    compare_cmd->add_option("reference", reference_image, "Converged reference (.exr)")->required();
    compare_cmd->add_option("--threshold", threshold,
                            "Exit with 1 when the relative MSE exceeds this (finite, >= 0)");

    ViewOptions view;
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
    view_cmd->add_flag("--hide-panel", view.hide_panel, "Start with the panel hidden (key H)");
    view_cmd->add_flag("--trusted-scene", view.render.trusted_scene, trusted_help);
    view_cmd->add_option("--script-time-limit", view.render.script_time_limit, time_limit_help);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kExitUsageError;
    }

    install_signal_handlers();
    try {
        if (render_cmd->parsed()) {
            render.denoise = denoise_option->count() > 0;
            return run_render(render);
        }
        if (info_cmd->parsed())
            return run_info(info_scene, loader_options(info_trusted, info_time_limit));
        if (compare_cmd->parsed()) return run_compare(test_image, reference_image, threshold);
        if (view_cmd->parsed()) return run_view(view);
    } catch (const CLI::ValidationError& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return kExitUsageError;
    } catch (const glint::Interrupted& e) {
        fmt::print(stderr, "glint: interrupted by {}; no output written\n",
                   e.signal() == SIGINT    ? "SIGINT"
                   : e.signal() == SIGTERM ? "SIGTERM"
                                           : "a signal");
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
