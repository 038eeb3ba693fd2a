#pragma once
// The CIE standard illuminants as relative spectral power distributions (CIE 015:2018).
#include <glint/spectral/tabulated_spectrum.h>

#include <string>
#include <string_view>
#include <vector>

namespace glint::spectral {

// "D65", "A", "F1" … "F12" (case-insensitive), scaled to luminance 1 (their Y equals that of a
// constant spectrum 1); nullptr for an unknown name.
const TabulatedSpectrum* named_illuminant(std::string_view name);
// The names named_illuminant knows, for error messages.
std::vector<std::string> illuminant_names();

}  // namespace glint::spectral
