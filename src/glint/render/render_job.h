#pragma once
// The render pipeline as a library call: the checks made before any work, the integrator,
// the film, the render, the denoiser and the all-or-nothing write of every output. Used by
// the `glint` command, the viewer and the tests.
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/render_stats.h>
#include <glint/render/render_control.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene_desc.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// A render held in memory.
struct RenderedImage {
    /// The film's image with the integrator's extra channels; AOVs only when asked for.
    Image image;
    std::optional<Image> denoised;  ///< with `denoise` on
    RenderStats stats;
    int threads = 0;               ///< worker threads used
    double cpu_seconds = 0.0;      ///< processor time of the render, all threads
    double denoise_seconds = 0.0;  ///< 0 without the denoiser
    uint64_t non_finite_samples = 0;
    uint64_t dropped_rays = 0;
};

/// What render_to_files() did, for a summary.
struct RenderReport {
    RenderedImage render;
    /// Every file the run may have written: outputs, denoised outputs, debug images.
    std::vector<std::string> targets;
};

/// One file of a set written together.
struct OutputFile {
    std::string path;
    const Image* image = nullptr;
    WriteOptions options;
};

/// Writes every file or none (film/output_batch.h): each to a verified temporary, then all
/// renamed into place with SIGINT and SIGTERM held back. Throws glint::Error naming the
/// path, or Interrupted when control.cancel is set before the renames.
void write_outputs(const std::vector<OutputFile>& files, const RenderControl& control = {});

/// Renders `desc` with `settings` (settings.threads workers, 0 = all cores) after checking
/// the film's memory, the integrator and the denoiser's needs. Throws glint::Error, or
/// Interrupted when control.cancel is set.
RenderedImage render_image(const SceneDesc& desc, const RenderSettings& settings,
                           const RenderControl& control = {});

/// Checks the debug views and every output's path first, then render_image(), then writes
/// every output (settings.outputs, the denoised images, the debug images) or none.
RenderReport render_to_files(const SceneDesc& desc, const RenderSettings& settings,
                             const RenderControl& control = {});

}  // namespace glint
