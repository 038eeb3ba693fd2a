#pragma once
// Stochastic progressive photon mapping (Hachisuka & Jensen 2009). Each pass traces one
// camera path per pixel to its first non-specular surface (a visible point, with direct
// light by next-event estimation), then a batch of photons; photons near a visible point
// add to its flux, and the search radius shrinks with alpha = 2/3, so the estimate
// converges to the correct image as passes grow. `spp` is the number of passes.
#include <glint/integrator/integrator.h>

namespace glint {

class SppmIntegrator final : public Integrator {
public:
    explicit SppmIntegrator(const RenderSettings& settings) : m_settings(settings) {}
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;

private:
    RenderSettings m_settings;
};

}  // namespace glint
