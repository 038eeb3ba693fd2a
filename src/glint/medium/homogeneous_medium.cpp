#include <glint/medium/homogeneous_medium.h>

namespace glint {

HomogeneousMedium::HomogeneousMedium(const Spectrum& sigma_a, const Spectrum& sigma_s, float g,
                                     const Spectrum& emission)
    : m_point{sigma_a, sigma_s, emission}, m_sigma_t(sigma_a + sigma_s), m_g(g) {}

void HomogeneousMedium::majorants(const Ray&, float t_max, MajorantVisitor visit) const {
    visit(MajorantSegment{0.0f, t_max, m_sigma_t});
}

Spectrum HomogeneousMedium::transmittance(const Ray& ray, float t, Rng&) const {
    return exp(m_sigma_t * (-t * glm::length(ray.direction)));
}

}  // namespace glint
