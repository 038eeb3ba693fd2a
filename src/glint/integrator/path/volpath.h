#pragma once
// Volumetric path tracing: the path tracer for scenes with participating media (issue 29).
// The walk carries the medium its ray travels through (the camera's at the start, changed
// where it crosses a surface that bounds media) and samples where the ray first collides
// in it by delta tracking against the medium's majorant (medium/delta_tracking.h). At a
// scattering collision it estimates direct light with the phase function, as at a surface
// with the BSDF; shadow rays cross interfaces and take on each medium's transmittance.
//
// Chromatic media: distances are sampled for one channel, the hero, chosen per path; the
// other channels' densities are carried as ratios r_u to the hero's (pbrt-v4's
// VolPathIntegrator), and every contribution is divided by the ratios' mean, which is the
// balance heuristic over the choice of hero (one-sample MIS): no colour noise from a
// channel whose extinction the hero's distances do not fit. Light sampling and BSDF or
// phase sampling are combined by the balance heuristic too, with the probability that
// delta tracking passes a shadow ray's media in the unidirectional density (r_l).
//
// Without media the walk is path's with balance instead of power heuristic, and without
// path's packets (bench/README.md compares the two).
#include <glint/integrator/tile/tile_integrator.h>

namespace glint {

class VolPathIntegrator final : public TileIntegrator {
public:
    explicit VolPathIntegrator(const RenderSettings& settings) : TileIntegrator(settings) {}
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);

    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

private:
    struct Walk;
    enum class MediumStep { kEnded, kScattered, kCrossed };
    MediumStep scatter_in_medium(const Scene& scene, Walk& walk, float t_hit) const;
    bool scatter_at_surface(const Scene& scene, Walk& walk, Arena& arena) const;
    void escape(const Scene& scene, Walk& walk) const;
};

}  // namespace glint
