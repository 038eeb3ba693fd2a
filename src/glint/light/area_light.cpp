#include <glint/light/area_light.h>
#include <glint/math/warp.h>

namespace glint {

std::optional<LightSample> AreaLight::sample_li(const Vec3& ref, const Vec2& u,
                                                float u_select) const {
    return arriving_from(ref, m_shape->sample(ref, u, u_select));
}

std::optional<LightSample> AreaLight::sample_li_piece(const Vec3& ref, const Vec2& u,
                                                      float u_select, uint32_t piece) const {
    return arriving_from(ref, m_shape->sample_piece(ref, u, u_select, piece));
}

std::optional<LightSample> AreaLight::arriving_from(const Vec3& ref, const ShapeSample& s) const {
    std::optional<LightSample> result;  // one named result, built in the caller's storage
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return result;
    Vec3 wi = s.direction;
    if (wi == Vec3(0.0f)) {
        const Vec3 d = s.p - ref;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return result;
        wi = d * (1.0f / std::sqrt(dist2));
    }
    if (!emits_towards(s.n, -wi)) return result;
    LightSample& ls = result.emplace();
    ls.wi = wi;
    ls.L = m_radiance.spectrum();
    ls.pdf = s.pdf;
    ls.p = s.p;
    ls.n = s.n;
    return result;
}

float AreaLight::pdf_li(const Vec3& ref, const SurfaceInteraction& on_light) const {
    return m_shape->pdf(ref, on_light.p, on_light.ng);
}

float AreaLight::pdf_li_piece(const Vec3& ref, const SurfaceInteraction& on_light,
                              uint32_t piece) const {
    return m_shape->pdf_piece(ref, on_light.p, on_light.ng, piece);
}

Spectrum AreaLight::le(const SurfaceInteraction& si, const Vec3& w) const {
    return radiance_towards(si.ng, w);
}

// Position uniform by area, direction cosine-weighted about the normal (on a random side
// when two-sided), so every photon carries L * pi * area (times 2 if two-sided).
std::optional<LightEmission> AreaLight::sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                  float u_select) const {
    bool back = false;
    if (m_two_sided) {
        back = u_select >= 0.5f;
        u_select = back ? 2.0f * u_select - 1.0f : 2.0f * u_select;
    }
    const ShapeSample s = m_shape->sample_area(u_position, u_select);
    const Vec3 n = back ? -s.n : s.n;
    const Vec3 local = warp::square_to_cosine_hemisphere(u_direction);
    const Vec3 w = Frame::from_normal(n).to_world(local);
    LightEmission e;
    e.ray = Ray{offset_ray_origin(s.p, n, w), w};
    e.n = n;
    e.Le = m_radiance.spectrum();
    e.pdf_pos = s.pdf;
    // Each side is chosen half the time.
    e.pdf_dir = warp::cosine_hemisphere_pdf(local) * (m_two_sided ? 0.5f : 1.0f);
    return e;
}

// The position density does not depend on the point (uniform by area); the direction's is
// the cosine lobe about the emitting side of n, halved for two sides.
EmissionPdf AreaLight::pdf_le(const Ray& ray, const Vec3& n) const {
    const float cosine = glm::dot(n, ray.direction);
    const float area = m_shape->area();
    EmissionPdf pdf;
    pdf.pos = area > 0.0f ? 1.0f / area : 0.0f;
    if (m_two_sided) {
        pdf.dir = std::abs(cosine) * (0.5f * kInvPi);
    } else {
        pdf.dir = cosine > 0.0f ? cosine * kInvPi : 0.0f;
    }
    return pdf;
}

Spectrum AreaLight::power() const {
    return m_radiance.spectrum() * (kPi * m_shape->area() * (m_two_sided ? 2.0f : 1.0f));
}

// A surface emits over the hemisphere about each normal (pi / 2 past it), on both sides of
// it when two-sided.
std::optional<LightBounds> AreaLight::bounds() const {
    return bounds_of(m_shape->bounds(), m_shape->normal_cone(), power().luminance());
}

std::optional<LightBounds> AreaLight::piece_bounds(uint32_t piece) const {
    const float phi = power().luminance() * (m_shape->piece_area(piece) / m_shape->area());
    return bounds_of(m_shape->piece_bounds(piece), m_shape->piece_normal_cone(piece), phi);
}

LightBounds AreaLight::bounds_of(const Bounds3& box, const DirectionCone& normals,
                                 float phi) const {
    LightBounds b;
    b.bounds = box;
    b.phi = std::max(0.0f, phi);
    b.normals = normals;
    b.cos_theta_e = 0.0f;
    b.two_sided = m_two_sided;
    return b;
}

}  // namespace glint
