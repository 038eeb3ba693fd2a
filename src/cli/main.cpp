// The `glint` command: render, info and compare. The only place that catches glint::Error.
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/film/image_io.h>
#include <glint/geometry/accel.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>

namespace {

using namespace glint;

constexpr int kExitInputError = 1;
constexpr int kExitUsageError = 2;

struct RenderOptions {
    std::string scene;
    std::vector<std::string> outputs;
    std::optional<int> spp;
    std::string resolution;
    std::string crop;
    std::optional<int> threads;
    std::optional<uint64_t> seed;
    std::string integrator;
    std::optional<float> exposure;
    std::string adaptive;
    std::optional<int> photons;
    bool no_mipmap = false;
    std::optional<int> intermediate;
    std::vector<std::string> debug;
    bool aovs = false;
    bool quiet = false;
    bool trusted_scene = false;
};

// A scene runs sandboxed with bounded memory and instructions unless the user vouches for it.
LoaderOptions loader_options(bool trusted_scene) {
    LoaderOptions options;
    if (trusted_scene) {
        options.trusted = true;
        options.memory_limit = 0;
        options.instruction_limit = 0;
    }
    return options;
}

Vec2i parse_resolution(const std::string& text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
        w < 1 || h < 1) {
        throw CLI::ValidationError("--res",
                                   fmt::format("'{}' is not WIDTHxHEIGHT, e.g. 512x512", text));
    }
    return Vec2i(w, h);
}

// x0,y0,x1,y1 as numbers; render settings check them against the resolution.
std::vector<double> parse_crop(const std::string& text) {
    int c[4];
    char extra = 0;
    if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &c[0], &c[1], &c[2], &c[3], &extra) != 4) {
        throw CLI::ValidationError("--crop",
                                   fmt::format("'{}' is not x0,y0,x1,y1, e.g. 64,32,128,96", text));
    }
    return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2]),
            static_cast<double>(c[3])};
}

// `where` names the flag or the scene line that gave the value.
void check_output_path(const std::string& path, const std::string& where) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext != ".exr" && ext != ".png") {
        throw Error(
            fmt::format("{}: output '{}': unsupported format (use .exr or .png)", where, path));
    }
}

// The scene's settings with the flags' values written into its glint.render{...} table,
// each with the flag's name as its location, so that an error about a value names the
// flag that gave it and anything else names the scene's line.
RenderSettings settings_for(const SceneDesc& desc, const RenderOptions& options) {
    Params table = desc.render ? *desc.render : Params("render", "render settings");
    if (options.spp) table.set("spp", static_cast<double>(*options.spp), "--spp");
    if (!options.resolution.empty()) {
        const Vec2i res = parse_resolution(options.resolution);
        table.set("width", static_cast<double>(res.x), "--res");
        table.set("height", static_cast<double>(res.y), "--res");
    }
    if (!options.crop.empty()) table.set("crop", parse_crop(options.crop), "--crop");
    if (!options.integrator.empty()) table.set("integrator", options.integrator, "--integrator");
    if (options.exposure)
        table.set("exposure", static_cast<double>(*options.exposure), "--exposure");
    if (options.aovs) table.set("aovs", true, "--aovs");
    if (options.no_mipmap) table.set("mipmapping", false, "--no-mipmap");
    if (options.intermediate)
        table.set("intermediate", static_cast<double>(*options.intermediate), "--intermediate");
    if (!options.adaptive.empty()) table.set("adaptive", options.adaptive, "--adaptive");
    if (!options.debug.empty()) table.set("debug", options.debug, "--debug");
    if (options.photons) {
        table.set("photons", static_cast<double>(*options.photons), "--photons");
        table.set("caustic_photons", static_cast<double>(*options.photons), "--photons");
    }
    if (!options.outputs.empty()) table.set("output", options.outputs, "--output");
    RenderSettings settings = parse_render_settings(&table);
    // Not table values: the seed may exceed what a table's integer holds, threads is no
    // scene setting.
    if (options.threads) settings.threads = *options.threads;
    if (options.seed) settings.seed = *options.seed;
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

// `--debug edges` writes the edge mask next to the first output, as NAME.edges.png;
// integrators' debug images (bdpt's strategies) go there as NAME.<name>.exr, in radiance.
void write_debug_images(const RenderSettings& settings, const RenderStats& stats) {
    for (const NamedImage& named : stats.images) {
        std::filesystem::path path = settings.outputs.front();
        path.replace_extension("." + named.name + ".exr");
        write_image(path.string(), named.image);
        fmt::print(stderr, "wrote {}\n", path.string());
    }
    for (const std::string& view : settings.debug) {
        for (const ExtraChannel& channel : stats.channels) {
            if (channel.name != view + ".Y") continue;
            std::filesystem::path path = settings.outputs.front();
            path.replace_extension("." + view + ".png");
            write_image(path.string(), grey_image(settings.output_width(), settings.output_height(),
                                                  channel.values));
            fmt::print(stderr, "wrote {}\n", path.string());
        }
    }
}

int run_render(const RenderOptions& options) {
    const SceneDesc desc = load_scene_file(options.scene, loader_options(options.trusted_scene));
    const RenderSettings settings = settings_for(desc, options);
    for (const std::string& path : settings.outputs)
        check_output_path(path, settings.where_of("output"));
    check_debug_views(settings);
    std::vector<std::string> warnings;
    auto integrator = make_integrator(settings, &warnings);
    for (const std::string& warning : warnings) fmt::print(stderr, "warning: {}\n", warning);
    const auto scene = build_scene(desc, settings);

    const int threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Film film(settings.output_width(), settings.output_height(), settings.aovs,
              settings.output_origin());
    Progress progress("rendering", expected_samples(settings), options.quiet);
    const RenderStats stats = integrator->render(*scene, film, progress);
    progress.finish();

    const Image image = final_image(film, stats);
    for (const std::string& path : settings.outputs)
        write_image(path, image, WriteOptions{settings.exposure});
    write_debug_images(settings, stats);
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
        fmt::print(stderr, "{} samples and {} rays in all\n", stats.samples, stats.rays);
        for (const std::string& path : settings.outputs) fmt::print(stderr, "wrote {}\n", path);
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

int run_info(const std::string& scene_path, bool trusted_scene) {
    const SceneDesc desc = load_scene_file(scene_path, loader_options(trusted_scene));
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    const SceneStats& s = scene->stats();
    fmt::print("scene:      {}\n", scene_path);
    fmt::print("shapes:     {}\n", s.shapes);
    fmt::print("triangles:  {}\n", s.triangles);
    fmt::print("lights:     {}\n", s.lights);
    fmt::print("groups:     {} ({} instances)\n", s.groups, s.instances);
    fmt::print("materials:  {}\n", desc.materials.size());
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
                std::optional<double> threshold) {
    const CompareResult r = compare_images(read_image(test_path), read_image(reference_path));
    fmt::print("relative MSE: {:.6g}\n", r.rel_mse);
    fmt::print("RMSE:         {:.6g}\n", r.rmse);
    fmt::print("test mean:    ({:.6g}, {:.6g}, {:.6g})\n", r.test_mean[0], r.test_mean[1],
               r.test_mean[2]);
    fmt::print("ref mean:     ({:.6g}, {:.6g}, {:.6g})\n", r.ref_mean[0], r.ref_mean[1],
               r.ref_mean[2]);
    if (threshold && r.rel_mse > *threshold) {
        fmt::print(stderr, "relative MSE {:.6g} exceeds the threshold {:.6g}\n", r.rel_mse,
                   *threshold);
        return kExitInputError;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"glint: a physically based renderer driven by Lua scenes"};
    app.require_subcommand(1);
    app.set_version_flag("--version",
                         fmt::format("glint 0.1.0 (Embree {})", Accel::embree_version()));

    RenderOptions render;
    CLI::App* render_cmd = app.add_subcommand("render", "Render a scene to EXR and/or PNG");
    render_cmd->add_option("scene", render.scene, "Scene script (.lua)")->required();
    render_cmd->add_option("-o,--output", render.outputs, "Output image, .exr or .png (repeatable)")
        ->allow_extra_args(false);  // `-o a.png scene.lua`: the scene is not a second output
    render_cmd->add_option("--spp", render.spp, "Samples per pixel")->check(CLI::PositiveNumber);
    render_cmd->add_option("--res", render.resolution, "Resolution WIDTHxHEIGHT");
    render_cmd->add_option("--crop", render.crop,
                           "Render only pixels [x0, x1) x [y0, y1) of the image, given as "
                           "x0,y0,x1,y1; the output is that window");
    render_cmd->add_option("--threads", render.threads, "Worker threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    render_cmd->add_option("--seed", render.seed, "Random seed");
    render_cmd->add_option("--integrator", render.integrator,
                           "Light transport algorithm, e.g. path");
    render_cmd->add_option("--exposure", render.exposure, "Exposure in stops for PNG output");
    render_cmd->add_flag("--aovs", render.aovs,
                         "Add albedo, normal and depth channels to EXR output");
    render_cmd->add_option(
        "--adaptive", render.adaptive,
        "Adaptive sampling: none, sobel (supersample edges), variance (stop converged pixels)");
    render_cmd
        ->add_option("--photons", render.photons,
                     "Photons per pass (sppm) or per photon map (photon)")
        ->check(CLI::PositiveNumber);
    render_cmd
        ->add_option("--debug", render.debug,
                     "Also write a debug view: edges (with --adaptive sobel), photons (with "
                     "--integrator photon, or whitted with caustics = true), strategies (with "
                     "--integrator bdpt)")
        ->allow_extra_args(false);
    render_cmd
        ->add_option("--intermediate", render.intermediate,
                     "sppm: also write the image every N passes (NAME.passNNNN.EXT)")
        ->check(CLI::NonNegativeNumber);
    render_cmd->add_flag("--no-mipmap", render.no_mipmap,
                         "Look image textures up in their full-resolution level only");
    render_cmd->add_flag("-q,--quiet", render.quiet, "No progress or summary on stderr");
    const char* trusted_help =
        "Run the scene script with Lua's full standard library (io, os, debug, package) and "
        "without memory or instruction limits: only for scenes you trust";
    render_cmd->add_flag("--trusted-scene", render.trusted_scene, trusted_help);

    std::string info_scene;
    CLI::App* info_cmd =
        app.add_subcommand("info", "Print counts of shapes, triangles, lights and bounds");
    info_cmd->add_option("scene", info_scene, "Scene script (.lua)")->required();
    bool info_trusted = false;
    info_cmd->add_flag("--trusted-scene", info_trusted, trusted_help);

    std::string test_image, reference_image;
    std::optional<double> threshold;
    CLI::App* compare_cmd = app.add_subcommand("compare", "Compare an image with a reference");
    compare_cmd->add_option("test", test_image, "Image to check (.exr)")->required();
    compare_cmd->add_option("reference", reference_image, "Converged reference (.exr)")->required();
    compare_cmd->add_option("--threshold", threshold,
                            "Exit with 1 when the relative MSE exceeds this");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kExitUsageError;
    }

    try {
        if (render_cmd->parsed()) return run_render(render);
        if (info_cmd->parsed()) return run_info(info_scene, info_trusted);
        if (compare_cmd->parsed()) return run_compare(test_image, reference_image, threshold);
    } catch (const CLI::ValidationError& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return kExitUsageError;
    } catch (const glint::Error& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return kExitInputError;
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint: internal error: {}\n", e.what());
        return kExitInputError;
    }
    return kExitUsageError;
}
