#pragma once
// Photon mapping (Jensen's two-pass method). Pass one traces photons from the lights into
// a caustic map (light - specular+ - diffuse paths, aimed with projection maps) and a
// global map (every diffuse hit). Pass two traces camera rays through specular surfaces
// to the first diffuse hit, where it adds direct light (next-event estimation), the
// caustic map's radiance estimate, and indirect light by final gathering: BSDF-sampled
// rays whose hits are evaluated in the global map. Estimates use the k nearest photons
// with a cone filter, within at most `photon_radius`.
#include <glint/integrator/photon/photon_map.h>
#include <glint/integrator/tile/tile_integrator.h>

namespace glint {

/// The caustic map's settings, shared by "photon" and "whitted" (with caustics = true).
struct CausticSettings {
    int caustic_photons = 100000;  ///< photons emitted for the caustic map (>= 0)
    int photon_neighbours = 50;    ///< photons per radiance estimate (>= 1)
    bool projection_maps = true;   ///< aim caustic photons at specular objects
    /// Largest radius of a radiance estimate, in scene units (>= 0); 0 means 1/20 of the
    /// scene's bounding-box diagonal. Where fewer than photon_neighbours photons lie within
    /// it, the estimate uses the photons there over this radius's disc.
    float photon_radius = 0.0f;
    /// Spectral mode: the sets of wavelengths the maps are traced at, the photons taking
    /// turns, and one per camera sample (transport/wavelength_sets.h) (in [1, 256]).
    int wavelength_sets = kDefaultWavelengthSets;

    /// Reads and validates the keys above; errors name the key's location.
    static CausticSettings read(const Params& params);
};

/// The settings of "photon", from glint.render{...}.
struct PhotonSettings {
    int photons = 100000;  ///< photons emitted for the global map (>= 1)
    int gather_rays = 16;  ///< final-gathering rays per visible point (>= 0)
    CausticSettings caustic;

    /// Reads and validates the keys above; errors name the key's location.
    static PhotonSettings read(const Params& params);
};

// The caustic map alone (light - specular+ - diffuse photons), for any integrator that wants
// photon-mapped caustics; `rays` counts the rays traced.
// In spectral mode its photons carry the wavelengths of `sets` (the camera paths' too).
PhotonMap build_caustic_map(const Scene& scene, const RenderSettings& settings,
                            const CausticSettings& caustic, const WavelengthSets& sets,
                            uint64_t& rays);
// The sets of wavelengths a render with `settings` traces its maps at: `caustic`'s count in
// spectral mode, RGB's one otherwise.
WavelengthSets photon_wavelength_sets(const RenderSettings& settings,
                                      const CausticSettings& caustic);
// The largest search radius (squared) for radiance estimates in `scene`: `photon_radius`,
// or 1/20 of the scene's diagonal when that is 0.
float photon_search_radius2(const Scene& scene, const CausticSettings& caustic);

// The photon maps' debug view: their estimate alone (photon, and whitted's caustics).
inline DebugView photons_debug_view() {
    return {"photons", "--integrator photon (or whitted with caustics = true)"};
}

class PhotonIntegrator final : public TileIntegrator {
public:
    PhotonIntegrator(const RenderSettings& settings, const PhotonSettings& photon);
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities = TileIntegrator::capabilities();
        // Each photon path draws a time of its own, as sppm's do; a camera path gathers
        // photons of every time (docs/scene-language.md, "Motion blur").
        capabilities.motion_blur = true;
        capabilities.spectral = true;  // its maps are traced in sets of wavelengths
        capabilities.debug_views.push_back(photons_debug_view());
        return capabilities;
    }
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

    // Builds both maps (also used by tests); returns the rays traced.
    uint64_t build_maps(const Scene& scene);
    const PhotonMap& caustic_map() const { return m_caustic; }
    const PhotonMap& global_map() const { return m_global; }
    double caustic_photons_per_second() const { return m_caustic_rate; }

private:
    // The passes' photon maps (render() builds them itself, to time them).
    uint64_t prepare(const Scene& scene) override { return build_maps(scene); }
    const WavelengthSets* wavelength_sets() const override { return &m_sets; }
    Spectrum estimate(const PhotonMap& map, const SurfaceInteraction& si, const Bsdf& bsdf) const;
    Spectrum final_gather(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                          Sampler& sampler, Arena& arena, RayCounter& counter) const;

    PhotonSettings m_photon;
    PhotonMap m_caustic;
    PhotonMap m_global;
    WavelengthSets m_sets;  // the maps' wavelengths (spectral mode), made by build_maps()
    float m_max_distance2 = kInfinity;
    bool m_show_photons = false;  // debug view: only the maps' estimate at the first diffuse hit
    double m_caustic_rate = 0.0;
};

}  // namespace glint
