#pragma once
// A spectrum given as (wavelength nm, value) pairs: measured data, standard illuminants and
// what a scene states in Lua as { {nm, value}, ... }. Linear between samples, 0 outside them
// (a table says nothing of the light it does not list).
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glint::spectral {

class TabulatedSpectrum {
public:
    TabulatedSpectrum() = default;

    // Checks the table: at least two pairs, wavelengths strictly increasing and positive,
    // values finite and non-negative. Returns what is wrong, or nothing if it is valid.
    static std::optional<std::string> check(const std::vector<std::pair<float, float>>& samples);
    // The table, which must pass `check` (throws std::invalid_argument otherwise).
    explicit TabulatedSpectrum(std::vector<std::pair<float, float>> samples);

    float eval(float nm) const;
    bool empty() const { return m_nm.empty(); }
    const std::vector<float>& wavelengths() const { return m_nm; }
    const std::vector<float>& values() const { return m_value; }

private:
    std::vector<float> m_nm;
    std::vector<float> m_value;
};

}  // namespace glint::spectral
