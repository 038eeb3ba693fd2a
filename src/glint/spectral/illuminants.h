#pragma once
// The CIE standard illuminants as relative spectral power distributions (CIE 015:2018).
#include <glint/spectral/tabulated_spectrum.h>

#include <string>
#include <string_view>
#include <vector>

namespace glint::spectral {

// "D65", "A", "F1" … "F12" (case-insensitive), normalised to 1 at 560 nm; nullptr for an
// unknown name.
const TabulatedSpectrum* named_illuminant(std::string_view name);
// The names named_illuminant knows, for error messages.
std::vector<std::string> illuminant_names();

}  // namespace glint::spectral
