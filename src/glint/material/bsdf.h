#pragma once
// The BSDF contract.
//
// A Bsdf works in the local shading frame: z is the shading normal on the outside of the
// surface, `wo` points away from the surface towards the viewer, `wi` towards the light;
// both are unit vectors and may lie on either side (z < 0 is inside or behind).
//
//   eval(wo, wi)      f(wo, wi) WITHOUT the cosine factor; 0 for delta lobes.
//   pdf(wo, wi)       solid-angle density with which sample() returns wi; 0 for delta lobes.
//   eval_pdf(wo, wi, pdf)  both of the above in one call, for light sampling, which needs
//                     both: the same values, bit for bit.
//   sample(wo, u, uc) a direction wi with f and pdf; for delta lobes `pdf` is the discrete
//                     probability of the chosen lobe and `f` already contains the delta
//                     (f * |cos wi| / pdf is the path weight). nullopt when no direction
//                     is produced (absorbed).
//
// Rules, each tested in tests/material: sample() is distributed as pdf() (chi-square);
// no BSDF reflects more energy than it receives; reflection is reciprocal, and refraction
// obeys the generalised reciprocity f(wo,wi)/eta_o^2 = f(wi,wo)/eta_i^2 for radiance,
// with eta_o the index on wo's side (Veach 1997, eq. 5.14; see tests/material).
//
// BSDFs are built per hit in an Arena and never destroyed, so they must be trivially
// destructible (no virtual destructor, no owning members). A material whose BSDF is the
// same at every hit (no textures) may build it once and hand out that one: BSDFs are
// immutable, so threads share it safely.
#include <glint/core/spectrum.h>
#include <glint/math/frame.h>

#include <cstdint>
#include <optional>

namespace glint {

enum BsdfFlags : uint32_t {
    kBsdfReflection = 1u << 0,
    kBsdfTransmission = 1u << 1,
    kBsdfDiffuse = 1u << 2,
    kBsdfGlossy = 1u << 3,
    kBsdfDelta = 1u << 4,
};

struct BsdfSample {
    Spectrum f;
    Vec3 wi;
    float pdf = 0.0f;
    uint32_t flags = 0;
    // eta of the side wi enters relative to the side wo came from; 1 for reflection.
    float eta = 1.0f;

    bool is_delta() const { return flags & kBsdfDelta; }
    bool is_transmission() const { return flags & kBsdfTransmission; }
};

class Bsdf {
public:
    virtual Spectrum eval(const Vec3& wo, const Vec3& wi) const = 0;
    virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;
    virtual std::optional<BsdfSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const = 0;
    // eval() and pdf() together: one virtual call, and BSDFs that override it share the
    // work the two have in common.
    virtual Spectrum eval_pdf(const Vec3& wo, const Vec3& wi, float& pdf_out) const {
        pdf_out = pdf(wo, wi);
        return eval(wo, wi);
    }
    // Union of the flags of all lobes. A member, set once when the BSDF is built, rather
    // than a virtual call: integrators ask for it at every bounce.
    uint32_t flags() const { return m_flags; }
    bool is_delta() const {
        return (flags() & ~(kBsdfReflection | kBsdfTransmission)) == kBsdfDelta;
    }

protected:
    explicit Bsdf(uint32_t flags) : m_flags(flags) {}
    ~Bsdf() = default;  // not virtual: arena objects are never destroyed

private:
    uint32_t m_flags;
};

}  // namespace glint
