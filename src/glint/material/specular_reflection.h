#pragma once
// A perfect mirror with a tint (a delta lobe, two-sided).
#include <glint/material/bsdf.h>

namespace glint {

class SpecularReflectionBsdf final : public Bsdf {
public:
    explicit SpecularReflectionBsdf(const Spectrum& tint)
        : Bsdf(kBsdfReflection | kBsdfDelta), m_tint(tint) {}

protected:
    Spectrum eval_unscaled(const Vec3&, const Vec3&) const override { return Spectrum(0.0f); }
    float pdf_unscaled(const Vec3&, const Vec3&) const override { return 0.0f; }
    bool sample_unscaled(const Vec3& wo, const Vec2&, float, BsdfSample& out) const override {
        if (wo.z == 0.0f) return false;
        out = mirror(wo);
        return true;
    }
    DeltaLobes delta_lobes_unscaled(const Vec3& wo) const override {
        DeltaLobes lobes;
        if (wo.z != 0.0f && !m_tint.is_black()) lobes.add(mirror(wo));
        return lobes;
    }

private:
    BsdfSample mirror(const Vec3& wo) const {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        return BsdfSample{m_tint / abs_cos_theta(wi), wi, 1.0f, kBsdfReflection | kBsdfDelta, 1.0f};
    }

    Spectrum m_tint;
};

}  // namespace glint
