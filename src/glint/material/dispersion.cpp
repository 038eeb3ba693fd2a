#include <glint/material/dispersion.h>

#include <cmath>

namespace glint {

Dispersion Dispersion::sellmeier(const std::array<double, 3>& b, const std::array<double, 3>& c) {
    Dispersion d;
    d.m_sellmeier = true;
    d.m_b = b;
    d.m_c = c;
    return d;
}

Dispersion Dispersion::cauchy(double a, double b) {
    Dispersion d;
    d.m_b = {a, b, 0.0};
    return d;
}

Dispersion Dispersion::from_abbe(double n_d, double abbe) {
    // n_F − n_C = B (1/λ_F² − 1/λ_C²) = (n_d − 1) / V, then A from n(λ_d) = n_d.
    auto inv_sq = [](double nm) { return 1.0 / (nm * 1e-3 * nm * 1e-3); };
    const double b = (n_d - 1.0) / (abbe * (inv_sq(kLambdaF) - inv_sq(kLambdaC)));
    return cauchy(n_d - b * inv_sq(kLambdaD), b);
}

float Dispersion::index(float nm) const {
    const double um2 = (nm * 1e-3) * (nm * 1e-3);
    if (!m_sellmeier) return static_cast<float>(m_b[0] + m_b[1] / um2);
    double n2 = 1.0;
    for (int i = 0; i < 3; ++i) n2 += m_b[i] * um2 / (um2 - m_c[i]);
    return static_cast<float>(std::sqrt(std::max(n2, 1e-6)));
}

}  // namespace glint
