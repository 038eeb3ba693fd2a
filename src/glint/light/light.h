#pragma once
// The Light interface. Lights state their emission in the units that fit them:
// radiance for area lights, intensity (W/sr) for point and spot lights.
#include <glint/core/interaction.h>
#include <glint/core/spectrum.h>

#include <optional>

namespace glint {

struct LightSample {
    Vec3 wi;           // unit direction from the reference point towards the light
    Spectrum L;        // radiance arriving from that direction (intensity/r^2 for delta lights)
    float pdf = 0.0f;  // solid-angle density, or 1 for delta lights
    Vec3 p;            // the point on the light, target of the shadow ray
    bool is_delta = false;
};

// A point on an emitting surface, drawn with density `pdf_area` per unit area.
struct SurfacePoint {
    Vec3 p;
    Vec3 n;  // unit normal (the emitting side, for one-sided lights)
    float pdf_area = 0.0f;
};

// A ray leaving a light, for photon tracing and light paths.
struct LightEmission {
    Ray ray;        // unit direction
    Spectrum beta;  // Le |cos| / (pdf_position pdf_direction): the photon's power per sample
};

class Light {
public:
    virtual ~Light() = default;

    // Called once the scene is built (directional lights need its extent).
    virtual void preprocess(const Vec3& scene_center, float scene_radius) {
        (void)scene_center;
        (void)scene_radius;
    }
    // Samples an emitted ray; nullopt when nothing is emitted. u1 picks the position,
    // u2 the direction, u_select a triangle or side.
    virtual std::optional<LightEmission> sample_le(const Vec2& u1, const Vec2& u2, float u_select) const = 0;

    // Samples incident illumination at `ref`; nullopt when the light cannot reach it.
    virtual std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                                 float u_select) const = 0;
    // Density of sample_li choosing the point `on_light.p` (zero for delta lights).
    virtual float pdf_li(const Vec3&, const SurfaceInteraction&) const { return 0.0f; }
    // Radiance emitted from a hit on this light towards `w` (unit, away from the surface).
    virtual Spectrum le(const SurfaceInteraction&, const Vec3&) const { return Spectrum(0.0f); }
    // Lights that emit from a single point (point, spot) give its position and their
    // intensity per direction, so photons can be aimed (projection maps).
    virtual std::optional<Vec3> emission_point() const { return std::nullopt; }
    virtual Spectrum intensity(const Vec3&) const { return Spectrum(0.0f); }
    // Lights with a surface (area lights) give points on it, uniform by area, and what a
    // point emits towards a direction, so photons can be aimed (projection maps) from them
    // too. nullopt for lights without a surface.
    virtual std::optional<SurfacePoint> sample_surface_point(const Vec2& u, float u_select) const {
        (void)u;
        (void)u_select;
        return std::nullopt;
    }
    virtual Spectrum emitted_from(const SurfacePoint&, const Vec3&) const { return Spectrum(0.0f); }
    // Total emitted power, for choosing lights in proportion to it.
    virtual Spectrum power() const = 0;
    virtual bool is_delta() const = 0;

    /// Lights at infinity (the environment) surround the scene instead of sitting in it:
    /// no surface hit finds them, a ray that escapes the scene does. A scene has at most
    /// one; Scene::environment() returns it.
    virtual bool is_infinite() const { return false; }
    /// For an infinite light: the radiance (W sr^-1 m^-2) a ray escaping the scene along
    /// `direction` (world space, need not be unit) receives, i.e. the light arriving from
    /// that direction. Zero for every other light.
    virtual Spectrum le_escaped(const Vec3& direction) const {
        (void)direction;
        return Spectrum(0.0f);
    }
    /// For an infinite light: the solid-angle density with which sample_li chooses
    /// `direction` (world space, need not be unit; the same from every reference point),
    /// for weighting escaped rays against light sampling. Zero for every other light.
    virtual float pdf_li_escaped(const Vec3& direction) const {
        (void)direction;
        return 0.0f;
    }

    // Position of this light in the scene's light list (set by the LightSampler).
    int index() const { return m_index; }
    void set_index(int index) { m_index = index; }

private:
    int m_index = -1;
};

}  // namespace glint
