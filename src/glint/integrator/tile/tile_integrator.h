#pragma once
// The tile integrator: the tile loop, sampling and film handling shared by every
// integrator that estimates radiance per camera ray; subclasses supply li().
#include <glint/integrator/integrator.h>
#include <glint/integrator/transport/wavelength_sets.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

// An integrator that estimates radiance along camera rays independently per pixel sample:
// the tile loop, sampling and film handling live here; subclasses supply li().
// Every tile integrator also renders pass by pass, for the viewer (ProgressiveIntegrator,
// integrator/progressive.h).
class TileIntegrator : public Integrator, public ProgressiveIntegrator {
public:
    explicit TileIntegrator(const RenderSettings& settings);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    /// Pixel by pixel: a crop window alone, adaptive sampling, the film's halves, and the
    /// sobel edge mask.
    IntegratorCapabilities capabilities() const override;

    /// Adds sample `pass` of every pixel of `film`'s window, drawn from the sampler
    /// render() uses (made for settings.spp samples per pixel, so passes 0 .. spp - 1 into
    /// a cleared film give render()'s image bit for bit). Adaptive sampling does not apply:
    /// every pass is uniform. Throws glint::Error unless 0 <= pass < settings.spp. State the
    /// passes share (photon maps) is made by prepare() before the first pass and again after
    /// scene_changed(SceneChange::lights_or_objects).
    RenderStats render_pass(const Scene& scene, Film& film, int pass, Progress& progress) override;
    /// Adds samples [first, end) of every pixel of `film`'s window, drawn from the sampler
    /// render() uses (made for settings.spp samples per pixel), for a partial render: films
    /// of ranges that cover [0, spp) add up (Film::add_sums_image) to render()'s film bit
    /// for bit, since the film's sums are exact. Every pixel gets the same samples (no
    /// adaptive sampling). Throws glint::Error unless 0 <= first <= end <= settings.spp.
    RenderStats render_samples(const Scene& scene, Film& film, int first, int end,
                               Progress& progress);
    void scene_changed(SceneChange change) override;

    // Radiance arriving along `ray`. When `aov` is not null, fills first-hit features.
    virtual Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                        RayCounter& counter, AovSample* aov) const = 0;

protected:
    // Makes what every pixel of a render of `scene` reads besides the scene (photon maps)
    // and returns the rays that took; render() and the first pass call it. Nothing by default.
    virtual uint64_t prepare(const Scene& scene) {
        (void)scene;
        return 0;
    }

    // In spectral mode, the sets of wavelengths that what prepare() made is known at (photon
    // maps, a radiosity solution): each camera sample then carries one of these sets
    // (transport/wavelength_sets.h) instead of wavelengths of its own. Null by default.
    virtual const WavelengthSets* wavelength_sets() const { return nullptr; }

    // render() after prepare(): the tile loop over `film`'s window, for debug views that
    // render a second image from what prepare() made.
    RenderStats render_tiles(const Scene& scene, Film& film, Progress& progress);
    // Such a debug view: renders `film`'s window again, into a film of its own, with `view`
    // (the integrator's flag that switches its estimate to the view's) set for that render,
    // and adds the image's luminance to `stats` as the channel `name`, with the rays.
    void add_luminance_view(const Scene& scene, const Film& film, bool& view,
                            const std::string& name, RenderStats& stats);

    // What one thread renders pixels with: its sampler, scratch memory for BSDFs, and the
    // rays it traced. An integrator that needs more per thread derives from it and makes
    // its own in make_worker().
    struct Worker {
        virtual ~Worker() = default;
        std::unique_ptr<Sampler> sampler;
        Arena arena;
        RayCounter counter;
    };
    virtual std::unique_ptr<Worker> make_worker(const Sampler& prototype) const;

    // Sums of the luminance of a pixel's samples and of its square (for error estimates).
    struct PixelMoments {
        double sum = 0.0, sum_squares = 0.0;
    };
    // A pixel sample's start: `sampler` positioned on sample `index` of `pixel`, its filter
    // sample and its camera ray (the draws every tile integrator makes first, in this order).
    struct CameraSample {
        FilterSample filter;
        Ray ray;
    };
    CameraSample start_camera_sample(const Scene& scene, Vec2i pixel, int index,
                                     Sampler& sampler) const;
    // Adds sample `index` of `pixel` (its radiance, and features or null) to the film and
    // to `moments`; the index's parity chooses the film's half.
    static void record_sample(Film& film, Vec2i pixel, int index, const Spectrum& L,
                              float filter_weight, const AovSample* aov, PixelMoments& moments);

    // Renders samples [first, first + count) of `pixel` into `film`: li() for one sample
    // after the other. An integrator may override it to trace a pixel's samples together
    // (the path tracer's packets); each sample must still get what li() gives it.
    virtual PixelMoments render_pixel(const Scene& scene, Film& film, Vec2i pixel, Worker& worker,
                                      int first, int count) const;

    // Runs `work(pixel, worker)` for every pixel of `film`'s window (pixel in image
    // coordinates) for which `wanted` (indexed by the window's row-major pixel index) is
    // true, in parallel tiles, with one Worker per task made from `prototype`; returns the
    // rays traced.
    template <typename Work>
    uint64_t for_each_pixel(const Film& film, const Sampler& prototype, Progress& progress,
                            const std::vector<uint8_t>* wanted, Work&& work) const;
    // How many pixels away the adaptive mode's decisions reach: a crop window is rendered
    // this much wider (within the image), so that its pixels are the full render's.
    int adaptive_reach() const;
    void render_window(const Scene& scene, Film& film, Progress& progress,
                       RenderStats& stats) const;

    void render_uniform(const Scene& scene, Film& film, Progress& progress,
                        RenderStats& stats) const;
    void render_edge_adaptive(const Scene& scene, Film& film, Progress& progress,
                              RenderStats& stats) const;
    void render_variance_adaptive(const Scene& scene, Film& film, Progress& progress,
                                  RenderStats& stats) const;

    RenderSettings m_settings;
    std::unique_ptr<Filter> m_filter;

private:
    bool m_prepared = false;  // prepare() ran for the scene the passes render
};

// Inline: called for every sample.
inline TileIntegrator::CameraSample TileIntegrator::start_camera_sample(const Scene& scene,
                                                                        Vec2i pixel, int index,
                                                                        Sampler& sampler) const {
    sampler.start_pixel_sample(pixel, index);
    CameraSample sample;
    sample.filter = m_filter->sample(sampler.get_pixel_2d());
    const Vec2 film_point = Vec2(pixel) + Vec2(0.5f) + sample.filter.offset;
    sample.ray = scene.camera().sample_ray(film_point, sampler);
    return sample;
}

inline void TileIntegrator::record_sample(Film& film, Vec2i pixel, int index, const Spectrum& L,
                                          float filter_weight, const AovSample* aov,
                                          PixelMoments& moments) {
    film.add_sample(pixel, L, filter_weight, aov, index);
    const double y = L.is_finite() ? L.luminance() : 0.0;
    moments.sum += y;
    moments.sum_squares += y * y;
}

}  // namespace glint
