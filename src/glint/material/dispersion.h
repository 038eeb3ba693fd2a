#pragma once
// An index of refraction that varies with wavelength: Sellmeier's or Cauchy's formula, or a
// Cauchy form fitted to an index n_d and an Abbe number V_d. RGB mode uses the index at the
// helium d line (587.56 nm); spectral mode the index at the path's hero wavelength.
#include <array>

namespace glint {

class Dispersion {
public:
    static constexpr float kLambdaD = 587.56f;  // nm, helium d line (n_d)
    static constexpr float kLambdaF = 486.13f;  // nm, hydrogen F line
    static constexpr float kLambdaC = 656.27f;  // nm, hydrogen C line

    // n² = 1 + Σ B_i λ² / (λ² − C_i), λ in µm, C_i in µm².
    static Dispersion sellmeier(const std::array<double, 3>& b, const std::array<double, 3>& c);
    // n = A + B / λ², λ in µm.
    static Dispersion cauchy(double a, double b);
    // The Cauchy form with n(λ_d) = n_d and (n_d − 1) / (n_F − n_C) = abbe.
    static Dispersion from_abbe(double n_d, double abbe);

    float index(float nm) const;
    float reference_index() const { return index(kLambdaD); }

private:
    bool m_sellmeier = false;
    std::array<double, 3> m_b{1.5, 0.0, 0.0};  // Sellmeier B, or Cauchy A, B
    std::array<double, 3> m_c{0.0, 0.0, 0.0};  // Sellmeier C
};

}  // namespace glint
