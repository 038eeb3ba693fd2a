#include <glint/light/area_light.h>
#include <glint/math/warp.h>

namespace glint {

std::optional<LightSample> AreaLight::sample_li(const Vec3& ref, const Vec2& u,
                                                float u_select) const {
    std::optional<LightSample> result;  // one named result, built in the caller's storage
    const ShapeSample s = m_shape->sample(ref, u, u_select);
    const Vec3 d = s.p - ref;
    const float dist2 = glm::dot(d, d);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf) || !(dist2 > 0.0f)) return result;
    const Vec3 wi = d * (1.0f / std::sqrt(dist2));
    if (!emits_towards(s.n, -wi)) return result;
    LightSample& ls = result.emplace();
    ls.wi = wi;
    ls.L = m_radiance;
    ls.pdf = s.pdf;
    ls.p = s.p;
    return result;
}

float AreaLight::pdf_li(const Vec3& ref, const SurfaceInteraction& on_light) const {
    return m_shape->pdf(ref, on_light.p, on_light.ng);
}

Spectrum AreaLight::le(const SurfaceInteraction& si, const Vec3& w) const {
    return emitted(si.ng, w);
}

// Position uniform by area, direction cosine-weighted about the normal (on a random side
// when two-sided), so every photon carries L * pi * area (times 2 if two-sided).
std::optional<LightEmission> AreaLight::sample_le(const Vec2& u1, const Vec2& u2,
                                                  float u_select) const {
    float u_side = 0.0f;
    if (m_two_sided) {
        u_side = u_select < 0.5f ? 0.0f : 1.0f;
        u_select = u_select < 0.5f ? 2.0f * u_select : 2.0f * u_select - 1.0f;
    }
    const ShapeSample s = m_shape->sample_area(u1, u_select);
    const Vec3 n = u_side > 0.0f ? -s.n : s.n;
    const Vec3 w = Frame::from_normal(n).to_world(warp::square_to_cosine_hemisphere(u2));
    const float sides = m_two_sided ? 2.0f : 1.0f;
    return LightEmission{Ray{offset_ray_origin(s.p, n, w), w}, m_radiance * (kPi * sides / s.pdf)};
}

Spectrum AreaLight::power() const {
    return m_radiance * (kPi * m_shape->area() * (m_two_sided ? 2.0f : 1.0f));
}

}  // namespace glint
