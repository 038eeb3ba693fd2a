#pragma once
#include <glint/core/params.h>
#include <glint/light/light.h>

#include <memory>

namespace glint {

// Isotropic point light of a given intensity (W/sr).
class PointLight final : public Light {
public:
    PointLight(const Vec3& position, const Spectrum& intensity)
        : m_position(position), m_intensity(intensity) {}
    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    Spectrum power() const override { return 4.0f * kPi * m_intensity; }
    bool is_delta() const override { return true; }

private:
    Vec3 m_position;
    Spectrum m_intensity;
};

// Point light restricted to a cone, with a smooth falloff between two half-angles.
class SpotLight final : public Light {
public:
    SpotLight(const Vec3& position, const Vec3& direction, const Spectrum& intensity,
              float cone_degrees, float falloff_start_degrees);
    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    Spectrum power() const override;
    bool is_delta() const override { return true; }
    // Fraction of the intensity emitted in direction `w` (unit, away from the light).
    float falloff(const Vec3& w) const;

private:
    Vec3 m_position;
    Vec3 m_direction;
    Spectrum m_intensity;
    float m_cos_cone;
    float m_cos_falloff_start;
};

std::unique_ptr<Light> make_point_light(const Params& params);
std::unique_ptr<Light> make_spot_light(const Params& params);

}  // namespace glint
