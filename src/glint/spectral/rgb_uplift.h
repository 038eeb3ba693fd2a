#pragma once
// Jakob & Hanika 2019, "A Low-Dimensional Function Space for Efficient Spectral Upsampling":
// an Rgb becomes the smooth spectrum s(λ) = S(c0 λ² + c1 λ + c2) with the sigmoid
// S(x) = ½ + x / (2 √(1 + x²)), whose three coefficients are found by glint's own
// Gauss–Newton fit (rgb_uplift_table.h) so that the spectrum's colour under D65 is the Rgb.
// A sigmoid stays in [0, 1], so an uplifted reflectance is ≤ 1 at every wavelength.
#include <glint/core/rgb.h>
#include <glint/core/spectrum.h>

#include <array>

namespace glint::spectral {

// s(λ) = S(c0 λ² + c1 λ + c2) with λ in nm.
class SigmoidPolynomial {
public:
    constexpr SigmoidPolynomial() = default;
    constexpr SigmoidPolynomial(float c0, float c1, float c2) : m_c{c0, c1, c2} {}

    float eval(float nm) const;
    const std::array<float, 3>& coefficients() const { return m_c; }

private:
    std::array<float, 3> m_c{0.0f, 0.0f, 0.0f};
};

// The sigmoid polynomial of a colour in [0, 1]³: interpolated in the fitted table, then
// polished by two Gauss–Newton steps (about a microsecond: call it once per colour, not per
// wavelength).
SigmoidPolynomial uplift_coefficients(const Rgb& rgb);

// The value at `nm` of the spectrum `rgb` stands for in `role`:
// - reflectance: the sigmoid polynomial of rgb clamped to [0, 1] (≤ 1 everywhere);
// - unbounded: m · s(λ) with m = 2 · max channel, s the polynomial of rgb / m (so any
//   non-negative Rgb round-trips);
// - illuminant: the unbounded spectrum times D65 scaled to luminance 1, so that rgb = (1,1,1)
//   is the D65 white of sRGB with luminance 1.
float uplifted_rgb(const Rgb& rgb, RgbRole role, float nm);

}  // namespace glint::spectral
