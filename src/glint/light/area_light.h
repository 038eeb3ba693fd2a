#pragma once
// A shape that emits constant radiance from its front side (or both sides).
#include <glint/geometry/shape.h>
#include <glint/light/light.h>

#include <memory>

namespace glint {

class AreaLight final : public Light {
public:
    AreaLight(std::unique_ptr<ShapeSampler> shape, const SceneColor& radiance, bool two_sided)
        : m_shape(std::move(shape)),
          m_radiance(radiance),
          m_two_sided(two_sided),
          m_dark(radiance.is_black()) {}

    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    float pdf_li(const Vec3& ref, const SurfaceInteraction& on_light) const override;
    Spectrum le(const SurfaceInteraction& si, const Vec3& w) const override;
    Spectrum power() const override;
    std::optional<LightBounds> bounds() const override;
    uint32_t piece_count() const override { return m_shape->piece_count(); }
    std::optional<LightBounds> piece_bounds(uint32_t piece) const override;
    std::optional<LightSample> sample_li_piece(const Vec3& ref, const Vec2& u, float u_select,
                                               uint32_t piece) const override;
    float pdf_li_piece(const Vec3& ref, const SurfaceInteraction& on_light,
                       uint32_t piece) const override;
    /// A point uniform by area, a direction cosine-weighted about the normal (on the side
    /// u_select picks, when two-sided); n is the normal of the side the ray leaves.
    std::optional<LightEmission> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                           float u_select) const override;
    EmissionPdf pdf_le(const Ray& ray, const Vec3& n) const override;
    Spectrum emitted(const Vec3&, const Vec3& n, const Vec3& w) const override {
        return radiance_towards(n, w);
    }
    bool is_delta() const override { return false; }

    // Radiance leaving a surface point with normal `n` towards `w`.
    Spectrum radiance_towards(const Vec3& n, const Vec3& w) const {
        return emits_towards(n, w) ? m_radiance.spectrum() : Spectrum(0.0f);
    }
    // Whether radiance_towards(n, w) is non-zero, without building the spectrum.
    bool emits_towards(const Vec3& n, const Vec3& w) const {
        return !m_dark && (m_two_sided || glm::dot(n, w) > 0.0f);
    }

private:
    // The light sample at the shape's point `s` seen from `ref`.
    std::optional<LightSample> arriving_from(const Vec3& ref, const ShapeSample& s) const;
    LightBounds bounds_of(const Bounds3& box, const DirectionCone& normals, float phi) const;

    std::unique_ptr<ShapeSampler> m_shape;
    SceneColor m_radiance;
    bool m_two_sided;
    bool m_dark;  // zero radiance: emits nothing anywhere
};

}  // namespace glint
