#pragma once
// Radiosity (Goral et al. 1984; Cohen et al. 1988) and the hybrid two-pass method (Wallace,
// Cohen and Greenberg 1987). The diffuse surfaces are meshed and solved once, independently
// of the view (radiosity_solver.h); the image is then a tile render that looks the solution
// up where camera rays land, Gouraud-interpolating the vertex radiosities.
//
// With `hybrid = true` the solution only supplies the diffuse indirect light: a ray-traced
// second pass adds direct light by next-event estimation (exact soft shadows), follows
// mirrors and glass, and adds caustics from a caustic photon map.
#include <glint/integrator/photon/photon.h>
#include <glint/integrator/photon/photon_map.h>
#include <glint/integrator/radiosity/radiosity_mesh.h>
#include <glint/integrator/radiosity/radiosity_solver.h>
#include <glint/integrator/tile/tile_integrator.h>

#include <string>

namespace glint {

/// The settings of "radiosity", from glint.render{...}.
struct RadiosityIntegratorSettings {
    RadiositySettings solve;  ///< meshing and the solve (radiosity_* keys)
    bool hybrid = false;      ///< the two-pass method: radiosity for indirect light only
    /// A file to load the solution from when it exists (validated against the scene), and
    /// to save it to after solving otherwise; empty: none.
    std::string cache;
    CausticSettings caustic;  ///< the hybrid's caustic map (caustic_photons = 0: none)

    /// Reads and validates the keys above; errors name the key's location.
    static RadiosityIntegratorSettings read(const Params& params);
};

class RadiosityIntegrator final : public TileIntegrator {
public:
    RadiosityIntegrator(const RenderSettings& settings,
                        const RadiosityIntegratorSettings& radiosity);
    /// Reads the settings (RadiosityIntegratorSettings; every key, its type, default and
    /// meaning are in docs/integrators.md and docs/scene-language.md): the radiosity_* keys,
    /// hybrid, radiosity_cache and the caustic map's keys; `spp`, `seed` and `max_depth`
    /// from the common settings.
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);

    /// Meshes and solves (or loads the cache), builds the hybrid's caustic map, then renders.
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    /// A tile integrator's, less the crop window (never offered for radiosity).
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities = TileIntegrator::capabilities();
        capabilities.motion_blur = false;  // its photons or radiosity are made at one time
        capabilities.crop_windows = false;
        capabilities.spectral = true;  // solved once per set of wavelengths
        return capabilities;
    }
    /// At the first surface that is not a mirror or glass (followed through them): meshed
    /// surfaces show the interpolated radiosity (plus, in the hybrid, direct light and
    /// caustics, and the radiosity only for the indirect part); surfaces that are not
    /// meshed get direct light and one gathering ray that reads the mesh where it lands.
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

    /// Meshes and solves `scene`, or loads the cache; `quiet` hides the solve's progress.
    /// prepare() calls it before render()'s tiles and before the viewer's first pass.
    void solve(const Scene& scene, bool quiet);
    /// The cache's file: relative to the scene's folder, and inside it unless the scene is
    /// trusted (glint::Error otherwise, naming where the setting came from).
    std::string cache_path(const Scene& scene) const;
    /// The solution (in spectral mode, that of the first set of wavelengths).
    const RadiosityMesh& mesh() const { return m_meshes.front(); }
    const RadiositySolveStats& solve_stats() const { return m_solve_stats; }

protected:
    /// solve(), and the hybrid's caustic map: what every pass reads; returns the photon
    /// rays traced.
    uint64_t prepare(const Scene& scene) override;
    // Spectral mode: each set of wavelengths has a solution of its own, and a camera sample
    // reads the one of its set.
    const WavelengthSets* wavelength_sets() const override { return &m_sets; }

private:
    // Radiance leaving side `side` of the mesh at `at`: the interpolated radiosity (all of
    // it, or without the part the lights gave directly) plus the ambient term, over pi.
    Spectrum mesh_radiance(const RadiosityLocation& at, int side, bool indirect_only) const;
    // Which side of the meshed surface at `at` a ray along `direction` arrives on.
    int side_of(const RadiosityLocation& at, const Vec3& direction) const;
    // Indirect light at an unmeshed surface: one BSDF-sampled ray, whose hit on the mesh
    // gives the radiance that arrives.
    Spectrum gather(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                    Sampler& sampler, RayCounter& counter) const;

    RadiosityIntegratorSettings m_radiosity;
    // The solution the calling thread's path reads: that of its wavelength set.
    const RadiosityMesh& path_mesh() const {
        return m_meshes[static_cast<size_t>(m_sets.active_set())];
    }

    WavelengthSets m_sets;                // spectral mode's sets (RGB: one, no wavelengths)
    std::vector<RadiosityMesh> m_meshes;  // one solution per set
    RadiositySolveStats m_solve_stats;    // summed over the sets
    bool m_loaded = false;                // the solution came from the cache
    bool m_quiet = false;  // the solve's progress hidden (render() follows its Progress)
    PhotonMap m_caustics;
    float m_caustic_radius2 = 0.0f;
};

}  // namespace glint
