#pragma once
// One render from a loaded scene to its output files: the checks made before any work,
// the integrator, the film, the denoiser and the all-or-nothing write.
#include <glint/integrator/render_stats.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene_desc.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint::cli {

/// What a finished render reports for the summary the command prints.
struct RenderReport {
    RenderStats stats;
    int threads = 0;
    double cpu_seconds = 0.0;      ///< processor time of the render, all threads
    double denoise_seconds = 0.0;  ///< 0 without the denoiser
    /// Every file the run may have written: outputs, denoised outputs, debug images.
    std::vector<std::string> targets;
    uint64_t non_finite_samples = 0;
    uint64_t dropped_rays = 0;
};

/// Renders `desc` with `settings` and writes every output, or none (throws glint::Error,
/// or Interrupted after a signal). Warnings are printed to stderr before the render starts;
/// `quiet` silences the progress line.
RenderReport render_to_files(const SceneDesc& desc, const RenderSettings& settings, bool quiet);

/// The checks render_to_files() makes of the settings before any work (debug views, the
/// integrator and its own settings, the denoiser's needs), on their own: the CLI runs them
/// first so that a flag's bad value is told apart (exit code 2). Throws glint::Error.
void check_render_settings(const RenderSettings& settings);

}  // namespace glint::cli
