#include <glint/spectral/illuminants.h>

#include <glint/spectral/cie.h>
#include <glint/spectral/cie_data.h>

#include <glint/core/strings.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

namespace glint::spectral {
namespace {

// A table at `first_nm` + 5 nm · i, scaled to luminance 1 (∫ S ȳ dλ = ∫ ȳ dλ), so that every
// named illuminant is equally bright and a light's intensity alone sets its brightness.
template <size_t N>
TabulatedSpectrum with_unit_luminance(const std::array<double, N>& values, int first_nm) {
    double weighted = 0.0;
    for (size_t i = 0; i < N; ++i)
        weighted += values[i] * cie_xyz(first_nm + data::kStepNm * static_cast<double>(i)).y;
    const double scale = cie_y_integral() / (weighted * data::kStepNm);
    std::vector<std::pair<float, float>> samples;
    samples.reserve(N);
    for (size_t i = 0; i < N; ++i)
        samples.emplace_back(static_cast<float>(first_nm + data::kStepNm * static_cast<int>(i)),
                             static_cast<float>(values[i] * scale));
    return TabulatedSpectrum(std::move(samples));
}

// Illuminant A is defined by a formula (CIE 015:2018): Planck's law for 2856 K written with the
// second radiation constant c2 = 1.435e7 nm·K of its definition (hence 2848 K), at 5 nm.
std::array<double, data::kCieSamples> illuminant_a() {
    constexpr double c2 = 1.435e7;
    constexpr double kelvin = 2848.0;
    std::array<double, data::kCieSamples> values{};
    for (size_t i = 0; i < values.size(); ++i) {
        const double nm = data::kCieFirstNm + data::kStepNm * static_cast<double>(i);
        values[i] = 100.0 * std::pow(560.0 / nm, 5.0) * std::expm1(c2 / (kelvin * 560.0)) /
                    std::expm1(c2 / (kelvin * nm));
    }
    return values;
}

struct Named {
    std::string name;
    TabulatedSpectrum spectrum;
};

const std::vector<Named>& all_illuminants() {
    static const std::vector<Named> table = [] {
        std::vector<Named> t;
        t.push_back({"D65", with_unit_luminance(data::kD65, data::kCieFirstNm)});
        t.push_back({"A", with_unit_luminance(illuminant_a(), data::kCieFirstNm)});
        for (size_t f = 0; f < data::kFluorescent.size(); ++f)
            t.push_back({"F" + std::to_string(f + 1),
                         with_unit_luminance(data::kFluorescent[f], data::kFluorescentFirstNm)});
        return t;
    }();
    return table;
}

}  // namespace

const TabulatedSpectrum* named_illuminant(std::string_view name) {
    const std::string wanted = to_lower(name);
    for (const auto& entry : all_illuminants())
        if (to_lower(entry.name) == wanted) return &entry.spectrum;
    return nullptr;
}

std::vector<std::string> illuminant_names() {
    std::vector<std::string> names;
    for (const auto& entry : all_illuminants()) names.push_back(entry.name);
    return names;
}

}  // namespace glint::spectral
