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
// A scene without media (no glint.medium) is rendered by path itself, packets and all: the
// same image bit for bit, at path's speed (the walk here would give the same image up to
// noise, with balance instead of power heuristic, one path at a time).
#include <glint/integrator/path/path.h>
#include <glint/integrator/tile/tile_integrator.h>

namespace glint {

class VolPathIntegrator final : public TileIntegrator {
public:
    explicit VolPathIntegrator(const RenderSettings& settings)
        : TileIntegrator(settings), m_path(settings, DirectLighting::kMis) {}
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);

    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    RenderStats render_pass(const Scene& scene, Film& film, int pass, Progress& progress) override;
    void scene_changed(SceneChange change) override;
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities = TileIntegrator::capabilities();
        capabilities.scattering_media = true;
        capabilities.emitting_media = true;
        return capabilities;
    }

    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

private:
    struct Walk;
    enum class MediumStep { kEnded, kScattered, kCrossed };
    MediumStep scatter_in_medium(const Scene& scene, Walk& walk, float t_hit) const;
    MediumStep collide(const Scene& scene, Walk& walk, float t, const MediumPoint& point,
                       const Spectrum& sigma_maj, const Spectrum& T) const;
    void scatter_by_phase(const Scene& scene, Walk& walk, const Vec3& p) const;
    bool scatter_at_surface(const Scene& scene, Walk& walk, Arena& arena) const;
    void escape(const Scene& scene, Walk& walk) const;

    PathIntegrator m_path;  // renders scenes without media
};

}  // namespace glint
