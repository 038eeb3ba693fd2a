#include <glint/light/area_light.h>

namespace glint {

std::optional<LightSample> AreaLight::sample_li(const Vec3& ref, const Vec2& u,
                                                float u_select) const {
    const ShapeSample s = m_shape->sample(ref, u, u_select);
    const Vec3 d = s.p - ref;
    const float dist2 = glm::dot(d, d);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf) || !(dist2 > 0.0f)) return std::nullopt;
    LightSample ls;
    ls.wi = d / std::sqrt(dist2);
    ls.L = emitted(s.n, -ls.wi);
    if (ls.L.is_black()) return std::nullopt;
    ls.pdf = s.pdf;
    ls.p = s.p;
    return ls;
}

float AreaLight::pdf_li(const Vec3& ref, const SurfaceInteraction& on_light) const {
    return m_shape->pdf(ref, on_light.p, on_light.ng);
}

Spectrum AreaLight::le(const SurfaceInteraction& si, const Vec3& w) const {
    return emitted(si.ng, w);
}

Spectrum AreaLight::power() const {
    return m_radiance * (kPi * m_shape->area() * (m_two_sided ? 2.0f : 1.0f));
}

}  // namespace glint
