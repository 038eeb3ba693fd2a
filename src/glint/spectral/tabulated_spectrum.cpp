#include <glint/spectral/tabulated_spectrum.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace glint::spectral {

std::optional<std::string> TabulatedSpectrum::check(
    const std::vector<std::pair<float, float>>& samples) {
    if (samples.size() < 2) return "a spectrum needs at least two {nm, value} pairs";
    for (size_t i = 0; i < samples.size(); ++i) {
        const auto [nm, value] = samples[i];
        if (!std::isfinite(nm) || nm <= 0.0f)
            return fmt::format("pair {}: the wavelength {} nm is not a positive number", i + 1, nm);
        if (!std::isfinite(value) || value < 0.0f)
            return fmt::format("pair {}: the value {} is not a finite non-negative number", i + 1,
                               value);
        if (i > 0 && nm <= samples[i - 1].first)
            return fmt::format("pair {}: wavelengths must increase ({} nm after {} nm)", i + 1, nm,
                               samples[i - 1].first);
    }
    return std::nullopt;
}

TabulatedSpectrum::TabulatedSpectrum(std::vector<std::pair<float, float>> samples) {
    if (auto problem = check(samples)) throw std::invalid_argument(*problem);
    m_nm.reserve(samples.size());
    m_value.reserve(samples.size());
    for (const auto& [nm, value] : samples) {
        m_nm.push_back(nm);
        m_value.push_back(value);
    }
}

float TabulatedSpectrum::eval(float nm) const {
    if (m_nm.empty() || !(nm >= m_nm.front() && nm <= m_nm.back())) return 0.0f;
    if (nm == m_nm.back()) return m_value.back();
    const auto hi =
        static_cast<size_t>(std::upper_bound(m_nm.begin(), m_nm.end(), nm) - m_nm.begin());
    const size_t lo = hi - 1;
    const float t = (nm - m_nm[lo]) / (m_nm[hi] - m_nm[lo]);
    return m_value[lo] + t * (m_value[hi] - m_value[lo]);
}

}  // namespace glint::spectral
