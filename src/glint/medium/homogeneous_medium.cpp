#include <glint/medium/delta_tracking.h>
#include <glint/medium/homogeneous_medium.h>

namespace glint {

HomogeneousMedium::HomogeneousMedium(const Rgb& sigma_a, const Rgb& sigma_s, float g,
                                     const Rgb& emission)
    : m_sigma_a(sigma_a), m_sigma_s(sigma_s), m_emission(emission), m_g(g) {}

MediumPoint HomogeneousMedium::at(const Vec3&) const {
    return MediumPoint{uplift(m_sigma_a, RgbRole::unbounded), uplift(m_sigma_s, RgbRole::unbounded),
                       uplift(m_emission, RgbRole::illuminant)};
}

// The majorant is the extinction at every wavelength: delta tracking meets no null
// collisions.
void HomogeneousMedium::majorants(const Ray&, float t_max, MajorantVisitor visit) const {
    visit(MajorantSegment{0.0f, t_max, sigma_t()});
}

// exp(-sigma_t d) per value, with one exp for grey fog (the same bits as four).
Spectrum HomogeneousMedium::transmittance(const Ray& ray, float t, Rng&) const {
    return attenuation(sigma_t(), t * glm::length(ray.direction));
}

}  // namespace glint
