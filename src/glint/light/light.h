#pragma once
// The Light interface. Lights state their emission in the units that fit them:
// radiance for area lights, intensity (W/sr) for point and spot lights.
#include <glint/core/interaction.h>
#include <glint/core/spectrum.h>
#include <glint/light/light_bounds.h>

#include <cmath>
#include <optional>

namespace glint {

struct LightSample {
    Vec3 wi;           // unit direction from the reference point towards the light
    Spectrum L;        // radiance arriving from that direction (intensity/r^2 for delta lights)
    float pdf = 0.0f;  // solid-angle density, or 1 for delta lights
    Vec3 p;            // the point on the light, target of the shadow ray
    Vec3 n{0.0f};      // unit normal of the light's surface at p (area lights); zero for lights
                       // without a surface. Bidirectional methods need it for the densities
                       // with which the light's own sampling (sample_le) would emit from p
    bool is_delta = false;
};

/// A ray leaving a light, for photons, light paths and bidirectional methods, with the
/// densities of its origin and direction kept apart (a bidirectional method needs each).
struct LightEmission {
    Ray ray;               ///< origin on the light (offset off a surface), unit direction
    Vec3 n{0.0f};          ///< unit surface normal at the origin for lights with a surface (area),
                           ///< on the side the ray leaves; zero for lights without a surface
    Spectrum Le;           ///< radiance leaving along the ray (area, environment; W sr^-1 m^-2),
                           ///< intensity (point, spot; W sr^-1) or irradiance (directional; W m^-2)
    float pdf_pos = 0.0f;  ///< density of the origin: per unit area on an area light; 1 for
                           ///< point and spot lights (delta position); per unit area of the
                           ///< disc (radius = scene radius, perpendicular to the direction)
                           ///< through which directional and environment light enters the scene
    float pdf_dir = 0.0f;  ///< density of the direction per unit solid angle; 1 for a
                           ///< directional light (delta direction)

    /// Le |cos theta| / (pdf_pos pdf_dir): a photon's power per sample (|cos theta| with n
    /// for surface lights, 1 for lights without a surface).
    Spectrum beta() const {
        const bool surface = n.x != 0.0f || n.y != 0.0f || n.z != 0.0f;
        const float cosine = surface ? std::abs(glm::dot(n, ray.direction)) : 1.0f;
        const float pdf = pdf_pos * pdf_dir;
        return pdf > 0.0f ? Le * (cosine / pdf) : Spectrum(0.0f);
    }
};

/// Densities of an emitted ray's origin and direction, in LightEmission's measures.
struct EmissionPdf {
    float pos = 0.0f;
    float dir = 0.0f;
};

class Light {
public:
    virtual ~Light() = default;

    // Called once the scene is built (directional lights need its extent).
    virtual void preprocess(const Vec3& scene_center, float scene_radius) {
        (void)scene_center;
        (void)scene_radius;
    }
    /// Samples a ray leaving the light; nullopt when nothing is emitted. u_position picks the
    /// point, u_direction the direction, u_select a triangle or side.
    virtual std::optional<LightEmission> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                   float u_select) const = 0;
    /// Densities with which sample_le would produce `ray` (origin on the light, unit
    /// direction; `n` the light's unit normal there, zero for lights without a surface).
    /// Delta components are reported as sample_le reports them (1); a direction a light
    /// does not emit into has dir = 0.
    virtual EmissionPdf pdf_le(const Ray& ray, const Vec3& n) const = 0;
    /// What the light emits from its point `p` (normal `n`, zero without a surface)
    /// towards the unit direction `w`, in the units of LightEmission::Le: radiance for area
    /// and environment lights, intensity for point and spot lights; zero for a delta
    /// direction (directional light), which no other direction receives.
    /// The one query beyond sample_le that aiming photons needs (projection maps): they
    /// choose the direction themselves, from sample_le's origin, and must know what leaves
    /// that way. A general question every light can answer, so no light-type-specific
    /// virtuals are needed.
    virtual Spectrum emitted(const Vec3& p, const Vec3& n, const Vec3& w) const = 0;

    // Samples incident illumination at `ref`; nullopt when the light cannot reach it.
    virtual std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                                 float u_select) const = 0;
    // Density of sample_li choosing the point `on_light.p` (zero for delta lights).
    virtual float pdf_li(const Vec3&, const SurfaceInteraction&) const { return 0.0f; }
    // Radiance emitted from a hit on this light towards `w` (unit, away from the surface).
    virtual Spectrum le(const SurfaceInteraction&, const Vec3&) const { return Spectrum(0.0f); }
    // Total emitted power, for choosing lights in proportion to it.
    virtual Spectrum power() const = 0;
    /// Where the light is, its power and which way it emits, for the light tree; nullopt for
    /// lights without a place in the scene (environment, directional), which the tree
    /// chooses alongside its own.
    virtual std::optional<LightBounds> bounds() const { return std::nullopt; }

    /// Pieces: the parts of one light that the light tree chooses among one by one, the
    /// triangles of an emitting mesh (ShapeSampler::piece_count), so that every emissive
    /// triangle is a light of its own for next-event estimation while the mesh stays one
    /// light everywhere else (power, light paths, Whitted's sum over lights). A light of
    /// one piece answers the calls below as the whole-light calls above.
    virtual uint32_t piece_count() const { return 1; }
    /// The bounds of piece `piece` (< piece_count()).
    virtual std::optional<LightBounds> piece_bounds(uint32_t piece) const {
        (void)piece;
        return bounds();
    }
    /// sample_li within piece `piece`: the density is the point's given that piece.
    virtual std::optional<LightSample> sample_li_piece(const Vec3& ref, const Vec2& u,
                                                       float u_select, uint32_t piece) const {
        (void)piece;
        return sample_li(ref, u, u_select);
    }
    /// The density of sample_li_piece choosing `on_light`'s point, which lies on `piece`.
    virtual float pdf_li_piece(const Vec3& ref, const SurfaceInteraction& on_light,
                               uint32_t piece) const {
        (void)piece;
        return pdf_li(ref, on_light);
    }
    virtual bool is_delta() const = 0;
    /// Whether the emission is a delta in direction (a directional light): its rays come in
    /// parallel from a disc outside the scene, so bidirectional methods treat its vertex as
    /// a direction at infinity, like the environment's, rather than as a point.
    virtual bool is_delta_direction() const { return false; }

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
