#pragma once
// The spectral shape an emitter's table may state besides its colour: `blackbody = 2700`
// (kelvin) or `spectrum = "D65"` (a named illuminant) or `spectrum = { {nm, value}, ... }`.
// Each shape has luminance 1, so the colour parameter (intensity, irradiance, radiance: a
// number or an RGB) alone sets how bright the emitter is and the shape its colour:
// `intensity = 100, blackbody = 2700` is as bright as `intensity = 100`, but warm.
#include <glint/core/params.h>
#include <glint/core/rgb.h>
#include <glint/core/spectrum.h>
#include <glint/spectral/tabulated_spectrum.h>

#include <optional>

namespace glint::spectral {

class EmissionShape {
public:
    static EmissionShape blackbody(double kelvin);
    static EmissionShape tabulated(TabulatedSpectrum spectrum);

    // The relative spectral radiance at `nm`, luminance 1 over the visible range.
    double eval(double nm) const;
    // Its colour in linear Rec.709 (luminance 1): what RGB mode renders.
    Rgb rgb() const { return m_rgb; }

private:
    EmissionShape(double kelvin, TabulatedSpectrum spectrum);
    double unscaled(double nm) const;

    double m_kelvin = 0.0;  // > 0 for a blackbody
    TabulatedSpectrum m_table;
    double m_scale = 1.0;
    Rgb m_rgb;
};

// Reads `blackbody` or `spectrum` (at most one) from `params`; nothing if neither is given.
// Bad values (a temperature outside [100, 100000] K, an unknown illuminant, a malformed
// table) fail with the table's file and line.
std::optional<EmissionShape> read_emission_shape(const Params& params);

// The emitter colour parameter `name` times the shape, if any: with a shape, `name` may be
// left out (1). Negative colours fail.
Rgb read_emission_rgb(const Params& params, const char* name);

// The same, as the colour an emitter keeps: with a shape, spectral mode reads the shape
// itself at each wavelength (RGB mode renders read_emission_rgb's colour).
SceneColor read_emission_color(const Params& params, const char* name);

}  // namespace glint::spectral
