#pragma once
// Bidirectional path tracing (Veach and Guibas 1995; Veach 1997, ch. 10): for every camera
// sample a camera subpath and a light subpath, and every way of joining them -- s vertices
// from the light, t from the camera -- weighted by multiple importance sampling
// (bdpt_mis.h) so that each path is counted once:
//   s = 0        the camera subpath reaches a light (an area light, or the environment when
//                it escapes)
//   s = 1        a light point sampled afresh from the camera vertex (next-event estimation,
//                the light chosen by the light sampler)
//   t = 1        a light subpath vertex joined to a point on the lens, splatted to the film
//                position it lands on (light tracing)
//   s, t >= 2    a vertex of each subpath joined by a shadow ray
// It finds what the path tracer finds and what the light tracer finds: caustics of point
// lights seen directly and through glass, mirrors and glass seen directly, lights at infinity,
// and in participating media the volumetric caustics (subpaths scatter in media, subpath.h).
//
// Settings: the common ones (spp, seed, sampler, filter, max_depth: bounces, as the path
// tracer counts them, i.e. s + t - 2 <= max_depth). Each camera sample takes one light
// subpath; the camera-side strategies go to the sample's pixel, the splats are gathered per
// tile and reach the film in tile order, so the image is the same for any thread count.
// `--debug strategies` also returns the weighted image of each (s, t) with s + t <=
// kDebugMaxVertices and one of all longer paths; they sum to the image.
#include <glint/integrator/bidirectional/bdpt_mis.h>
#include <glint/integrator/bidirectional/subpath.h>
#include <glint/integrator/integrator.h>

#include <span>
#include <vector>

namespace glint {

/// What one strategy adds for a pair of subpaths.
struct StrategyContribution {
    Spectrum L{0.0f};     ///< weighted contribution (radiance; for a splat, before the
                          ///< film's splat scale)
    float weight = 0.0f;  ///< its MIS weight (0 when the strategy found nothing)
    bool splat = false;   ///< t = 1: L belongs at `film`, not at the sample's pixel
    Vec2 film{0.0f};      ///< film position of a splat
};

/// Joins the first `s` vertices of `light` and the first `t` of `camera` (t >= 1, s + t >= 2;
/// s = 1 samples a light point afresh, t = 1 a lens point) and weights the result by
/// `heuristic`. Draws first, whatever the outcome: for t = 1 the lens point (2D); else for
/// s = 1 the light point (2D), the light (1D) and its part (1D), in sample_direct_light's
/// order. `scratch` holds the path as the weights see it. `merge_eta` > 0 weights it among
/// the merges of vertex connection and merging too (vcm_strategy_weight); 0 is bdpt.
/// `light_tracing_count` is n_L / n_C, light subpaths per camera subpath (vcm_strategy_weight);
/// the contribution of t = 1 is that of one light subpath either way (the film's splat scale
/// divides by the number of them). `media`: the path sample's media walk, when the subpaths
/// were made with one (their shadow rays then take on the transmittance of the media they
/// cross, drawing from its stream, and the result is divided by the hero channel's MIS
/// denominator, the mean over channels of both subpaths' r_u). `volume_merge_scale` > 0:
/// vertex merging happens at points in media too, with that MisVertex::merge_scale (4 r / 3).
StrategyContribution connect_strategy(const Scene& scene, std::span<const PathVertex> light,
                                      std::span<const PathVertex> camera, int s, int t,
                                      Sampler& sampler, RayCounter& counter, MisHeuristic heuristic,
                                      std::vector<MisVertex>& scratch, float merge_eta = 0.0f,
                                      float light_tracing_count = 1.0f, MediaWalk* media = nullptr,
                                      float volume_merge_scale = 0.0f);

/// The MIS weight of strategy (s, t) for the path made of light[0, s) and camera[0, t), where
/// `sampled` stands for light[0] when s = 1 and t > 1 (the light point chosen by the
/// strategy) and for camera[0] when t = 1 (the lens point chosen by it). `merge_eta` and
/// `light_tracing_count` as for connect_strategy.
float strategy_mis_weight(const Scene& scene, std::span<const PathVertex> light,
                          std::span<const PathVertex> camera, int s, int t,
                          const PathVertex& sampled, MisHeuristic heuristic,
                          std::vector<MisVertex>& scratch, float merge_eta = 0.0f,
                          float light_tracing_count = 1.0f, float volume_merge_scale = 0.0f);

/// The MIS weight (vcm_strategy_weight) of merging light subpath vertex s (a photon, not in
/// `light`: light[0, s) are the vertices before it) with camera vertex t - 1 (t >= 2, s >= 1,
/// a surface that is not purely delta, or a point in a medium with volume_merge_scale > 0), which
/// stands for the photon's position: the path light[0, s), camera[t - 1] ... camera[0]. `merge_eta`
/// = n pi r^2 for n light paths merged per camera path within radius r; `light_tracing_count` as
/// for connect_strategy.
float merge_mis_weight(const Scene& scene, std::span<const PathVertex> light,
                       std::span<const PathVertex> camera, int s, int t, float merge_eta,
                       MisHeuristic heuristic, std::vector<MisVertex>& scratch,
                       float light_tracing_count = 1.0f, float volume_merge_scale = 0.0f);

class BdptIntegrator final : public Integrator {
public:
    /// Strategies with s + t up to this get an image of their own under --debug strategies.
    static constexpr int kDebugMaxVertices = 5;
    /// Subpaths' vertex cap when max_depth is unlimited (-1) and roulette alone ends paths.
    static constexpr int kMaxVertices = 64;

    explicit BdptIntegrator(const RenderSettings& settings);
    /// Reads no settings of its own; throws glint::Error (naming the setting) for adaptive
    /// sampling, which it does not do.
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    /// Light paths splat anywhere on the film: no crop window, no halves. One image per
    /// strategy under --debug strategies.
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities;
        capabilities.debug_views = {{"strategies", "--integrator bdpt"}};
        capabilities.spectral = true;
        capabilities.motion_blur = true;  // one time per camera and light subpath pair
        capabilities.scattering_media = true;
        capabilities.emitting_media = true;  // collected by the camera subpaths (subpath.h)
        return capabilities;
    }

    /// Index of strategy (s, t) among the debug images (the last one holds longer paths),
    /// and the number of those images.
    static int debug_index(int s, int t);
    static int debug_count();

private:
    struct Worker;
    struct TileResult;
    void render_tile(const Scene& scene, Film& film, std::span<Film> strategy_films, int tile,
                     Worker& worker, TileResult& result) const;

    RenderSettings m_settings;
    std::unique_ptr<Filter> m_filter;
    bool m_debug_strategies = false;
    std::optional<WalkMedia> m_media;  // this render's media (walk_media)
};

}  // namespace glint
