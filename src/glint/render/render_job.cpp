#include <glint/camera/camera_attributes.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/denoise/film_denoiser.h>
#include <glint/film/film.h>
#include <glint/film/output_batch.h>
#include <glint/geometry/accel.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/tile/tile_integrator.h>
#include <glint/integrator/transport/medium_emitters.h>
#include <glint/render/denoise_step.h>
#include <glint/render/partial_render.h>
#include <glint/render/render_checks.h>
#include <glint/render/render_job.h>
#include <glint/render/signal_block.h>
#include <glint/scene/build.h>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

namespace glint {

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

// Every output's path, known before the work (integrators' own debug images are added
// when they come).
std::vector<std::string> output_targets(const RenderSettings& settings) {
    std::vector<std::string> targets = settings.outputs;
    for (const std::string& view : settings.debug)
        targets.push_back(debug_image_path(settings, view).string());
    if (settings.denoise) {
        for (const std::string& output : settings.outputs) targets.push_back(denoised_path(output));
    }
    return targets;
}

// The integrator's debug images (in radiance) and the debug views' grey images, kept in
// `views` so that the files can point at them.
void add_debug_images(const RenderSettings& settings, const RenderStats& stats,
                      std::vector<Image>& views, std::vector<OutputFile>& files,
                      std::vector<std::string>& written) {
    for (const NamedImage& named : stats.images) {
        const std::string path = debug_image_path(settings, named.name, ".exr").string();
        files.push_back({path, &named.image, {}});
        written.push_back(path);
    }
    std::vector<std::string> view_paths;
    for (const std::string& view : settings.debug) {
        for (const ExtraChannel& channel : stats.channels) {
            if (channel.name != view + ".Y") continue;
            views.push_back(
                grey_image(settings.output_width(), settings.output_height(), channel.values));
            view_paths.push_back(debug_image_path(settings, view).string());
        }
    }
    for (size_t i = 0; i < views.size(); ++i) files.push_back({view_paths[i], &views[i], {}});
}

// A moving scene needs an integrator that carries each path's time.
void check_motion(const Scene& scene, const RenderSettings& settings,
                  const IntegratorCapabilities& capabilities) {
    if (!scene.has_motion() || capabilities.motion_blur) return;
    throw Error(
        fmt::format("{}: the '{}' integrator does not render moving scenes yet (its "
                    "radiosity solution is made for one time); use path, whitted, photon, "
                    "sppm, light, bdpt, vcm, mlt or preview",
                    settings.where_of("integrator"), settings.integrator));
}

// Only some integrators sample scattering in media, and fewer collect their emission; the
// others would show the scene as if its fog (or its glow) were not there, so
// say so.
void warn_if_media_ignored(const Scene& scene, const RenderSettings& settings,
                           const IntegratorCapabilities& capabilities,
                           const RenderControl& control) {
    const auto any_medium = [&](auto&& predicate) {
        return std::any_of(scene.media().begin(), scene.media().end(),
                           [&](const std::unique_ptr<Medium>& m) { return predicate(*m); });
    };
    if (!capabilities.scattering_media &&
        any_medium([](const Medium& m) { return m.scatters() || m.emits(); })) {
        warn(control,
             fmt::format("{}: the '{}' integrator ignores participating media that "
                         "scatter or emit (glint.medium); 'volpath', 'light', 'bdpt', 'vcm', 'mlt' "
                         "and 'preview' render them",
                         settings.where_of("integrator"), settings.integrator));
    } else if (!capabilities.emitting_media &&
               any_medium([](const Medium& m) { return m.emits(); })) {
        warn(control, fmt::format("{}: the '{}' integrator ignores the light media emit "
                                  "(glint.medium{{ emission = ... }}); 'volpath', 'light', "
                                  "'bdpt', 'vcm', 'mlt' and 'preview' render it",
                                  settings.where_of("integrator"), settings.integrator));
    } else if (capabilities.glow_needs_shape && !MediumEmitters(scene).unbounded().empty()) {
        warn(control, fmt::format("{}: the '{}' integrator ignores the light of a glowing medium "
                                  "that fills no shape (the camera's medium): its paths start "
                                  "only in media inside shapes; 'volpath', 'bdpt', 'vcm', 'mlt' "
                                  "and 'preview' render it",
                                  settings.where_of("integrator"), settings.integrator));
    }
}

// Integrators without wavelengths render in RGB; the user asked for spectra, so say so.
void warn_if_not_spectral(const RenderSettings& settings,
                          const IntegratorCapabilities& capabilities,
                          const RenderControl& control) {
    if (!settings.spectral || capabilities.spectral) return;
    warn(control, fmt::format("{}: the '{}' integrator renders in RGB; spectral = true has no "
                              "effect on it (docs/spectral.md lists the spectral integrators)",
                              settings.where_of("spectral"), settings.integrator));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RenderedImage render_image(const SceneDesc& desc, const RenderSettings& settings,
                           const RenderControl& control, std::optional<SampleRange> samples) {
    check_film_memory(settings);
    std::vector<std::string> warnings;
    auto integrator = make_integrator(settings, &warnings);
    TileIntegrator* partial =
        samples ? partial_render_integrator(*integrator, settings, *samples) : nullptr;
    if (control.cluster && !integrator->share_work(*control.cluster)) {
        throw Error(fmt::format("{}: integrator '{}' cannot share its work among MPI ranks",
                                settings.where_of("integrator"), settings.integrator));
    }
    check_denoise(settings, integrator->capabilities());
    if (settings.denoise) check_denoiser_ready(settings);
    for (const std::string& warning : warnings) warn(control, warning);
    const auto scene = build_scene(desc, settings);
    check_motion(*scene, settings, integrator->capabilities());
    warn_if_not_spectral(settings, integrator->capabilities(), control);
    warn_if_media_ignored(*scene, settings, integrator->capabilities(), control);
    for (const std::string& warning : scene->stats().warnings) warn(control, warning);
    throw_if_cancelled(control);

    RenderedImage result;
    result.threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, result.threads);
    // The denoiser reads the AOVs and the film's two halves; the image gets the AOVs only
    // when asked for.
    const bool film_aovs = film_needs_aovs(settings);
    Film film(settings.output_width(), settings.output_height(), film_aovs,
              settings.output_origin(), film_needs_halves(settings));
    const uint64_t work = partial ? static_cast<uint64_t>(film.width()) * film.height() *
                                        (samples->end - samples->first)
                                  : expected_samples(settings);
    Progress own_progress("rendering", work, control.quiet || control.progress);
    Progress& progress = control.progress ? *control.progress : own_progress;
    progress.set_cancel_flag(control.cancel);
    // Processor time of the render (all threads), besides its wall-clock time: a benchmark on
    // a busy machine compares methods by it (bench/bidirectional.sh, CLOCK=cpu).
    const std::clock_t cpu_start = std::clock();
    result.stats =
        partial ? partial->render_samples(*scene, film, samples->first, samples->end, progress)
                : integrator->render(*scene, film, progress);
    result.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    throw_if_cancelled(control);
    own_progress.finish();

    result.image =
        partial ? partial_sums_image(film, settings, *samples) : final_image(film, result.stats);
    if (film_aovs && !settings.aovs)
        result.image = without_channels(result.image, {"albedo.", "normal.", "depth."});
    // An image with depth records its camera, so that `glint warp` can show it from a
    // nearby viewpoint without the scene.
    if (settings.aovs && !partial) {
        for (auto& attribute : camera_attributes(desc.camera ? &*desc.camera : nullptr,
                                                 Vec2i(settings.width, settings.height)))
            result.image.attributes.push_back(std::move(attribute));
    }
    if (settings.denoise) {
        const auto start = std::chrono::steady_clock::now();
        result.denoised = denoise_film(film, settings, control);
        result.denoise_seconds = seconds_since(start);
        throw_if_cancelled(control);
    }
    result.non_finite_samples = film.non_finite_samples();
    result.dropped_rays = scene->accel().dropped_rays();
    return result;
}

RenderReport render_to_files(const SceneDesc& desc, const RenderSettings& settings,
                             const RenderControl& control, std::optional<SampleRange> samples) {
    check_debug_views(settings);
    if (samples) check_partial_outputs(settings);
    // Every output's directory is checked before the work: a bad path fails now, not
    // after an hour of rendering, and writes nothing.
    RenderReport report;
    report.targets = output_targets(settings);
    try {
        OutputBatch::check_targets(report.targets);
    } catch (const Error& e) {
        // Name where the paths came from: a flag, or the scene's line.
        throw Error(fmt::format("{}: {}", settings.where_of("output"), e.what()));
    }
    report.render = render_image(desc, settings, control, samples);
    const RenderedImage& render = report.render;

    const WriteOptions write_options{settings.exposure, settings.tonemap};
    std::vector<OutputFile> files;
    for (const std::string& path : settings.outputs)
        files.push_back({path, &render.image, write_options});
    if (render.denoised) {
        for (const std::string& path : settings.outputs)
            files.push_back({denoised_path(path), &*render.denoised, write_options});
    }
    std::vector<Image> views;
    add_debug_images(settings, render.stats, views, files, report.targets);
    write_outputs(files, control);
    return report;
}

void write_outputs(const std::vector<OutputFile>& files, const RenderControl& control) {
    // All or nothing: each output is written to a temporary and verified; only when all
    // are good are they renamed into place. The batch removes its temporaries on any
    // exception, an interruption included.
    OutputBatch batch;
    for (const OutputFile& file : files) {
        batch.add(file.path, *file.image, file.options);
        throw_if_cancelled(control);
    }
    const SignalBlock block;
    throw_if_cancelled(control);
    batch.commit();
}

}  // namespace glint
