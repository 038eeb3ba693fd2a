#pragma once
// Stochastic progressive photon mapping (Hachisuka & Jensen 2009). Each pass traces one
// camera path per pixel to its first non-specular surface (a visible point, with direct
// light by next-event estimation), then a batch of photons; photons near a visible point
// add to its flux, and the search radius shrinks with alpha = 2/3, so the estimate
// converges to the correct image as passes grow. `spp` is the number of passes.
#include <glint/integrator/integrator.h>

namespace glint {

/// The settings of "sppm", from glint.render{...}. `spp` is the number of passes.
struct SppmSettings {
    int photons = 100000;        ///< photons per pass (>= 1)
    float photon_radius = 0.0f;  ///< initial search radius; 0 = 1/256 of the scene's size
    int intermediate = 0;        ///< also write the image every N passes (0 = never)

    /// Reads and validates the keys above; errors name the key's location.
    static SppmSettings read(const Params& params);
};

class SppmIntegrator final : public Integrator {
public:
    SppmIntegrator(const RenderSettings& settings, const SppmSettings& sppm)
        : m_settings(settings), m_sppm(sppm) {}
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    /// Each pixel sums the photons' flux in photon order, and the photons do not depend
    /// on the window: a crop window renders alone.
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities;
        capabilities.crop_windows = true;
        capabilities.motion_blur = true;  // visible points and photons each carry a time
        capabilities.spectral = true;     // each pass has its own wavelengths
        return capabilities;
    }
    /// Every rank finds all visible points (camera rays are few next to the photons) and
    /// traces its share of each pass's photons; the ranks all-gather the photons' deposits
    /// and add them in photon order, so every rank updates every pixel as one process does.
    bool share_work(Cluster& cluster) override {
        m_cluster = &cluster;
        return true;
    }

private:
    RenderSettings m_settings;
    SppmSettings m_sppm;
    Cluster* m_cluster = nullptr;
};

}  // namespace glint
