#pragma once
// Classic recursive ray tracing (Whitted 1980): direct light from every light at each
// non-specular hit (stratified shadow rays for area lights, hence soft shadows), an
// ambient term, optional photon-mapped caustics, and exact recursion into mirror reflection and
// refraction, weighted by Fresnel, with total internal reflection and Beer absorption. No indirect
// diffuse light.
// Glass branches in two at every hit, so a closed glass object would cost 2^max_depth rays per
// camera sample: each camera sample may trace kWhittedRayBudget rays through mirrors and glass,
// after which every hit follows its strongest lobe only (see whitted.cpp).
#include <glint/integrator/photon/photon.h>
#include <glint/integrator/photon/photon_map.h>
#include <glint/integrator/tile/tile_integrator.h>

namespace glint {

/// Rays one whitted camera sample may trace through mirrors and glass before it stops
/// branching: past it, a delta hit follows only its strongest lobe (largest weight).
inline constexpr int kWhittedRayBudget = 1024;

/// The settings of "whitted", from glint.render{...}.
struct WhittedSettings {
    SceneColor ambient;              ///< ambient light, times the surface albedo (>= 0)
    int shadow_samples = 4;          ///< N in [1, 64]: area lights get N x N stratified shadow rays
    bool penumbra_shortcut = false;  ///< test 4 rays first; full set only in the penumbra
    bool caustics = false;           ///< add photon-mapped caustics (see CausticSettings)
    CausticSettings caustic;         ///< caustic_photons, photon_neighbours, projection_maps,
                                     ///< photon_radius

    /// Reads and validates the keys above; errors name the key's location.
    static WhittedSettings read(const Params& params);
};

class WhittedIntegrator final : public TileIntegrator {
public:
    WhittedIntegrator(const RenderSettings& settings, const WhittedSettings& whitted);
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    // With `caustics = true`, builds a caustic photon map first and adds its estimate at
    // every diffuse hit: the caustics a classic ray tracer cannot find on its own.
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities = TileIntegrator::capabilities();
        capabilities.debug_views.push_back(photons_debug_view());
        return capabilities;
    }
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

    // Direct light from one area light through N x N stratified shadow rays; with the
    // penumbra shortcut, the four corner strata decide first whether the point is in the
    // umbra (all blocked: black) or fully lit (all clear: no more shadow rays).
    Spectrum area_light_direct(const Scene& scene, const Light& light, const SurfaceInteraction& si,
                               const Bsdf& bsdf, const Vec3& wo_local, const Vec2& rotation,
                               RayCounter& counter) const;

private:
    // Checks max_depth and builds the caustic map (caustics = true).
    uint64_t prepare(const Scene& scene) override;
    // The caustic map's sets, with caustics = true: each sample reads the map at one set.
    const WavelengthSets* wavelength_sets() const override {
        return m_whitted.caustics ? &m_sets : nullptr;
    }
    // Radiance along `ray`, recursing into delta lobes. `budget` is what is left of the
    // camera sample's kRayBudget: each call takes one, and once none is left a delta hit
    // follows only its strongest lobe (see whitted.cpp).
    Spectrum trace(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                   RayCounter& counter, AovSample* aov, int depth, int& budget) const;
    Spectrum direct(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                    Sampler& sampler, RayCounter& counter) const;

    WhittedSettings m_whitted;
    int m_max_depth;
    PhotonMap m_caustics;
    WavelengthSets m_sets;  // the caustic map's wavelengths (spectral mode)
    float m_caustic_radius2 = 0.0f;
    bool m_show_photons = false;  // debug view: only the caustic map's estimate at diffuse hits
};

}  // namespace glint
