#pragma once
// Emission by temperature (Planck's law).
namespace glint::spectral {

// Spectral radiance of a black body at `kelvin`, W·sr⁻¹·m⁻²·nm⁻¹ at `nm`. 0 for kelvin ≤ 0.
double blackbody(double nm, double kelvin);

// The blackbody divided by its peak value (Wien's law), so that its maximum over λ is 1:
// a light's `blackbody = T` sets the colour, its `intensity`/`scale` the brightness.
double blackbody_normalized(double nm, double kelvin);

}  // namespace glint::spectral
