#pragma once
// The interactive preview with real-time caustics (issue 18). Each pass first traces a
// batch of caustic photons (light - specular+ - first non-specular surface) from every
// light, aimed at mirrors and glass with projection maps, and keeps the last few batches in
// world space; then it traces one camera sample per pixel through mirrors and glass (one
// Fresnel-chosen lobe per interface) to the first non-specular surface, where it adds
// direct light (one light sample and its shadow ray), the caustic photons' density within
// a global radius that shrinks from pass to pass (progressive photon mapping with Knaus and
// Zwicker's radius schedule), and one or more path-traced bounces of indirect light (or, with
// preview_bounces = 0, an ambient term for the light neither of those carries). Direct light
// uses ReSTIR DI (integrator/realtime/restir_di.h) unless preview_restir = "off"; then it is
// one light sample and its shadow ray.
// The film averages the passes, so the image converges while nothing changes; photons
// survive a camera move (they are in world space) and are dropped when a light or an
// object moves. For speed (15 frames per second at 640x480 is the aim) the camera rays of
// 4 x 2 pixel blocks and their shadow rays are traced as Embree packets, the pass draws its
// numbers from a cheap sampler of its own, and the photon grid caches its cells per thread;
// see docs/integrators.md.
#include <glint/integrator/photon/interleaved_fog.h>
#include <glint/integrator/photon/pass_sampler.h>
#include <glint/integrator/photon/photon_map.h>
#include <glint/integrator/photon/photon_tracer.h>
#include <glint/integrator/photon/preview_media.h>
#include <glint/integrator/photon/projection_map.h>
#include <glint/integrator/progressive.h>
#include <glint/integrator/realtime/restir_di.h>
#include <glint/integrator/tile/tile_integrator.h>
#include <glint/integrator/transport/hash_grid.h>
#include <glint/integrator/transport/media.h>

#include <optional>
#include <vector>

namespace glint {

/// The settings of "preview", from glint.render{...}. Its keys carry the prefix so that a
/// scene's settings for photon or sppm (whose `photons` mean far more photons) do not slow
/// the preview down.
struct PreviewSettings {
    int photons = 20000;  ///< caustic photons emitted per pass (>= 0)
    int window = 4;       ///< passes of photons kept and used by every estimate (>= 1)
    /// Radius of the first pass's caustic estimate, in scene units (>= 0); 0 means 1/400 of
    /// the scene's bounding-box diagonal.
    float radius = 0.0f;
    /// Radius of the first pass's volume photon estimate (media), in scene units (>= 0);
    /// 0 means 1/100 of the scene's bounding-box diagonal. It shrinks as `radius` does.
    float volume_radius = 0.0f;
    /// Scale of the ambient term (>= 0; 0 turns it off), an estimate of the light of all
    /// bounces after the first from the lights' power, the scene's size and how closed it
    /// is, plus the constant background for the directions that escape (see restart()).
    /// Used only with bounces = 0: the path-traced bounces carry that light.
    float ambient = 1.0f;
    /// Path-traced bounces of indirect light after the first non-specular surface, each with
    /// next-event estimation (>= 0; 0: the ambient term instead). 0 by default, as
    /// preview_restir is "off": both cost frames per second (docs/integrators.md), and the
    /// viewer's default stays the fast preview until they reach its speed.
    int bounces = 0;
    /// Direct light at the first non-specular surface: preview_restir ("unbiased", "biased",
    /// "off"), preview_restir_candidates (M), preview_restir_spatial (neighbours, 0: none),
    /// preview_restir_temporal.
    RestirSettings restir;
    /// In media that scatter: single scattering along the primary rays estimated in one pixel
    /// of each 2 x 2 block per pass and shared with the neighbours whose rays cross the
    /// medium alike (interleaved_fog.h); false: every pixel estimates its own.
    bool fog_interleave = true;

    /// Reads and validates preview_photons, preview_window, preview_radius,
    /// preview_ambient, preview_bounces, preview_fog_interleave and the preview_restir keys;
    /// errors name the key's location.
    static PreviewSettings read(const Params& params);
};

class PreviewIntegrator final : public Integrator, public ProgressiveIntegrator {
public:
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities;
        // Camera rays, shadow rays and photons carry times; a camera ray gathers photons of
        // every time (an approximation, as the preview is).
        capabilities.motion_blur = true;
        // Each pass carries one set of wavelengths, its camera paths and photons alike.
        capabilities.spectral = true;
        // Single scattering, volumetric caustics and the glow of media seen from the camera
        // (preview_media.h).
        capabilities.scattering_media = true;
        capabilities.emitting_media = true;
        return capabilities;
    }
    PreviewIntegrator(const RenderSettings& settings, const PreviewSettings& preview);
    ~PreviewIntegrator() override;
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);

    /// settings.spp passes into `film`, starting from no photons.
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    /// One photon batch, then one camera sample per pixel (sample index `pass`) added to
    /// `film`; `film` is the average of the passes since it was cleared.
    RenderStats render_pass(const Scene& scene, Film& film, int pass, Progress& progress) override;
    /// A camera change keeps the photons and the radius; any other change drops them.
    void scene_changed(SceneChange change) override;

    /// Where the last pass's time went, in seconds (for bench/preview).
    struct PassTiming {
        double photons = 0.0;  ///< tracing the photon batch and indexing the kept photons
        double camera = 0.0;   ///< camera samples, their shading and the film
    };
    const PassTiming& last_pass_timing() const { return m_timing; }
    /// Caustic photons kept now (the last `window` batches).
    size_t stored_photons() const { return m_grid.size(); }
    /// Photon batches traced since the photons were last dropped.
    int photon_passes() const { return m_photon_passes; }
    /// The radius the next pass's caustic estimate uses (0 before the first pass).
    float radius() const { return m_photon_passes > 0 ? std::sqrt(m_radius2) : 0.0f; }
    /// Volume photons kept now (scenes with media that scatter; see preview_media.h).
    size_t stored_volume_photons() const;
    /// The radius of the volume photons' estimate in the last pass (0 before the first).
    float volume_radius() const { return m_photon_passes > 0 ? std::sqrt(m_volume_radius2) : 0.0f; }

    /// Whether the camera pass traces its rays in packets (the default) or one at a time:
    /// the same image bit for bit, the one-ray form being the plain loop the packet form is
    /// tested against (and what bench/preview compares its speed with).
    void set_packets(bool packets) { m_packets = packets; }

private:
    struct CameraLanes;  // preview.cpp: the per-lane state of a block of pixels
    // The camera passes' packets: blocks of 4 x 2 pixels.
    static constexpr int kBlockWidth = 4, kBlockHeight = 2;
    static_assert(kBlockWidth * kBlockHeight == kPacketWidth);
    struct RestirState;  // preview_restir.h: ReSTIR's buffers and the arenas its BSDFs live in
    struct RestirLanes;  // preview_restir.cpp: the per-lane state of a block's first stage
    // Mirrors and glass a camera path follows before its first diffuse surface, at most.
    static constexpr int kMaxCameraSegments = 16;
    void restart(const Scene& scene);
    // The camera ray of `pixel` (named in the full image) in pass `pass`, with `sampler`
    // started on that pixel sample: its film position, then its lens position.
    static Ray pass_camera_ray(const Scene& scene, PassSampler& sampler, Vec2i pixel, int pass);
    static uint32_t trace_camera_block(const Scene& scene, const Film& film, Vec2i corner, int pass,
                                       PerLane<PassSampler>& samplers, PerLane<Ray>& rays,
                                       PerLane<SurfaceInteraction>& si, uint32_t& hit,
                                       RayCounter& counter);
    void trace_photons(const Scene& scene, RenderStats& stats);
    Spectrum caustic_estimate(const SurfaceInteraction& si, const Bsdf& bsdf,
                              HashGrid::Cache& cache) const;
    Spectrum indirect_estimate(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                               Spectrum reflected, Sampler& sampler, Arena& arena,
                               RayCounter& counter, HashGrid::Cache& cache) const;
    Spectrum bounce_estimate(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                             Sampler& sampler, Arena& arena, RayCounter& counter) const;
    // preview_media.cpp: the preview in media that scatter.
    void trace_photons_in_media(const Scene& scene, const PhotonEmitter& emitter, uint64_t first,
                                uint64_t count, uint64_t seed, int max_bounces,
                                std::vector<Photon>& surface, std::vector<VolumePhoton>& volume,
                                uint64_t& rays) const;
    Spectrum in_scattering(const Scene& scene, const Ray& ray, float t_end, const Medium& medium,
                           Sampler& sampler, Rng& rng, RayCounter& counter) const;
    // A camera path's first traversal, traced with its neighbours' as a packet
    // (Scene::intersect_surface_packet_passing): whether it hit, and where that wrote the
    // surface and the interfaces passed (the path's records from then on).
    struct FirstTraversal {
        bool hit = false;
        SurfaceInteraction* si = nullptr;
        PassedSurfaces* passed = nullptr;
    };
    // Where a camera path in media stopped at its first surface that is not purely
    // specular, so that its direct light is sampled with its neighbours' (their chains of
    // square roots and divisions overlap) and its shadow ray traced with theirs
    // (transmittance_packet): all the path needs to finish as camera_sample_in_media()
    // would have. The surface is the FirstTraversal's.
    struct AwaitedLight {
        bool waiting = false;
        const Medium* medium = nullptr;  // the path's, at the surface
        Rng rng;                         // the path's stream, for grid media's ratio tracking
        Spectrum L{0.0f}, beta{0.0f};
        const SurfaceInteraction* si = nullptr;
        const Bsdf* bsdf = nullptr;
        // Set by sample_awaited_lights:
        Scene::ShadowRay shadow;
        const Medium* shadow_medium = nullptr;  // where the shadow ray starts
        Spectrum contribution{0.0f};            // 0: no light sample
    };
    // With `awaited` (not null) a path that reaches its first surface that is not purely
    // specular returns there with awaited->waiting set; sample_awaited_lights() and then
    // finish_awaited() give its light.
    Spectrum camera_sample_in_media(const Scene& scene, Vec2i pixel, const Ray& camera_ray,
                                    Sampler& sampler, Arena& arena, RayCounter& counter,
                                    HashGrid::Cache& cache, DeferredLeg* deferred,
                                    const FirstTraversal& first,
                                    AwaitedLight* awaited = nullptr) const;
    // The direct light's samples of the `waiting` lanes; returns those that need a shadow
    // ray.
    uint32_t sample_awaited_lights(const Scene& scene, uint32_t waiting,
                                   PerLane<AwaitedLight>& awaited, PerLane<PassSampler>& samplers,
                                   RayCounter& counter) const;
    Spectrum finish_awaited(const Scene& scene, const AwaitedLight& awaited,
                            const Spectrum& transmittance, Sampler& sampler, Arena& arena,
                            RayCounter& counter, HashGrid::Cache& cache) const;
    void render_media_pass(const Scene& scene, Film& film, int pass, uint64_t& rays);
    void render_restir_pass(const Scene& scene, Film& film, int pass, RenderStats& stats);
    // ReSTIR's first stage for the pixels of one row, one at a time, and for one block of
    // 4 x 2 pixels in packets: the same reservoirs and sums bit for bit.
    void restir_first_stage_row(const Scene& scene, const Film& film, int y, int pass,
                                RestirState& state, PassSampler& sampler, Arena& arena,
                                Arena& scratch, RayCounter& counter, HashGrid::Cache& cache) const;
    void restir_first_stage_block(const Scene& scene, const Film& film, Vec2i corner, int pass,
                                  RestirState& state, RestirLanes& lanes, Arena& arena,
                                  Arena& scratch, RayCounter& counter) const;
    Spectrum camera_sample(const Scene& scene, const Ray& ray, Sampler& sampler, Arena& arena,
                           RayCounter& counter, HashGrid::Cache& cache) const;
    void render_block(const Scene& scene, Film& film, Vec2i corner, int pass, CameraLanes& lanes,
                      Arena& arena, RayCounter& counter) const;

    RenderSettings m_settings;
    PreviewSettings m_preview;
    const Scene* m_scene = nullptr;  // the scene the photons were traced in
    std::vector<std::optional<ProjectionMap>> m_projections;  // per light, where supported
    bool m_specular_surfaces = true;  // whether caustic photons can exist (restart())
    // Ambient radiance per unit albedo, as a colour: spectral mode reads it at each pass's
    // wavelengths.
    Rgb m_ambient{0.0f};
    // Spectral mode: the wavelengths of the current pass (its camera paths and its photon
    // batch), and how many passes had theirs since render() began (they stratify the range).
    WavelengthContext m_pass_wavelengths;
    uint32_t m_spectral_passes = 0;
    std::vector<std::vector<Photon>> m_batches;  // the last `window` batches, a ring
    HashGrid m_grid;                // the photons of m_batches, indexed for the current radius
    std::vector<Photon> m_photons;  // the same photons, in m_grid's storage order
    int m_photon_passes = 0;        // batches traced since the restart
    float m_radius2 = 0.0f;         // squared radius of the current pass's estimate
    // Media that scatter (none: the preview ignores media but absorbing glass), their volume
    // photons' batches (a ring as m_batches), their radius, and how this pass sees them.
    std::optional<WalkMedia> m_media;
    // Each light's centre by Light::index, where in-scattering's equiangular sampling aims
    // (none for lights at infinity).
    std::vector<std::optional<Vec3>> m_light_centres;
    std::vector<std::vector<VolumePhoton>> m_volume_batches;
    float m_volume_radius2 = 0.0f;
    VolumePhotonView m_volume_view;
    // The interleaved single scattering of the pass in media, and each pixel's light besides
    // it (and whether its path went through a dispersive event), kept until it is added.
    InterleavedFog m_fog;
    struct PixelRest {
        Spectrum L{0.0f};
        bool hero_only = false;
    };
    std::vector<PixelRest> m_rest;
    PassTiming m_timing;
    bool m_packets = true;
    // ReSTIR's state per film size (at most two: the viewer's reduced first pass after a
    // change must not wipe the full-size passes' history); dropped by restart().
    std::vector<std::unique_ptr<RestirState>> m_restir;
};

}  // namespace glint
