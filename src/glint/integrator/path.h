#pragma once
// Unidirectional path tracing with next-event estimation, combined with BSDF sampling by
// multiple importance sampling (power heuristic, Veach 1997), and Russian roulette.
#include <glint/integrator/integrator.h>

namespace glint {

class PathIntegrator final : public TileIntegrator {
public:
    explicit PathIntegrator(const RenderSettings& settings) : TileIntegrator(settings) {}
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;
};

}  // namespace glint
