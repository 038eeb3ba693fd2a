#pragma once
// The denoising step of a render: the denoiser a render's settings choose (`denoise`,
// `denoiser`, `denoise_quality`, `denoise_clean_aux`), run on its finished film. Used by
// `glint render --denoise` and by the viewer.
#include <glint/denoise/network_denoiser.h>
#include <glint/film/image.h>
#include <glint/scene/render_settings.h>

namespace glint {

class Film;
class Progress;

/// The network denoiser's settings for a render on `threads` threads.
NetworkDenoiseSettings network_denoise_settings(const RenderSettings& settings, int threads);

/// Throws glint::Error, naming where `denoise` was set, when the chosen denoiser cannot run:
/// the network's weights are not installed. Call it before rendering.
void check_denoiser_ready(const RenderSettings& settings);

/// Units of work denoise_film() reports to its Progress (tiles of network passes, or 1 for
/// the non-local means filter).
int denoise_steps(int width, int height, const RenderSettings& settings);

/// The film's image denoised (R, G, B); the network needs a film with AOVs, the non-local
/// means filter one with AOVs and halves. Advances `progress` by denoise_steps() in all.
Image denoise_film(const Film& film, const RenderSettings& settings, int threads,
                   Progress& progress);

}  // namespace glint
