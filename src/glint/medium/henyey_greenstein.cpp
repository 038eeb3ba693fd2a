#include <glint/math/frame.h>
#include <glint/medium/henyey_greenstein.h>

#include <algorithm>
#include <cmath>

namespace glint {

PhaseSample HenyeyGreenstein::sample(const Vec3& wo, const Vec2& u) const {
    // Inverting the cumulative distribution of cos_theta (in the convention above); near
    // g = 0 the inversion loses its digits and the density is uniform anyway.
    float cos_theta;
    if (std::abs(m_g) < 1e-3f) {
        cos_theta = 1.0f - 2.0f * u.x;
    } else {
        const float ratio = (1.0f - m_g * m_g) / (1.0f + m_g - 2.0f * m_g * u.x);
        cos_theta = -(1.0f + m_g * m_g - ratio * ratio) / (2.0f * m_g);
    }
    cos_theta = std::clamp(cos_theta, -1.0f, 1.0f);
    const float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    const float phi = 2.0f * kPi * u.y;
    const Frame frame = Frame::from_normal(wo);
    const Vec3 wi = glm::normalize(
        frame.to_world(Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta)));
    return PhaseSample{wi, density(cos_theta)};
}

}  // namespace glint
