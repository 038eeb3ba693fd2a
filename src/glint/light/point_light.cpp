#include <glint/light/point_light.h>
#include <glint/math/frame.h>
#include <glint/math/warp.h>
#include <glint/spectral/emission_params.h>

#include <algorithm>

namespace glint {
namespace {

std::optional<LightSample> sample_point(const Vec3& position, const Vec3& ref,
                                        const Spectrum& intensity) {
    const Vec3 d = position - ref;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return std::nullopt;
    LightSample s;
    s.wi = d / std::sqrt(dist2);
    s.L = intensity / dist2;
    s.pdf = 1.0f;
    s.p = position;
    s.is_delta = true;
    return s;
}

}  // namespace

std::optional<LightEmission> PointLight::sample_le(const Vec2&, const Vec2& u_direction,
                                                   float) const {
    LightEmission e;
    e.ray = Ray{m_position, warp::square_to_uniform_sphere(u_direction)};
    e.Le = m_intensity.spectrum();
    e.pdf_pos = 1.0f;
    e.pdf_dir = warp::uniform_sphere_pdf();
    return e;
}

EmissionPdf PointLight::pdf_le(const Ray&, const Vec3&) const {
    return {1.0f, warp::uniform_sphere_pdf()};
}

// Uniform in the outer cone; the falloff goes into Le, not into the density, so directions
// in the falloff band carry less power each.
std::optional<LightEmission> SpotLight::sample_le(const Vec2&, const Vec2& u_direction,
                                                  float) const {
    const Vec3 local = warp::square_to_uniform_cone(u_direction, m_cos_cone);
    const Vec3 w = Frame::from_normal(m_direction).to_world(local);
    const float falloff_value = falloff(w);
    if (falloff_value <= 0.0f) return std::nullopt;
    LightEmission e;
    e.ray = Ray{m_position, w};
    e.Le = m_intensity.spectrum() * falloff_value;
    e.pdf_pos = 1.0f;
    e.pdf_dir = warp::uniform_cone_pdf(local, m_cos_cone);
    return e;
}

EmissionPdf SpotLight::pdf_le(const Ray& ray, const Vec3&) const {
    const float cos_theta = glm::dot(glm::normalize(ray.direction), m_direction);
    return {1.0f,
            cos_theta >= m_cos_cone ? warp::uniform_cone_pdf(Vec3(0, 0, 1), m_cos_cone) : 0.0f};
}

std::optional<LightSample> DirectionalLight::sample_li(const Vec3& ref, const Vec2&, float) const {
    LightSample s;
    s.wi = -m_direction;
    s.L = m_irradiance.spectrum();
    s.pdf = 1.0f;
    s.p = ref + s.wi * (2.0f * m_radius + glm::length(ref - m_center));  // beyond the scene
    s.is_delta = true;
    return s;
}

// Rays start on a disk that covers the scene, facing along the light.
std::optional<LightEmission> DirectionalLight::sample_le(const Vec2& u_position, const Vec2&,
                                                         float) const {
    const Vec2 d = warp::square_to_uniform_disk_concentric(u_position);
    const Frame frame = Frame::from_normal(m_direction);
    LightEmission e;
    e.ray = Ray{m_center - m_direction * m_radius + m_radius * (d.x * frame.s() + d.y * frame.t()),
                m_direction};
    e.Le = m_irradiance.spectrum();
    e.pdf_pos = 1.0f / (kPi * m_radius * m_radius);
    e.pdf_dir = 1.0f;
    return e;
}

// Any ray is taken to be along the light's direction (a delta, reported as 1 like
// sample_le does); the origin's density is that of the disc, wherever on it.
EmissionPdf DirectionalLight::pdf_le(const Ray&, const Vec3&) const {
    return {1.0f / (kPi * m_radius * m_radius), 1.0f};
}

std::optional<LightSample> PointLight::sample_li(const Vec3& ref, const Vec2&, float) const {
    return sample_point(m_position, ref, m_intensity.spectrum());
}

SpotLight::SpotLight(const Vec3& position, const Vec3& direction, const SceneColor& intensity,
                     float cone_degrees, float falloff_start_degrees)
    : m_position(position),
      m_direction(glm::normalize(direction)),
      m_intensity(intensity),
      m_cos_cone(std::cos(glm::radians(cone_degrees))),
      m_cos_falloff_start(std::cos(glm::radians(falloff_start_degrees))) {}

float SpotLight::falloff(const Vec3& w) const {
    const float cos_theta = glm::dot(w, m_direction);
    if (cos_theta >= m_cos_falloff_start) return 1.0f;
    if (cos_theta <= m_cos_cone) return 0.0f;
    const float x = (cos_theta - m_cos_cone) / (m_cos_falloff_start - m_cos_cone);
    return x * x * (3.0f - 2.0f * x);  // smoothstep
}

std::optional<LightSample> SpotLight::sample_li(const Vec3& ref, const Vec2&, float) const {
    auto s = sample_point(m_position, ref, m_intensity.spectrum());
    if (!s) return s;
    const float f = falloff(-s->wi);
    if (f <= 0.0f) return std::nullopt;
    s->L *= f;
    return s;
}

// Light leaves a point in every direction: a whole-sphere cone, with nothing beyond it.
std::optional<LightBounds> PointLight::bounds() const {
    LightBounds b;
    b.bounds.expand(m_position);
    b.phi = std::max(0.0f, power().luminance());
    b.normals = DirectionCone::whole_sphere();
    b.cos_theta_e = 1.0f;
    return b;
}

// The cone is exactly the spot's: no emission past its outer angle.
std::optional<LightBounds> SpotLight::bounds() const {
    LightBounds b;
    b.bounds.expand(m_position);
    b.phi = std::max(0.0f, power().luminance());
    b.normals = DirectionCone{m_direction, m_cos_cone, false};
    b.cos_theta_e = 1.0f;
    return b;
}

Spectrum SpotLight::power() const {
    // Full intensity inside the inner cone, and about half of it across the falloff band.
    return m_intensity.spectrum() * 2.0f * kPi *
           ((1.0f - m_cos_falloff_start) + 0.5f * (m_cos_falloff_start - m_cos_cone));
}

namespace {

// A light's colour parameter `name` (intensity or irradiance), checked, shaped by a
// `blackbody` or `spectrum` if the table gives one, and uplifted.
SceneColor read_emission(const Params& params, const char* name) {
    return spectral::read_emission_color(params, name);
}

}  // namespace

std::unique_ptr<Light> make_point_light(const Params& params) {
    const Vec3 position = params.get_vec3("position");
    const SceneColor intensity = read_emission(params, "intensity");
    return std::make_unique<PointLight>(position, intensity);
}

std::unique_ptr<Light> make_directional_light(const Params& params) {
    const Vec3 direction = params.get_vec3("direction");
    if (!(glm::length(direction) > 0.0f)) params.fail("'direction' must not be zero");
    const SceneColor irradiance = read_emission(params, "irradiance");
    return std::make_unique<DirectionalLight>(direction, irradiance);
}

std::unique_ptr<Light> make_spot_light(const Params& params) {
    const Vec3 position = params.get_vec3("position");
    const Vec3 target = params.get_vec3("look_at");
    const SceneColor intensity = read_emission(params, "intensity");
    const float cone = params.get_float("cone_angle", 30.0f);
    const float falloff_start = params.get_float("falloff_start", cone * 0.8f);
    if (!(cone > 0.0f && cone <= 90.0f)) params.fail("'cone_angle' must be in (0, 90] degrees");
    if (!(falloff_start >= 0.0f && falloff_start <= cone)) {
        params.fail("'falloff_start' must be between 0 and 'cone_angle'");
    }
    if (glm::length(target - position) <= 0.0f)
        params.fail("'look_at' must differ from 'position'");
    return std::make_unique<SpotLight>(position, target - position, intensity, cone, falloff_start);
}

}  // namespace glint
