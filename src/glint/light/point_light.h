#pragma once
#include <glint/core/params.h>
#include <glint/light/light.h>

#include <memory>

namespace glint {

// Isotropic point light of a given intensity (W/sr).
class PointLight final : public Light {
public:
    PointLight(const Vec3& position, const SceneColor& intensity)
        : m_position(position), m_intensity(intensity) {}
    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    Spectrum power() const override { return 4.0f * kPi * m_intensity.spectrum(); }
    std::optional<LightBounds> bounds() const override;
    /// From the position (pdf_pos 1), a direction uniform on the sphere.
    std::optional<LightEmission> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                           float u_select) const override;
    EmissionPdf pdf_le(const Ray& ray, const Vec3& n) const override;
    Spectrum emitted(const Vec3&, const Vec3&, const Vec3&) const override {
        return m_intensity.spectrum();
    }
    bool is_delta() const override { return true; }

private:
    Vec3 m_position;
    SceneColor m_intensity;
};

// Point light restricted to a cone, with a smooth falloff between two half-angles.
class SpotLight final : public Light {
public:
    SpotLight(const Vec3& position, const Vec3& direction, const SceneColor& intensity,
              float cone_degrees, float falloff_start_degrees);
    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    Spectrum power() const override;
    std::optional<LightBounds> bounds() const override;
    /// From the position (pdf_pos 1), a direction uniform in the cone of `cone_degrees`.
    std::optional<LightEmission> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                           float u_select) const override;
    EmissionPdf pdf_le(const Ray& ray, const Vec3& n) const override;
    Spectrum emitted(const Vec3&, const Vec3&, const Vec3& w) const override {
        return m_intensity.spectrum() * falloff(w);
    }
    bool is_delta() const override { return true; }
    // Fraction of the intensity emitted in direction `w` (unit, away from the light).
    float falloff(const Vec3& w) const;

private:
    Vec3 m_position;
    Vec3 m_direction;
    SceneColor m_intensity;
    float m_cos_cone;
    float m_cos_falloff_start;
};

// Parallel light from one direction (the sun): `irradiance` on a surface facing it.
class DirectionalLight final : public Light {
public:
    DirectionalLight(const Vec3& direction, const SceneColor& irradiance)
        : m_direction(glm::normalize(direction)), m_irradiance(irradiance) {}
    void preprocess(const Vec3& scene_center, float scene_radius) override {
        m_center = scene_center;
        m_radius = scene_radius;
    }
    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    /// Along the light's direction (pdf_dir 1), from a point uniform on the disc of the
    /// scene's radius that faces the light outside the scene (pdf_pos 1 / (pi r^2)).
    std::optional<LightEmission> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                           float u_select) const override;
    EmissionPdf pdf_le(const Ray& ray, const Vec3& n) const override;
    Spectrum emitted(const Vec3&, const Vec3&, const Vec3&) const override {
        return Spectrum(0.0f);
    }
    Spectrum power() const override {
        return m_irradiance.spectrum() * (kPi * m_radius * m_radius);
    }
    bool is_delta() const override { return true; }
    bool is_delta_direction() const override { return true; }

private:
    Vec3 m_direction;  // the way the light travels
    SceneColor m_irradiance;
    Vec3 m_center{0.0f};
    float m_radius = 1.0f;
};

std::unique_ptr<Light> make_point_light(const Params& params);
std::unique_ptr<Light> make_directional_light(const Params& params);
std::unique_ptr<Light> make_spot_light(const Params& params);

}  // namespace glint
