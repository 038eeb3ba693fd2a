#pragma once
// pbrt-v4's spectral inputs reduced to glint's linear Rec.709 RGB: blackbody emitters, the
// named spectra scenes use (metals' eta and k, glasses' index, standard illuminants) and
// spectra given as (wavelength, value) pairs.
#include <glint/math/vector.h>

#include <optional>
#include <string>
#include <vector>

namespace glint {

/// CIE 1931 2-degree colour matching functions by the multi-lobe Gaussian fit of Wyman,
/// Sloan and Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching
/// Functions", JCGT 2(2), 2013. `nm` is the wavelength in nanometres.
Vec3 cie_xyz_fit(double nm);

/// Linear Rec.709 (sRGB primaries, D65 white) from CIE XYZ.
Vec3 rec709_from_xyz(const Vec3& xyz);

/// The colour of a blackbody at `kelvin`, normalised to luminance Y = 1. pbrt-v4 normalises
/// its blackbody spectrum to 1 at its peak, and then every light divides its spectrum by
/// its luminance (SpectrumToPhotometric), so a blackbody light of scale s has luminance s
/// whatever its temperature: this is that colour. Throws glint::Error for kelvin <= 0.
Vec3 blackbody_rgb(double kelvin);

/// An emission spectrum given as (nm, value) pairs, as the colour of luminance 1 (pbrt-v4
/// divides light spectra by their luminance too).
Vec3 illuminant_rgb(const std::vector<double>& pairs);

/// A reflectance or index spectrum given as (nm, value) pairs, sampled at 650, 550 and
/// 450 nm (as glint's conductor presets are): pbrt's RGB uplifting is not invertible, and
/// point samples are what a per-channel Fresnel equation needs.
Vec3 sampled_rgb(const std::vector<double>& pairs);

/// What a named pbrt-v4 spectrum stands for in RGB.
struct NamedSpectrum {
    enum class Kind { Index, Illuminant };
    Kind kind;
    Vec3 rgb;
};

/// The named spectra glint knows: "metal-Au-eta"/"-k", Ag, Cu, Al; "glass-BK7", "glass-BAF10",
/// "glass-FK51A", "glass-LASF9", "glass-F5"; "stdillum-D65", "stdillum-A". Nothing for others.
std::optional<NamedSpectrum> named_spectrum(const std::string& name);

/// The pairs of a spectrum file (whitespace-separated numbers, '#' comments), as pbrt-v4
/// reads them. Throws glint::Error naming the file.
std::vector<double> read_spectrum_file(const std::string& path);

}  // namespace glint
