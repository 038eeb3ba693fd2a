#pragma once
// Indices of refraction that vary with wavelength (dispersion): Sellmeier, Cauchy, or a
// Cauchy form fitted to an index n_d and Abbe number V_d; named presets for common glasses.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::spectral {

// The reference wavelength of n_d (helium d line), where RGB mode evaluates the index.
inline constexpr double kLambdaD = 587.56;
// Fraunhofer F and C lines, which define the Abbe number V_d = (n_d − 1) / (n_F − n_C).
inline constexpr double kLambdaF = 486.13;
inline constexpr double kLambdaC = 656.27;

class DispersiveIor {
public:
    DispersiveIor() = default;

    // A constant index (no dispersion).
    static DispersiveIor constant(double n);
    // n² = 1 + Σ B_i λ² / (λ² − C_i), λ in µm, C_i in µm² (as glass catalogues give them).
    // b and c hold as many terms as each other (1 to 6), C_i ≥ 0.
    static DispersiveIor sellmeier(std::vector<double> b, std::vector<double> c);
    // n = A + B / λ² + C / λ⁴, λ in µm.
    static DispersiveIor cauchy(double a, double b, double c = 0.0);
    // The two-term Cauchy index with n(λ_d) = n_d and (n_d − 1) / (n_F − n_C) = abbe.
    static DispersiveIor from_abbe(double n_d, double abbe);

    // What is wrong with these Sellmeier terms, or nothing (for error messages of loaders).
    static std::optional<std::string> check_sellmeier(const std::vector<double>& b,
                                                      const std::vector<double>& c);

    double eval(double nm) const;
    // The index at kLambdaD: what RGB mode uses.
    double reference() const { return eval(kLambdaD); }
    // (n_d − 1) / (n_F − n_C); infinity without dispersion.
    double abbe_number() const;
    bool is_dispersive() const { return m_kind != Kind::constant; }

private:
    enum class Kind { constant, sellmeier, cauchy };
    Kind m_kind = Kind::constant;
    std::vector<double> m_a{1.5};  // constant: {n}; Cauchy: {A, B, C}; Sellmeier: B_i
    std::vector<double> m_c;       // Sellmeier: C_i
};

// "BK7", "fused silica", "diamond", "water" (case-insensitive; '_', '-' and ' ' alike).
std::optional<DispersiveIor> named_dielectric(std::string_view name);
std::vector<std::string> dielectric_names();

}  // namespace glint::spectral
