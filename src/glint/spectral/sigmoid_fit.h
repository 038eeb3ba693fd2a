#pragma once
// glint's own fit of Jakob & Hanika's sigmoid polynomial to an RGB colour: Gauss–Newton with
// Levenberg–Marquardt damping over the three coefficients, matching the spectrum's colour
// under D65 (quantity_to_rgb) to the target. Used by the build-time table generator and tests.
#include <array>

namespace glint::spectral {

// Coefficients of S(c0 t² + c1 t + c2) in the normalised wavelength t = (λ − 360) / 470, where
// the fit is well conditioned.
using NormalisedCoefficients = std::array<double, 3>;

struct SigmoidFit {
    NormalisedCoefficients coefficients{};
    double residual = 0.0;  // the largest channel error of the fitted colour
};

// Fits the colour `target` (linear Rec.709, each channel in [0, 1]) from `start`, until every
// channel is within `tolerance` or after `max_steps` accepted Gauss–Newton steps.
SigmoidFit fit_sigmoid_polynomial(const std::array<double, 3>& target,
                                  const NormalisedCoefficients& start, double tolerance = 1e-9,
                                  int max_steps = 200);

// The same polynomial with λ in nm: c0 λ² + c1 λ + c2.
std::array<double, 3> to_nm_coefficients(const NormalisedCoefficients& c);

// S(x) = ½ + x / (2 √(1 + x²)), 0 or 1 for infinite x.
double sigmoid(double x);

}  // namespace glint::spectral
