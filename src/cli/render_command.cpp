#include "render_command.h"

#include "flags.h"
#include "signals.h"

#include <glint/render/distributed_render.h>
#include <glint/render/render_checks.h>
#include <glint/render/render_job.h>

#include <fmt/format.h>

#include <filesystem>
#include <tuple>

namespace glint::cli {

CLI::App* add_render_command(CLI::App& app, RenderOptions& render) {
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
    render_cmd->add_flag("--spectral", render.spectral,
                         "Spectral mode: each path carries four wavelengths (hero wavelength "
                         "sampling) instead of RGB; needed for dispersion");
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
    render_cmd->add_option("--samples", render.samples,
                           "Render only sample indices [A, B) of every pixel, given as A:B with "
                           "B <= spp, and write the film's exact sums to an EXR file for glint "
                           "merge (tile integrators; docs/cluster.md)");
    render_cmd->add_option("--intermediate", render.intermediate,
                           "sppm: also write the image every N passes (NAME.passNNNN.EXT)");
    render_cmd->add_flag("--no-mipmap", render.no_mipmap,
                         "Look image textures up in their full-resolution level only");
    render_cmd->add_flag("-q,--quiet", render.quiet, "No progress or summary on stderr");
    render_cmd->add_flag("--trusted-scene", render.trusted_scene, trusted_scene_help());
    render_cmd->add_option("--script-time-limit", render.script_time_limit,
                           script_time_limit_help());

    // `--denoise` alone asks for the default denoiser; its value, when given, names one.
    render_cmd->callback(
        [&render, denoise_option] { render.denoise = denoise_option->count() > 0; });
    return render_cmd;
}

namespace {

std::pair<SceneDesc, RenderSettings> load_and_check(const RenderOptions& options) {
    SceneDesc desc =
        load_scene(options.scene, loader_options(options.trusted_scene, options.script_time_limit));
    RenderSettings settings =
        with_flag_errors_as_usage_errors([&] { return settings_for(desc, options); });
    with_flag_errors_as_usage_errors([&] { check_render_settings(settings); });
    return {std::move(desc), std::move(settings)};
}

}  // namespace

int run_render(const RenderOptions& options, Cluster& cluster) {
    RenderControl control;
    control.quiet = options.quiet;
    control.cancel = &g_signal;
    RenderSettings settings;
    RenderReport report;
    if (cluster.size() > 1) {
        // This rank's part of an MPI job; rank 0 prints the summary, and the error when a
        // rank fails: the others exit with the same code, quietly.
        if (!options.samples.empty())
            bad_flag("--samples", options.samples, "no --samples under mpirun (ranks share them)");
        std::optional<RenderReport> distributed;
        try {
            distributed = render_distributed(
                cluster,
                [&] {
                    auto loaded = load_and_check(options);
                    settings = loaded.second;
                    return loaded;
                },
                control);
        } catch (const Error&) {
            if (cluster.rank() == 0) throw;
            return kExitInputError;
        }
        if (!distributed) return 0;
        report = std::move(*distributed);
    } else {
        const std::optional<SampleRange> samples = parse_samples_flag(options.samples);
        SceneDesc desc;
        std::tie(desc, settings) = load_and_check(options);
        report = render_to_files(desc, settings, control, samples);
    }
    const RenderedImage& render = report.render;
    const RenderStats& stats = render.stats;
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
                   settings.width, settings.height, settings.spp, render.threads, stats.seconds,
                   stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6);
        fmt::print(stderr, "{} samples and {} rays in all, {:.2f} s of processor time\n",
                   stats.samples, stats.rays, render.cpu_seconds);
        if (settings.denoise) fmt::print(stderr, "denoised in {:.2f} s\n", render.denoise_seconds);
        for (const std::string& path : report.targets) {
            if (std::filesystem::exists(path)) fmt::print(stderr, "wrote {}\n", path);
        }
    }
    if (!options.quiet && cluster.size() > 1) {
        fmt::print(stderr,
                   "cluster: {} ranks; rank 0 exchanged {} bytes in {:.3f} s of collectives\n",
                   cluster.size(), cluster.bytes_exchanged(), cluster.exchange_seconds());
    }
    if (render.non_finite_samples > 0) {
        fmt::print(stderr, "warning: {} samples were not finite and were skipped\n",
                   render.non_finite_samples);
    }
    if (render.dropped_rays > 0) {
        fmt::print(stderr, "warning: {} rays were not finite and were dropped\n",
                   render.dropped_rays);
    }
    return 0;
}

}  // namespace glint::cli
