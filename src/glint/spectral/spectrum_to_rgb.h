#pragma once
// A spectrum integrated to the Rgb that stands for it in RGB mode. Both integrate at the 5 nm
// wavelengths of the CIE tables (360–830 nm).
#include <glint/core/rgb.h>

#include <array>
#include <functional>

namespace glint::spectral {

// The colour of an emitter with spectral radiance f(λ): Rec.709 of ∫ f x̄ȳz̄ dλ / ∫ ȳ dλ,
// so that a constant 1 has luminance 1.
Rgb emission_to_rgb(const std::function<double(double)>& f);

// The Rgb of a reflectance-like or unbounded quantity f(λ) (a reflectance, η, k): its colour
// under D65, divided channel by channel by D65's own, so that a constant c gives exactly
// (c, c, c).
Rgb quantity_to_rgb(const std::function<double(double)>& f);

// quantity_to_rgb as weights: rgb = Σ_i f(wavelength(i)) · per_sample[i] (what the uplift's
// fit evaluates thousands of times).
struct ReflectanceWeights {
    std::array<std::array<double, 3>, 95> per_sample{};
    static double wavelength(size_t i) { return 360.0 + 5.0 * static_cast<double>(i); }
};
const ReflectanceWeights& reflectance_weights();

}  // namespace glint::spectral
