#pragma once
// Metropolis light transport ("mlt"): multiplexed MLT (Hachisuka, Kaplanyan and Dachsbacher
// 2014) over bidirectional path tracing, in primary sample space (Kelemen et al. 2002).
//
// A state of the chain is a point of the unit hypercube (PssSampler). It picks one path depth
// d (fixed per chain) and, from its connection stream, one of the d + 2 BDPT strategies
// (s, t) that make paths of d + 2 vertices; the strategy's contribution, weighted by its BDPT
// MIS weight and multiplied by d + 2 (the inverse of the probability of picking it), is the
// state's contribution C(u): an unbiased estimate of the whole image from one path. Chains
// of mutations visit states in proportion to its luminance f(u); each mutation splats the
// current and the proposed state's C / f with weights 1 - a and a (the acceptance
// probability; Kelemen's expected values), and the image is b pixels / mutations times the
// splats, with b = sum over depths of E[f] from the bootstrap.
//
// Start-up bias: a chain is only distributed in proportion to f after it has forgotten its
// start. The bootstrap draws `mlt_bootstrap` independent states (a share per depth), whose
// mean f gives b, and starts every chain at one of them chosen in proportion to f: a sample
// of f's distribution (exact as the bootstrap grows), so no mutations are thrown away.
//
// Determinism: bootstrap sample i and chain c each have an RNG keyed by (seed, i) or (seed,
// c); chains run in parallel, each into its own splat buffer, and the buffers reach the film
// in chain order, so the image is the same for any thread count.
#include <glint/integrator/bidirectional/bdpt_mis.h>
#include <glint/integrator/bidirectional/pss_sampler.h>
#include <glint/integrator/bidirectional/subpath.h>
#include <glint/integrator/integrator.h>

#include <vector>

namespace glint {

/// mlt's own settings (glint.render{...} keys).
struct MltSettings {
    int bootstrap = 100000;   ///< mlt_bootstrap: states drawn to estimate b and start chains
    int chains = 1000;        ///< mlt_chains: Markov chains (fewer when mutations are fewer)
    float large_step = 0.3f;  ///< mlt_large_step: probability of a large step
    float sigma = 0.01f;      ///< mlt_sigma: standard deviation of a small step
    /// Reads and validates the keys (errors name the key's file:line).
    static MltSettings read(const Params& params);
};

/// One state's contribution.
struct MltSample {
    Rgb L{0.0f};      ///< C(u): radiance estimate of the whole image (film-normalised, as a light
                      ///< tracer's splat before its scale), MIS-weighted, times d + 2; in the
                      ///< film's colour (spectral mode: read at the state's wavelengths)
    Vec2 film{0.0f};  ///< where it lands on the film (pixels)
};

/// What one thread evaluates states with: scratch memory reused from one state to the next.
struct MltWorkspace {
    Arena arena;
    RayCounter counter;
    std::vector<PathVertex> camera, light;
    std::vector<MisVertex> scratch;
};

class MltIntegrator final : public Integrator {
public:
    /// Path depth (bounces) chains are spread over when max_depth is -1 (unlimited): MLT
    /// needs a finite set of depths to multiplex.
    static constexpr int kDefaultMaxDepth = 10;

    MltIntegrator(const RenderSettings& settings, const MltSettings& mlt);
    /// Reads MltSettings; throws glint::Error (naming the setting) for adaptive sampling or
    /// bad values. The `sampler` and `filter` settings do not apply: the chains make the
    /// samples, and each lands in the pixel that holds it (a box filter).
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities;
        capabilities.motion_blur = true;       // the path's time is a dimension of its state
        capabilities.spectral = true;          // and so is its hero wavelength
        capabilities.scattering_media = true;  // subpaths in media (subpath.h)
        capabilities.emitting_media = true;    // the s = 0 states collect it (evaluate())
        return capabilities;
    }

    /// The contribution of the sampler's current state for paths of `depth` bounces on a
    /// film of `film_size` pixels. Reads, in the connection stream, the strategy (1D), then
    /// connect_strategy's values; in the camera stream the film point (2D), in spectral mode
    /// the hero wavelength (1D), the lens (2D, if the camera has one), with `media` the
    /// media walk's hero channel and stream seed (2 x 1D, start_media_walk), and the camera
    /// subpath; in the light stream the light subpath. `media`: the scene's media for the
    /// subpaths (walk_media), null for none.
    static MltSample evaluate(const Scene& scene, PssSampler& sampler, int depth, Vec2 film_size,
                              MltWorkspace& workspace, bool spectral = false,
                              const WalkMedia* media = nullptr);

    /// Depths chains are spread over: 0 .. max_depth().
    int max_depth() const;

private:
    struct Chain;
    void run_chain(const Scene& scene, int chain, uint64_t mutations, uint64_t start_key, int depth,
                   Vec2 film_size, Chain& result) const;

    RenderSettings m_settings;
    MltSettings m_mlt;
    std::optional<WalkMedia> m_media;  // this render's media (walk_media)
};

}  // namespace glint
