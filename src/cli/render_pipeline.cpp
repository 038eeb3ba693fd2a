#include "render_pipeline.h"

#include "signals.h"

#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/progress.h>
#include <glint/film/denoise.h>
#include <glint/film/output_batch.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/build.h>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

namespace glint::cli {

namespace {

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
            "photon); '{}' adds light paths to the image, which it cannot split into halves",
            where, settings.integrator));
    }
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

}  // namespace

void check_render_settings(const RenderSettings& settings) {
    check_debug_views(settings);
    check_denoise(settings, *make_integrator(settings, nullptr));
}

RenderReport render_to_files(const SceneDesc& desc, const RenderSettings& settings, bool quiet) {
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
    // The denoiser reads the AOVs and the film's two halves; the outputs get the AOVs
    // only when asked for.
    const bool film_aovs = settings.aovs || settings.denoise;
    check_memory(Film::memory_bytes(settings.width, settings.height, film_aovs, settings.denoise),
                 fmt::format("the film ({}x{}{})", settings.width, settings.height,
                             settings.denoise ? " with AOVs and halves for the denoiser"
                             : settings.aovs  ? " with AOVs"
                                              : ""));
    std::vector<std::string> warnings;
    auto integrator = make_integrator(settings, &warnings);
    check_denoise(settings, *integrator);
    for (const std::string& warning : warnings) fmt::print(stderr, "warning: {}\n", warning);
    const auto scene = build_scene(desc, settings);
    for (const std::string& warning : scene->stats().warnings)
        fmt::print(stderr, "warning: {}\n", warning);
    throw_if_interrupted();

    const int threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Film film(settings.output_width(), settings.output_height(), film_aovs,
              settings.output_origin(), settings.denoise);
    Progress progress("rendering", expected_samples(settings), quiet);
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
        const Image denoised = denoise(film);
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
    RenderReport report;
    report.stats = stats;
    report.threads = threads;
    report.cpu_seconds = cpu_seconds;
    report.denoise_seconds = denoise_seconds;
    report.targets = std::move(targets);
    report.non_finite_samples = film.non_finite_samples();
    report.dropped_rays = scene->accel().dropped_rays();
    return report;
}

}  // namespace glint::cli
