#pragma once
// The CIE 1931 2° standard observer and the colour spaces built on it.
#include <glint/core/rgb.h>

namespace glint::spectral {

// The visible range the tables cover and spectral rendering samples.
inline constexpr float kLambdaMin = 360.0f;
inline constexpr float kLambdaMax = 830.0f;

struct Xyz {
    double x = 0.0, y = 0.0, z = 0.0;
};

// The colour-matching functions x̄, ȳ, z̄ at `nm` (linear between the 5 nm table's entries;
// 0 outside [kLambdaMin, kLambdaMax]).
Xyz cie_xyz(double nm);

// ∫ ȳ(λ) dλ over the table (nm): what a spectrum's Y is divided by to make a luminance.
double cie_y_integral();

// CIE XYZ to linear Rec.709/sRGB primaries with the D65 white (IEC 61966-2-1).
Rgb xyz_to_rec709(const Xyz& xyz);
// Linear Rec.709 to CIE XYZ (the inverse of xyz_to_rec709).
Xyz rec709_to_xyz(const Rgb& rgb);

// Chromaticity (x, y) of a colour; {0, 0} for black.
struct Chromaticity {
    double x = 0.0, y = 0.0;
};
Chromaticity chromaticity(const Xyz& xyz);

}  // namespace glint::spectral
