#include <glint/material/coat_albedo.h>
#include <glint/material/fresnel.h>
#include <glint/material/microfacet.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

constexpr int kCosineIntervals = 32;  // nodes at cos theta = (j / 32)^2
constexpr int kCosineNodes = kCosineIntervals + 1;
constexpr int kTexturedColumns = 17;
constexpr int kQuadratureSide = 32;  // 32 x 32 visible normals per table entry

// E(mu) by the midpoint rule over the unit square of visible-normal sampling: each point
// gives a facet wm with density D_wo(wm), whose reflection carries F G2 / G1 of the light
// (the estimator f cos_i / pdf of the reflection lobe, Heitz 2018, eq. 19).
float integrate_albedo(float mu, float alpha, float eta) {
    if (alpha < GgxDistribution::kSmoothAlpha) return fresnel_dielectric(mu, eta);
    mu = std::max(mu, 1e-4f);  // the limit at grazing incidence is finite and smooth
    const Vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    const GgxDistribution distribution(alpha);
    const float g1 = distribution.g1(wo);
    double sum = 0.0;
    for (int a = 0; a < kQuadratureSide; ++a) {
        for (int b = 0; b < kQuadratureSide; ++b) {
            const Vec2 u((a + 0.5f) / kQuadratureSide, (b + 0.5f) / kQuadratureSide);
            const Vec3 wm = distribution.sample_visible_normal(wo, u);
            const Vec3 wi = reflect(wo, wm);
            if (wi.z <= 0.0f) continue;
            sum += fresnel_dielectric(glm::dot(wo, wm), eta) * distribution.g2(wo, wi) / g1;
        }
    }
    return static_cast<float>(sum / (kQuadratureSide * kQuadratureSide));
}

}  // namespace

CoatAlbedoTable::CoatAlbedoTable(float eta, float alpha_min, float alpha_max)
    : m_eta(eta),
      m_roughness_min(std::sqrt(alpha_min)),
      m_roughness_max(std::sqrt(alpha_max)),
      m_columns(alpha_max > alpha_min ? kTexturedColumns : 1) {
    m_albedo.resize(static_cast<size_t>(m_columns) * kCosineNodes);
    for (int column = 0; column < m_columns; ++column) {
        for (int j = 0; j < kCosineNodes; ++j) {
            const float t = static_cast<float>(j) / kCosineIntervals;
            m_albedo[column * kCosineNodes + j] =
                integrate_albedo(t * t, alpha_of_column(column), eta);
        }
    }
    // E_avg = 2 integral of E(mu) mu dmu = 4 integral of E(t^2) t^3 dt with mu = t^2, taken
    // of the interpolated table itself (finely, by the midpoint rule), so that the diffuse
    // weights of PlasticBsdf integrate to what its normalisation assumes.
    constexpr int kSteps = 64 * kCosineIntervals;
    m_average.resize(m_columns);
    for (int column = 0; column < m_columns; ++column) {
        double sum = 0.0;
        for (int s = 0; s < kSteps; ++s) {
            const double t = (s + 0.5) / kSteps;
            sum += albedo_in_column(column, static_cast<float>(t * t)) * 4.0 * t * t * t;
        }
        m_average[column] = static_cast<float>(sum / kSteps);
    }
}

float CoatAlbedoTable::alpha_of_column(int column) const {
    if (m_columns == 1) return m_roughness_min * m_roughness_min;
    const float r = m_roughness_min + (m_roughness_max - m_roughness_min) * column /
                                          static_cast<float>(m_columns - 1);
    return r * r;
}

CoatAlbedoTable::Position CoatAlbedoTable::alpha_position(float alpha) const {
    if (m_columns == 1) return {0, 0.0f};
    const float r = std::sqrt(std::max(0.0f, alpha));
    const float x =
        std::clamp((r - m_roughness_min) / (m_roughness_max - m_roughness_min), 0.0f, 1.0f) *
        (m_columns - 1);
    const int index = std::min(static_cast<int>(x), m_columns - 2);
    return {index, x - index};
}

float CoatAlbedoTable::albedo_in_column(int column, float cos_theta) const {
    const float x = std::sqrt(std::clamp(cos_theta, 0.0f, 1.0f)) * kCosineIntervals;
    const int j = std::min(static_cast<int>(x), kCosineIntervals - 1);
    const float s = x - j;
    const float* e = &m_albedo[column * kCosineNodes + j];
    return (1.0f - s) * e[0] + s * e[1];
}

float CoatAlbedoTable::albedo(float cos_theta, float alpha) const {
    if (m_columns == 1) return albedo_in_column(0, cos_theta);
    const Position p = alpha_position(alpha);
    return (1.0f - p.fraction) * albedo_in_column(p.index, cos_theta) +
           p.fraction * albedo_in_column(p.index + 1, cos_theta);
}

float CoatAlbedoTable::average_albedo(float alpha) const {
    if (m_columns == 1) return m_average[0];
    const Position p = alpha_position(alpha);
    return (1.0f - p.fraction) * m_average[p.index] + p.fraction * m_average[p.index + 1];
}

}  // namespace glint
