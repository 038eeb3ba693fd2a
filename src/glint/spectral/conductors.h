#pragma once
// Measured optical constants of metals: the complex index η + i k at a wavelength.
#include <glint/core/rgb.h>

#include <string>
#include <string_view>
#include <vector>

namespace glint::spectral {

struct ComplexIor {
    float eta = 1.0f;
    float k = 0.0f;
};

// A metal's measured η(λ), k(λ) (linear between measurements).
class ConductorData {
public:
    struct Sample {
        float nm, eta, k;
    };
    ConductorData(std::string name, std::vector<Sample> samples);

    ComplexIor eval(float nm) const;
    const std::string& name() const { return m_name; }

    // η and k integrated to RGB (quantity_to_rgb: weighted by the observer under D65), what
    // RGB mode uses; computed once.
    Rgb rgb_eta() const { return m_rgb_eta; }
    Rgb rgb_k() const { return m_rgb_k; }

private:
    std::string m_name;
    std::vector<Sample> m_samples;
    Rgb m_rgb_eta, m_rgb_k;
};

// "Au", "Ag", "Cu", "Al" and the other names of conductor_names() (case-insensitive; "gold",
// "silver", "copper", "aluminium"/"aluminum" too); nullptr for an unknown name.
const ConductorData* named_conductor(std::string_view name);
std::vector<std::string> conductor_names();

}  // namespace glint::spectral
