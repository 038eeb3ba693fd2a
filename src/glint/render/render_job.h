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

/// Sample indices [first, end) of every pixel: a partial render (`glint render --samples`),
/// or one MPI rank's share. The sampler is made for settings.spp samples, end <= spp.
struct SampleRange {
    int first = 0;
    int end = 0;
};

/// Renders `desc` with `settings` (settings.threads workers, 0 = all cores) after checking
/// the film's memory, the integrator and the denoiser's needs. Throws glint::Error, or
/// Interrupted when control.cancel is set.
/// With `samples`, renders only that range (tile integrators, uniform sampling, no
/// denoiser) and the image is the film's exact sums (Film::sums_image) with the attributes
/// merge_partial_renders() checks: "samples" (A:B), "spp" and "render" (the settings that
/// must agree).
RenderedImage render_image(const SceneDesc& desc, const RenderSettings& settings,
                           const RenderControl& control = {},
                           std::optional<SampleRange> samples = std::nullopt);

/// The image of the partial renders `parts` (render_image with a SampleRange) added up:
/// exactly what one render of all their samples gives. `names` (one per part, for messages)
/// name a part that does not belong. Throws glint::Error for parts of different renders or
/// overlapping ranges; when the ranges leave gaps in [0, spp) a line saying so is appended to
/// `warnings`.
Image merge_partial_renders(const std::vector<Image>& parts, const std::vector<std::string>& names,
                            std::vector<std::string>& warnings);

/// Checks the debug views and every output's path first, then render_image(), then writes
/// every output (settings.outputs, the denoised images, the debug images) or none.
/// With `samples`, writes the partial render's sums to every output, each of which must be
/// an EXR file.
RenderReport render_to_files(const SceneDesc& desc, const RenderSettings& settings,
                             const RenderControl& control = {},
                             std::optional<SampleRange> samples = std::nullopt);

}  // namespace glint
