#pragma once
// Unidirectional path tracing with next-event estimation, combined with BSDF sampling by
// multiple importance sampling (power heuristic, Veach 1997), and Russian roulette.
#include <glint/integrator/integrator.h>

namespace glint {

//
// The two single-strategy variants exist to validate the combination: all three must
// converge to the same image (tests/integrator/test_path.cpp).
enum class DirectLighting {
    kMis,        // "path": light sampling and BSDF sampling, power heuristic
    kLightOnly,  // "path_light": next-event estimation only (emitters found by BSDF rays ignored)
    kBsdfOnly,   // "path_bsdf": no light sampling; point and spot lights are invisible
};

class PathIntegrator final : public TileIntegrator {
public:
    PathIntegrator(const RenderSettings& settings, DirectLighting strategy)
        : TileIntegrator(settings), m_strategy(strategy) {}
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

private:
    DirectLighting m_strategy;
};

}  // namespace glint
