#pragma once
// Indices of refraction that vary with wavelength (dispersion): Sellmeier, Cauchy, or a
// Cauchy form fitted to an index n_d and Abbe number V_d; named presets for common glasses.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::spectral {

// The reference wavelength of n_d (helium d line), where RGB mode evaluates the index.
inline constexpr float kLambdaD = 587.56f;
// Fraunhofer F and C lines, which define the Abbe number V_d = (n_d − 1) / (n_F − n_C).
inline constexpr float kLambdaF = 486.13f;
inline constexpr float kLambdaC = 656.27f;

class DispersiveIor {
public:
    // A constant index (no dispersion).
    static DispersiveIor constant(float n);
    // n² = 1 + Σ B_i λ² / (λ² − C_i), λ in µm, C_i in µm².
    static DispersiveIor sellmeier(const std::array<double, 3>& b, const std::array<double, 3>& c);
    // n = A + B / λ² + C / λ⁴, λ in µm.
    static DispersiveIor cauchy(double a, double b, double c = 0.0);
    // The two-term Cauchy index with n(λ_d) = n_d and (n_d − 1) / (n_F − n_C) = abbe. abbe ≤ 0
    // or infinite gives a constant index.
    static DispersiveIor from_abbe(double n_d, double abbe);

    double eval(double nm) const;
    // The index at kLambdaD: what RGB mode uses.
    double reference() const { return eval(kLambdaD); }
    // (n_d − 1) / (n_F − n_C); infinity without dispersion.
    double abbe_number() const;
    bool is_dispersive() const { return m_kind != Kind::constant; }

private:
    enum class Kind { constant, sellmeier, cauchy };
    Kind m_kind = Kind::constant;
    std::array<double, 3> m_a{1.5, 0.0, 0.0};  // constant: n; Cauchy: A, B, C; Sellmeier: B
    std::array<double, 3> m_c{0.0, 0.0, 0.0};  // Sellmeier: C
};

// "BK7", "fused silica", "diamond", "water" (case-insensitive; '_' and ' ' alike).
std::optional<DispersiveIor> named_dielectric(std::string_view name);
std::vector<std::string> dielectric_names();

}  // namespace glint::spectral
