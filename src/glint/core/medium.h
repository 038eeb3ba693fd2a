#pragma once
// What fills the space between surfaces. A walk carries the medium its ray travels through
// (null: vacuum) and asks it two things about each segment:
//
//   - where light traveling along it first interacts: distance sampling by delta tracking
//     against a majorant (medium/delta_tracking.h), which needs the medium's coefficients at
//     a point (`at`) and an upper bound of its extinction along the ray (`majorants`);
//   - how much light crosses it: `transmittance` (closed form where the medium has one,
//     ratio tracking against the same majorants otherwise).
//
// Scattering follows the medium's phase function (Henyey-Greenstein with asymmetry g).
// Coefficients are per unit length in scene units. The interface is pbrt-v4's (base/medium.h:
// SamplePoint, SampleRay's majorant iterator) written as a plain virtual class with a
// visitor, so that a grid medium (a DDA over a majorant grid) drives its own loop.
#include <glint/core/ray.h>
#include <glint/core/rng.h>
#include <glint/core/spectrum.h>

#include <glm/geometric.hpp>

#include <type_traits>
#include <utility>

namespace glint {

/// The coefficients of a medium at one point (per unit length).
struct MediumPoint {
    Spectrum sigma_a{0.0f};   ///< absorption
    Spectrum sigma_s{0.0f};   ///< scattering
    Spectrum emission{0.0f};  ///< radiance emitted per unit absorption (sigma_a Le is the source)
};

/// A stretch [t_min, t_max) of a unit-direction ray over which `sigma_maj` bounds the
/// extinction sigma_a + sigma_s from above, channel by channel.
struct MajorantSegment {
    float t_min = 0.0f;
    float t_max = 0.0f;
    Spectrum sigma_maj{0.0f};
};

/// A non-owning reference to a callable `bool(const MajorantSegment&)`: what a medium calls
/// for each majorant segment, in order along the ray; the callable returns false to stop.
class MajorantVisitor {
public:
    template <typename F,
              typename = std::enable_if_t<!std::is_same_v<std::decay_t<F>, MajorantVisitor>>>
    MajorantVisitor(F&& f)  // NOLINT: implicit, so a lambda can be passed directly
        : m_object(const_cast<void*>(static_cast<const void*>(&f))),
          m_call([](void* object, const MajorantSegment& segment) {
              return (*static_cast<std::remove_reference_t<F>*>(object))(segment);
          }) {}
    bool operator()(const MajorantSegment& segment) const { return m_call(m_object, segment); }

private:
    void* m_object;
    bool (*m_call)(void*, const MajorantSegment&);
};

class Medium {
public:
    virtual ~Medium() = default;

    /// The coefficients at world point `p`.
    virtual MediumPoint at(const Vec3& p) const = 0;
    /// Calls `visit` with the majorant segments of `ray` (unit direction) over [0, t_max), in
    /// order, until it returns false or the segments end. Segments may leave gaps (the
    /// medium is empty there) and need not reach t_max.
    virtual void majorants(const Ray& ray, float t_max, MajorantVisitor visit) const = 0;
    /// The fraction of light that crosses `ray` from its origin to parameter `t` (the ray's
    /// direction need not be unit length): exact where the medium has a closed form, else an
    /// unbiased estimate drawing from `rng` (ratio tracking, medium/delta_tracking.h).
    virtual Spectrum transmittance(const Ray& ray, float t, Rng& rng) const = 0;

    /// Asymmetry g in (-1, 1) of the Henyey-Greenstein phase function: 0 scatters evenly,
    /// g > 0 forwards, g < 0 backwards.
    virtual float phase_asymmetry() const { return 0.0f; }
    /// Whether the medium scatters light anywhere; a medium that only absorbs (and maybe
    /// emits) lets walks multiply by its transmittance instead of sampling distances.
    virtual bool scatters() const = 0;
    /// Whether the medium emits light anywhere.
    virtual bool emits() const { return false; }
    /// Whether its coefficients are the same everywhere (`at` ignores its point).
    virtual bool is_homogeneous() const { return false; }
};

/// A homogeneous medium that absorbs and does not scatter: transmittance exp(-sigma_a d)
/// over a distance d (Beer-Lambert). The interior of an absorbing dielectric.
///
/// Media keep their coefficients as the colours the scene gave and uplift them when asked
/// (uplift(..., RgbRole::unbounded)), as materials do: in spectral mode a path asks at its
/// own wavelengths, in RGB mode the uplift is a copy.
class AbsorbingMedium final : public Medium {
public:
    explicit AbsorbingMedium(const Rgb& sigma_a) : m_sigma_a(sigma_a) {}
    MediumPoint at(const Vec3&) const override { return MediumPoint{sigma_a()}; }
    void majorants(const Ray&, float t_max, MajorantVisitor visit) const override {
        visit(MajorantSegment{0.0f, t_max, sigma_a()});
    }
    Spectrum transmittance(const Ray& ray, float t, Rng&) const override {
        return transmittance(ray, t);
    }
    /// The closed form; needs no random numbers.
    Spectrum transmittance(const Ray& ray, float t) const {
        return exp(sigma_a() * (-t * glm::length(ray.direction)));
    }
    bool scatters() const override { return false; }
    bool is_homogeneous() const override { return true; }
    Spectrum sigma_a() const { return uplift(m_sigma_a, RgbRole::unbounded); }
    bool absorbs() const { return m_sigma_a.max_value() > 0.0f; }

private:
    Rgb m_sigma_a;
};

/// The media on the two sides of a surface: `inside` is the side its geometric normal
/// points away from (the inside of a closed shape), `outside` the side it points to. Null
/// on both sides (the default) means the surface separates no media: the walk keeps the
/// medium it is in.
struct MediumInterface {
    const Medium* inside = nullptr;
    const Medium* outside = nullptr;

    /// Whether the surface bounds a medium at all.
    bool is_transition() const { return inside != nullptr || outside != nullptr; }
    /// The medium on the side a ray arrives from: the inside when it hits the back face.
    const Medium* arriving(bool front_face) const { return front_face ? outside : inside; }
    /// The medium a ray leaving the surface along a direction on the front side
    /// (`to_front`) or the back side enters.
    const Medium* leaving(bool to_front) const { return to_front ? outside : inside; }
};

}  // namespace glint
