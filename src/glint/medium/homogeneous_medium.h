#pragma once
// A medium with the same coefficients everywhere (fog, milk, murky water): one majorant
// segment per ray, equal to the extinction (so delta tracking meets no null collisions),
// and the closed-form transmittance exp(-sigma_t d).
#include <glint/core/medium.h>

namespace glint {

class HomogeneousMedium final : public Medium {
public:
    /// Coefficients per unit length; `emission` is the radiance of its sigma_a-weighted
    /// source; g the Henyey-Greenstein asymmetry.
    HomogeneousMedium(const Spectrum& sigma_a, const Spectrum& sigma_s, float g,
                      const Spectrum& emission = Spectrum(0.0f));

    MediumPoint at(const Vec3&) const override { return m_point; }
    void majorants(const Ray& ray, float t_max, MajorantVisitor visit) const override;
    Spectrum transmittance(const Ray& ray, float t, Rng& rng) const override;
    float phase_asymmetry() const override { return m_g; }
    bool scatters() const override { return !m_point.sigma_s.is_black(); }
    bool emits() const override { return !(m_point.emission * m_point.sigma_a).is_black(); }
    bool is_homogeneous() const override { return true; }

    const Spectrum& sigma_t() const { return m_sigma_t; }

private:
    MediumPoint m_point;
    Spectrum m_sigma_t;
    float m_g;
};

}  // namespace glint
