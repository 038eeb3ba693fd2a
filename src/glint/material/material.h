#pragma once
// A Material turns a surface hit into a BSDF (built in the per-thread arena) and states
// what the surface emits and what the medium behind it absorbs.
#include <glint/core/arena.h>
#include <glint/core/interaction.h>
#include <glint/material/bsdf.h>

namespace glint {

class Material {
public:
    virtual ~Material() = default;

    // The BSDF at this hit, or nullptr for a surface that does not scatter (a pure emitter).
    virtual const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const = 0;
    // Reflectance colour for the albedo feature channel.
    virtual Spectrum albedo(const SurfaceInteraction&) const { return Spectrum(0.0f); }

    // Radiance leaving the front side (and the back too when two-sided).
    virtual Spectrum emission() const { return Spectrum(0.0f); }
    virtual bool emits_two_sided() const { return false; }
    bool is_emissive() const { return !emission().is_black(); }

    // Beer-Lambert absorption coefficient (per scene length unit) of the volume inside a
    // closed shape with this material; zero for surfaces.
    virtual Spectrum interior_absorption() const { return Spectrum(0.0f); }
};

}  // namespace glint
