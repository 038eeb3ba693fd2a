#include <glint/spectral/dispersion.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace glint::spectral {
namespace {

// Lower case with '_', '-' and ' ' dropped: "Fused_Silica" and "fused silica" are one name.
std::string canonical(std::string_view s) {
    std::string out;
    for (unsigned char ch : s)
        if (ch != '_' && ch != '-' && ch != ' ') out.push_back(static_cast<char>(std::tolower(ch)));
    return out;
}

struct Preset {
    const char* name;
    std::vector<double> b, c;
};

// Sellmeier coefficients (λ in µm), from:
// - BK7: Schott optical glass data sheet, N-BK7 (n_d = 1.5168, V_d = 64.17);
// - fused silica: I. H. Malitson, J. Opt. Soc. Am. 55, 1205 (1965);
// - diamond: F. Peter, Z. Phys. 15, 358 (1923);
// - water (20 °C): M. Daimon and A. Masumura, Appl. Opt. 46, 3811 (2007).
const std::vector<Preset>& presets() {
    static const std::vector<Preset> table = {
        {"BK7", {1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}},
        {"fused silica",
         {0.6961663, 0.4079426, 0.8974794},
         {0.0684043 * 0.0684043, 0.1162414 * 0.1162414, 9.896161 * 9.896161}},
        {"diamond", {0.3306, 4.3356}, {0.175 * 0.175, 0.106 * 0.106}},
        {"water",
         {5.684027565e-1, 1.726177391e-1, 2.086189578e-2, 1.130748688e-1},
         {5.101829712e-3, 1.821153936e-2, 2.620722293e-2, 1.069792721e1}},
    };
    return table;
}

}  // namespace

DispersiveIor DispersiveIor::constant(double n) {
    DispersiveIor ior;
    ior.m_kind = Kind::constant;
    ior.m_a = {n};
    return ior;
}

std::optional<std::string> DispersiveIor::check_sellmeier(const std::vector<double>& b,
                                                          const std::vector<double>& c) {
    if (b.empty() || b.size() > 6)
        return fmt::format("Sellmeier B needs 1 to 6 terms, got {}", b.size());
    if (b.size() != c.size())
        return fmt::format("Sellmeier B and C need as many terms ({} and {})", b.size(), c.size());
    for (size_t i = 0; i < b.size(); ++i)
        if (!std::isfinite(b[i]) || !std::isfinite(c[i]) || c[i] < 0.0)
            return fmt::format("Sellmeier term {}: B and C must be finite and C ≥ 0 (µm²)", i + 1);
    return std::nullopt;
}

DispersiveIor DispersiveIor::sellmeier(std::vector<double> b, std::vector<double> c) {
    if (auto problem = check_sellmeier(b, c)) throw std::invalid_argument(*problem);
    DispersiveIor ior;
    ior.m_kind = Kind::sellmeier;
    ior.m_a = std::move(b);
    ior.m_c = std::move(c);
    return ior;
}

DispersiveIor DispersiveIor::cauchy(double a, double b, double c) {
    DispersiveIor ior;
    ior.m_kind = b == 0.0 && c == 0.0 ? Kind::constant : Kind::cauchy;
    ior.m_a = ior.m_kind == Kind::constant ? std::vector<double>{a} : std::vector<double>{a, b, c};
    return ior;
}

DispersiveIor DispersiveIor::from_abbe(double n_d, double abbe) {
    if (!(abbe > 0.0) || std::isinf(abbe)) return constant(n_d);
    const auto inv2 = [](double nm) { return 1.0 / (nm * nm * 1e-6); };  // 1/λ² with λ in µm
    const double b = (n_d - 1.0) / (abbe * (inv2(kLambdaF) - inv2(kLambdaC)));
    return cauchy(n_d - b * inv2(kLambdaD), b);
}

double DispersiveIor::eval(double nm) const {
    const double um2 = nm * nm * 1e-6;
    switch (m_kind) {
        case Kind::constant:
            return m_a[0];
        case Kind::cauchy:
            return m_a[0] + m_a[1] / um2 + m_a[2] / (um2 * um2);
        case Kind::sellmeier: {
            double n2 = 1.0;
            for (size_t i = 0; i < m_a.size(); ++i) n2 += m_a[i] * um2 / (um2 - m_c[i]);
            return std::sqrt(std::max(n2, 1.0));
        }
    }
    return m_a[0];
}

double DispersiveIor::abbe_number() const {
    const double spread = eval(kLambdaF) - eval(kLambdaC);
    if (spread == 0.0) return std::numeric_limits<double>::infinity();
    return (eval(kLambdaD) - 1.0) / spread;
}

std::optional<DispersiveIor> named_dielectric(std::string_view name) {
    const std::string wanted = canonical(name);
    for (const Preset& p : presets())
        if (canonical(p.name) == wanted) return DispersiveIor::sellmeier(p.b, p.c);
    return std::nullopt;
}

std::vector<std::string> dielectric_names() {
    std::vector<std::string> names;
    for (const Preset& p : presets()) names.emplace_back(p.name);
    return names;
}

}  // namespace glint::spectral
