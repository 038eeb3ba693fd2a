#pragma once
// A medium with the same coefficients everywhere (fog, milk, murky water): one majorant
// segment per ray, equal to the extinction (so delta tracking meets no null collisions),
// and the closed-form transmittance exp(-sigma_t d).
#include <glint/core/medium.h>

namespace glint {

class HomogeneousMedium final : public Medium {
public:
    /// Coefficients per unit length; `emission` is the radiance of its sigma_a-weighted
    /// source; g the Henyey-Greenstein asymmetry. Colours, uplifted when asked (see
    /// AbsorbingMedium).
    HomogeneousMedium(const Rgb& sigma_a, const Rgb& sigma_s, float g,
                      const Rgb& emission = Rgb(0.0f));

    MediumPoint at(const Vec3&) const override;
    void majorants(const Ray& ray, float t_max, MajorantVisitor visit) const override;
    Spectrum transmittance(const Ray& ray, float t, Rng& rng) const override;
    float phase_asymmetry() const override { return m_g; }
    bool scatters() const override { return m_sigma_s.max_value() > 0.0f; }
    bool emits() const override { return (m_emission * m_sigma_a).max_value() > 0.0f; }
    bool is_homogeneous() const override { return true; }

    // sigma_a and sigma_s uplifted apart and added, as at() gives them. Inline: it is read
    // on every transmittance.
    Spectrum sigma_t() const {
        return uplift(m_sigma_a, RgbRole::unbounded) + uplift(m_sigma_s, RgbRole::unbounded);
    }

private:
    Rgb m_sigma_a, m_sigma_s, m_emission;
    float m_g;
};

}  // namespace glint
