#pragma once
// What fills the space between surfaces. A walk carries the medium its ray travels through
// (null: vacuum), and every segment's throughput is multiplied by the medium's
// transmittance over it. Today the only medium absorbs and does not scatter (the interior
// of an absorbing dielectric, Beer-Lambert); scattering media (homogeneous, heterogeneous,
// null-scattering, issue 29) are further kinds of Medium, and a walk that meets one asks it
// for a scattering distance as well.
#include <glint/core/ray.h>
#include <glint/core/spectrum.h>

#include <glm/geometric.hpp>

namespace glint {

class Medium {
public:
    virtual ~Medium() = default;
    /// The fraction of light that crosses `ray` from its origin to parameter `t` (the ray's
    /// direction need not be unit length).
    virtual Spectrum transmittance(const Ray& ray, float t) const = 0;
};

/// A homogeneous medium that absorbs and does not scatter: transmittance exp(-sigma_a d)
/// over a distance d (Beer-Lambert).
class AbsorbingMedium final : public Medium {
public:
    explicit AbsorbingMedium(const Spectrum& sigma_a) : m_sigma_a(sigma_a) {}
    Spectrum transmittance(const Ray& ray, float t) const override {
        return exp(m_sigma_a * (-t * glm::length(ray.direction)));
    }
    const Spectrum& sigma_a() const { return m_sigma_a; }

private:
    Spectrum m_sigma_a;
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
