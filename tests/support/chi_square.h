#pragma once
// Chi-square goodness-of-fit test of a direction sampler against its claimed density
// (the method of Nori and Mitsuba: equal solid-angle bins in (cos theta, phi), expected
// counts from numerically integrating the pdf, bins with small expectation pooled).
#include <glint/math/vector.h>

#include <functional>
#include <optional>
#include <string>

namespace glint::test {

struct ChiSquareResult {
    bool passed = false;
    double p_value = 0.0;
    double integrated_pdf = 0.0;  // should be the fraction of successful samples
    double sample_fraction = 0.0;
    std::string details;
};

using DirectionSampler = std::function<std::optional<Vec3>(const Vec2& u, float u_extra)>;
using DirectionPdf = std::function<double(const Vec3& w)>;

ChiSquareResult chi_square_directions(const DirectionSampler& sample, const DirectionPdf& pdf,
                                      int sample_count = 200000, uint64_t seed = 1,
                                      int cos_theta_bins = 20, int phi_bins = 40,
                                      double significance = 0.01);

// Upper tail probability of the chi-square distribution with `dof` degrees of freedom.
double chi_square_upper_tail(double statistic, int dof);

}  // namespace glint::test
