#pragma once
// The pipeline's one place for the denoiser: what it needs before any work, what the film
// must record for it, and the call itself.
#include <glint/film/film.h>
#include <glint/film/image.h>
#include <glint/integrator/integrator.h>
#include <glint/render/render_control.h>
#include <glint/scene/render_settings.h>

namespace glint {

/// Throws glint::Error (naming the `denoise` setting) when `settings.denoise` asks for
/// more than the integrator and the settings give (first-hit features; for the non-local
/// means filter also the film's halves, two samples in each). Whether the network's
/// weights are installed is check_denoiser_ready()'s question (denoise/film_denoiser.h).
void check_denoise(const RenderSettings& settings, const IntegratorCapabilities& capabilities);

/// Whether the film must keep its two halves of each pixel's samples.
bool film_needs_halves(const RenderSettings& settings);

/// The denoised image of a rendered film, by the denoiser the settings choose, with a
/// "denoising" progress line.
Image denoise_film(const Film& film, const RenderSettings& settings, const RenderControl& control);

}  // namespace glint
