#pragma once
// Spectral data and conversions, usable in RGB and spectral mode alike. Everything is a
// function of a wavelength in nanometres; nothing here knows what a path carries.
//
//   uplifted_rgb      an Rgb as a smooth spectrum (Jakob & Hanika 2019), by its role
//   cie_xyz           the CIE 1931 2° colour-matching functions
//   xyz_to_rec709     CIE XYZ to linear Rec.709/sRGB primaries (D65 white)
//   blackbody         Planck's law, and its normalised form for emitters
//   named_illuminant  D65, A, F1–F12 as tabulated spectra
//   named_conductor   measured η, k of metals (Au, Ag, Cu, Al, …)
//   DispersiveIor     Sellmeier / Cauchy / Abbe indices of refraction, with presets
//   spectrum_to_rgb   a spectrum integrated to the Rgb that stands for it in RGB mode
#include <glint/spectral/blackbody.h>
#include <glint/spectral/cie.h>
#include <glint/spectral/conductors.h>
#include <glint/spectral/dispersion.h>
#include <glint/spectral/illuminants.h>
#include <glint/spectral/rgb_uplift.h>
#include <glint/spectral/spectrum_to_rgb.h>
#include <glint/spectral/tabulated_spectrum.h>
