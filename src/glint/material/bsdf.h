#pragma once
// The BSDF contract.
//
// A Bsdf works in the local shading frame: z is the shading normal on the outside of the
// surface, and `wo`, `wi` are unit vectors that may lie on either side (z < 0 is inside or
// behind). What they mean depends on the transport mode:
//
//   TransportMode::kRadiance (camera paths; the default everywhere)
//       `wo` points towards the viewer (where the path came from), `wi` towards the light
//       (where it continues); light flows from wi to wo, and f = f(wo, wi) is the BSDF of
//       radiance. Refraction carries the factor 1/eta^2 (radiance is compressed with the
//       solid angle, Veach 1997, sec. 5.2), with eta = BsdfSample::eta = n(wi side) /
//       n(wo side).
//   TransportMode::kImportance (light paths, photons)
//       `wo` points towards where the path came from (towards the light), `wi` where it
//       continues; light flows from wo to wi, and f is the adjoint BSDF
//       f*(wo, wi) = f(wi, wo) (radiance mode with the arguments swapped), so that a light
//       path's throughput f* |cos wi| / pdf carries power. Refraction has no 1/eta^2 here.
//       With a shading normal that differs from the geometric one, the adjoint is also
//       multiplied by Veach's correction (1997, sec. 5.3, eq. 5.17)
//           |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|)
//       which makes light paths carry the same measure as camera paths over the shading
//       normal's cosines (0 where the denominator vanishes). `ng_local` is the geometric
//       normal in the local shading frame; the default (0, 0, 1) means no correction.
//
// Every BSDF implements one form, the protected virtuals *_unscaled: f WITHOUT any
// 1/eta^2. For a BSDF that obeys generalised reciprocity, f(wo, wi) / n_o^2 =
// f(wi, wo) / n_i^2 (Veach 1997, eq. 5.14; n_o the index on wo's side), that unscaled f is
// exactly the adjoint f(wi, wo) of the radiance BSDF, so the two modes differ only by
// factors the public non-virtual wrappers below apply, in this one place:
//   radiance:    f = unscaled / eta^2 for a refracted pair (wo, wi on opposite sides)
//   importance:  f = unscaled * shading-normal correction
// No integrator multiplies or undoes either factor by hand.
//
//   eval(wo, wi, mode, ng)  f WITHOUT the cosine factor; 0 for delta lobes.
//   pdf(wo, wi)        solid-angle density with which sample() returns wi; 0 for delta lobes;
//                      the same in both modes (the sampled distribution does not change).
//   eval_pdf(wo, wi, pdf, mode, ng)  both of the above in one call, for light sampling,
//                      which needs both: the same values, bit for bit.
//   sample(wo, u, uc, mode, ng)  a direction wi with f and pdf; for delta lobes `pdf` is the
//                      discrete probability of the chosen lobe and `f` already contains the
//                      delta (f * |cos wi| / pdf is the path weight). nullopt when no
//                      direction is produced (absorbed).
//   delta_lobes(wo, mode, ng)  every delta lobe at wo at once, each with pdf 1 and its whole
//                      weight f * |cos wi| (e.g. Fresnel R for glass reflection, (1 - R) /
//                      eta^2 for its refraction in radiance mode); lobes of weight 0 are left
//                      out (total internal reflection gives one lobe). Non-delta lobes of a
//                      mixed BSDF are not listed; a BSDF without delta lobes lists none. It is
//                      what sample() would give summed over u_lobe: the weight of a lobe is the
//                      expectation of sample()'s f |cos wi| / pdf over the samples in it.
//
// Rules, each tested in tests/material: sample() is distributed as pdf() (chi-square);
// no BSDF reflects more energy than it receives; reflection is reciprocal, and refraction
// obeys generalised reciprocity; importance mode is the adjoint of radiance mode
// (test_bsdf_modes.cpp).
//
// BSDFs are built per hit in an Arena and never destroyed, so they must be trivially
// destructible (no virtual destructor, no owning members). A material whose BSDF is the
// same at every hit (no textures) may build it once and hand out that one: BSDFs are
// immutable, so threads share it safely.
#include <glint/core/spectrum.h>
#include <glint/math/frame.h>

#include <array>
#include <cmath>
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

// Which quantity a path carries: radiance (camera paths) or importance (light paths and
// photons). See the contract above for what wo and wi mean in each.
enum class TransportMode { kRadiance, kImportance };

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

// All delta lobes of a BSDF at one wo (see Bsdf::delta_lobes): each with pdf 1, so that
// f * |cos wi| is the lobe's whole weight. At most two: a reflection and a refraction.
struct DeltaLobes {
    int count = 0;
    std::array<BsdfSample, 2> lobes;

    void add(const BsdfSample& lobe) { lobes[count++] = lobe; }
    const BsdfSample* begin() const { return lobes.data(); }
    const BsdfSample* end() const { return lobes.data() + count; }
};

class Bsdf {
public:
    /// f(wo, wi) in `mode`, without the cosine factor, in the local shading frame; 0 for delta
    /// lobes. `ng_local`: the geometric normal in the shading frame (importance mode only).
    Spectrum eval(const Vec3& wo, const Vec3& wi, TransportMode mode = TransportMode::kRadiance,
                  const Vec3& ng_local = Vec3(0.0f, 0.0f, 1.0f)) const {
        return scale(eval_unscaled(wo, wi), wo, wi, mode, ng_local);
    }

    /// Solid-angle density (sr^-1) with which sample() returns wi; 0 for delta lobes.
    float pdf(const Vec3& wo, const Vec3& wi) const { return pdf_unscaled(wo, wi); }

    /// eval() and pdf() together, bit for bit the same values: one virtual call, and BSDFs
    /// that override eval_pdf_unscaled() share the work the two have in common.
    Spectrum eval_pdf(const Vec3& wo, const Vec3& wi, float& pdf_out,
                      TransportMode mode = TransportMode::kRadiance,
                      const Vec3& ng_local = Vec3(0.0f, 0.0f, 1.0f)) const {
        return scale(eval_pdf_unscaled(wo, wi, pdf_out), wo, wi, mode, ng_local);
    }

    /// Samples wi from wo with `u` in [0,1)^2 and `u_lobe` in [0,1) choosing the lobe, into
    /// `out`; f is in `mode` (see the contract above). False when the path is absorbed (`out`
    /// is then unspecified). The sample is written where the caller keeps it, field by field,
    /// and never copied as a whole: a copy right after the BSDF's stores reads them back in
    /// wider pieces than they were written, which stalls the CPU (bench/README.md).
    bool sample(const Vec3& wo, const Vec2& u, float u_lobe, BsdfSample& out,
                TransportMode mode = TransportMode::kRadiance,
                const Vec3& ng_local = Vec3(0.0f, 0.0f, 1.0f)) const {
        if (!sample_unscaled(wo, u, u_lobe, out)) return false;
        if (mode == TransportMode::kImportance || out.is_transmission())
            out.f = scale_sample(out.f, out, wo, mode, ng_local);
        return true;
    }

    /// The same sample as an optional: nullopt when the path is absorbed.
    std::optional<BsdfSample> sample(const Vec3& wo, const Vec2& u, float u_lobe,
                                     TransportMode mode = TransportMode::kRadiance,
                                     const Vec3& ng_local = Vec3(0.0f, 0.0f, 1.0f)) const {
        std::optional<BsdfSample> result;
        if (!sample(wo, u, u_lobe, result.emplace(), mode, ng_local)) result.reset();
        return result;
    }

    /// Every delta lobe at wo with its whole weight f |cos wi| (pdf 1), in `mode`; none for a
    /// BSDF without delta lobes. For integrators that follow all specular lobes (Whitted).
    DeltaLobes delta_lobes(const Vec3& wo, TransportMode mode = TransportMode::kRadiance,
                           const Vec3& ng_local = Vec3(0.0f, 0.0f, 1.0f)) const {
        DeltaLobes result;
        if (!(m_flags & kBsdfDelta)) return result;
        result = delta_lobes_unscaled(wo);
        for (int i = 0; i < result.count; ++i) {
            BsdfSample& lobe = result.lobes[i];
            lobe.f = scale_sample(lobe.f, lobe, wo, mode, ng_local);
        }
        return result;
    }

    // Union of the flags of all lobes. A member, set once when the BSDF is built, rather
    // than a virtual call: integrators ask for it at every bounce.
    uint32_t flags() const { return m_flags; }
    bool is_delta() const {
        return (flags() & ~(kBsdfReflection | kBsdfTransmission)) == kBsdfDelta;
    }

    /// Veach's shading-normal correction for importance transport (1997, eq. 5.17):
    /// |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|) with ns = (0, 0, 1); 0 where the denominator
    /// vanishes (a direction in the geometric or the shading plane), where the ratio would
    /// be unbounded. Exactly 1 when ng_local is the shading normal.
    static float shading_correction(const Vec3& wo, const Vec3& wi, const Vec3& ng_local) {
        if (ng_local.x == 0.0f && ng_local.y == 0.0f) return 1.0f;
        const float numerator = std::abs(wo.z) * std::abs(glm::dot(wi, ng_local));
        const float denominator = std::abs(glm::dot(wo, ng_local)) * std::abs(wi.z);
        if (!(denominator > kMinCorrectionDenominator)) return 0.0f;
        return numerator / denominator;
    }

protected:
    // `flags`: the union of the lobes' flags. `eta`: index inside over index outside, for a
    // BSDF that refracts (kBsdfTransmission), so that the wrappers can apply 1/eta^2 to a
    // refracted pair in eval() without asking the BSDF.
    explicit Bsdf(uint32_t flags, float eta = 1.0f) : m_flags(flags), m_eta(eta) {}
    ~Bsdf() = default;  // not virtual: arena objects are never destroyed

    // What each BSDF implements: the mode-independent parts, f without any 1/eta^2.
    virtual Spectrum eval_unscaled(const Vec3& wo, const Vec3& wi) const = 0;
    virtual float pdf_unscaled(const Vec3& wo, const Vec3& wi) const = 0;
    // Writes the sample into `out` and returns true, or returns false when absorbed.
    virtual bool sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                                 BsdfSample& out) const = 0;
    virtual Spectrum eval_pdf_unscaled(const Vec3& wo, const Vec3& wi, float& pdf_out) const {
        pdf_out = pdf_unscaled(wo, wi);
        return eval_unscaled(wo, wi);
    }
    // Only called for BSDFs whose flags include kBsdfDelta; lobes with pdf 1.
    virtual DeltaLobes delta_lobes_unscaled(const Vec3&) const { return {}; }

private:
    // Below this the correction's denominator counts as 0: a float product of two cosines
    // that small is grazing in the geometric or shading plane, and the ratio meaningless.
    static constexpr float kMinCorrectionDenominator = 1e-12f;

    // Each value divided (not multiplied by 1 / eta^2): the dielectrics divided f by eta^2
    // this way before the factor moved here, so radiance values keep their bits.
    static Spectrum divide(const Spectrum& f, float eta2) {
        return f.map([eta2](float v) { return v / eta2; });
    }

    Spectrum scale(const Spectrum& f, const Vec3& wo, const Vec3& wi, TransportMode mode,
                   const Vec3& ng_local) const {
        if (mode == TransportMode::kImportance) return f * shading_correction(wo, wi, ng_local);
        if ((m_flags & kBsdfTransmission) && (wo.z < 0.0f) != (wi.z < 0.0f)) {
            const float eta = wo.z > 0.0f ? m_eta : 1.0f / m_eta;  // n(wi side) / n(wo side)
            return divide(f, eta * eta);
        }
        return f;
    }

    // A sampled lobe knows its own eta.
    static Spectrum scale_sample(const Spectrum& f, const BsdfSample& s, const Vec3& wo,
                                 TransportMode mode, const Vec3& ng_local) {
        if (mode == TransportMode::kImportance) return f * shading_correction(wo, s.wi, ng_local);
        if (s.is_transmission()) return divide(f, s.eta * s.eta);
        return f;
    }

    uint32_t m_flags;
    float m_eta;
};

}  // namespace glint
