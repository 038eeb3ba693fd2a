#pragma once
// Partial renders: sample ranges of one render, written as the film's exact sums and added
// up again (`glint render --samples A:B`, `glint merge`, the MPI ranks). See docs/cluster.md.
#include <glint/film/film.h>
#include <glint/integrator/tile/tile_integrator.h>
#include <glint/render/render_job.h>

namespace glint {

/// The tile integrator that renders `samples` of `settings`' render; throws glint::Error
/// naming the setting in the way (an integrator that renders whole images, adaptive
/// sampling, the denoiser, debug views) or a range outside [0, spp).
TileIntegrator* partial_render_integrator(Integrator& integrator, const RenderSettings& settings,
                                          SampleRange samples);

/// `film`'s sums (Film::sums_image) with the attributes "samples" ("A:B"), "spp" and
/// "render" (the settings the parts of one render share).
Image partial_sums_image(const Film& film, const RenderSettings& settings, SampleRange samples);

/// Throws glint::Error unless every output is an EXR file (the sums need float channels).
void check_partial_outputs(const RenderSettings& settings);

}  // namespace glint
