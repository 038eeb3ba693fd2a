#pragma once
// The checks the pipeline makes before any work, each naming the setting (a flag or the
// scene's line) that is wrong.
#include <glint/scene/render_settings.h>

namespace glint {

/// Every `debug` view is one some integrator can write, the one chosen among them, with
/// what the view needs (edges: adaptive sobel).
void check_debug_views(const RenderSettings& settings);

/// The film (with AOVs and halves when the render needs them) fits the memory budget.
void check_film_memory(const RenderSettings& settings);

/// The checks a render makes of its settings before any work (debug views, the integrator
/// and its own settings, the denoiser's needs), on their own: the CLI runs them first so
/// that a flag's bad value is told apart (exit code 2). Throws glint::Error.
void check_render_settings(const RenderSettings& settings);

/// Whether the film records AOVs: asked for, or needed by the denoiser.
bool film_needs_aovs(const RenderSettings& settings);

}  // namespace glint
