#pragma once
// The sigmoid-polynomial coefficient table of rgb_uplift.cpp, computed at build time by
// uplift_table_generator.cpp (glint's own fit, sigmoid_fit.h) into rgb_uplift_table.cpp.
//
// Layout, as in Jakob & Hanika's paper: a colour's largest channel l picks one of three
// cubes; inside it z = that channel's value (on the nonuniform grid kUpliftZ, denser near 0
// and 1) and x, y = the next two channels (l + 1, l + 2 mod 3) divided by it, on a uniform grid.
#include <array>

namespace glint::spectral::data {

inline constexpr int kUpliftResolution = 32;

// The z value of each grid index (increasing from 0 to 1).
extern const std::array<float, kUpliftResolution> kUpliftZ;
// coefficients[((l · N + zi) · N + yi) · N + xi] = {c0, c1, c2} of the normalised wavelength
// (sigmoid_fit.h).
extern const std::array<std::array<float, 3>,
                        3 * kUpliftResolution * kUpliftResolution * kUpliftResolution>
    kUpliftCoefficients;

// The grid's z values: a double smoothstep, so that cells crowd where colours are darkest and
// brightest (where the coefficients change fastest).
inline double uplift_z(int index) {
    const double t = static_cast<double>(index) / (kUpliftResolution - 1);
    const auto smoothstep = [](double x) { return x * x * (3.0 - 2.0 * x); };
    return smoothstep(smoothstep(t));
}

}  // namespace glint::spectral::data
