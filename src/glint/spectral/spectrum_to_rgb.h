#pragma once
// A spectrum integrated to the Rgb that stands for it in RGB mode.
#include <glint/core/rgb.h>

#include <functional>

namespace glint::spectral {

// The colour of an emitter with spectral radiance f(λ): Rec.709 of ∫ f x̄ȳz̄ dλ / ∫ ȳ dλ,
// so that a constant 1 gives luminance 1.
Rgb emission_to_rgb(const std::function<double(double)>& f);

// The Rgb of a reflectance-like or unbounded quantity f(λ) (a reflectance, η, k): its colour
// under D65 divided by D65's, so that a constant c gives (c, c, c).
Rgb quantity_to_rgb(const std::function<double(double)>& f);

}  // namespace glint::spectral
