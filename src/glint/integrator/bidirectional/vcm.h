#pragma once
// Vertex connection and merging (Georgiev, Křivánek, Davidovič and Slusallek 2012, "Light
// transport simulation with vertex connection and merging"): bidirectional path tracing
// (bdpt.h) and progressive photon mapping in one estimator, weighted by one multiple
// importance sampling (bdpt_mis.h, vcm_strategy_weight).
//
// Each iteration (spp of them):
//   1. n_L light subpaths (subpath.h; n_L = vcm_light_paths, by default one per pixel); each
//      joins the lens (t = 1, splatted), and its vertices on surfaces that are not purely
//      delta are kept as photons in a hash grid;
//   2. one camera subpath per pixel, which does what bdpt's camera side does with one light
//      subpath (s = 0, s = 1, s, t >= 2: vertex connection; pixel j takes light subpath
//      j mod n_L), and at every vertex that is not purely delta gathers the photons of all
//      n_L light subpaths within the radius r_i (vertex merging: a density estimate with the
//      constant kernel 1 / (n_L pi r^2)).
// The MIS counts follow n_L (bdpt_mis.h): merges weigh eta = n_L pi r^2 against a
// connection's 1, light tracing n_L / n_C against the camera's strategies (n_C pixels).
// More light subpaths than pixels buy denser photons and more light tracing for caustics
// that only merging (or the lens joins) sample well, at the cost of the light pass.
// Merging finds what no connection can: paths with a delta vertex on each side of a diffuse
// one, such as the caustic of a point light through glass seen in a mirror. It is biased (the
// kernel blurs over the disc); the radius shrinks as r_i = r_0 i^((alpha - 1) / 2) so the
// bias vanishes as iterations grow, and the weights leave merging little where connections
// do well.
//
// The light subpaths of an iteration are traced in chunks of pixels, their splats added in
// chunk order; camera subpaths in tiles. The image is the same for any thread count.
#include <glint/integrator/integrator.h>

namespace glint {

class Cluster;

/// The settings of "vcm", from glint.render{...}. `spp` is the number of iterations, each
/// with `light_paths` light subpaths and one camera subpath per pixel.
struct VcmSettings {
    /// Most light subpaths per iteration (they are all held in memory at once).
    static constexpr int kMaxLightPaths = 1 << 24;

    float radius = 0.0f;         ///< initial merging radius r_0 (scene units); 0: 1/256 of the
                                 ///< diagonal of the scene's bounding box (sppm's default)
    float alpha = 0.75f;         ///< radius reduction: r_i = r_0 i^((alpha - 1) / 2), in (0, 1]
    int light_paths = 0;         ///< n_L, light subpaths per iteration in [1, kMaxLightPaths];
                                 ///< 0: one per pixel (width x height)
    bool volume_merging = true;  ///< in scenes with media, merge at points in media too
                                 ///< (the fog seen through glass; docs/integrators.md)

    /// Reads and validates "vcm_radius", "vcm_alpha", "vcm_light_paths" and
    /// "vcm_volume_merging"; errors name the key's location.
    static VcmSettings read(const Params& params);
};

class VcmIntegrator final : public Integrator {
public:
    /// Subpaths' vertex cap when max_depth is unlimited (-1) and roulette alone ends paths.
    static constexpr int kMaxVertices = 64;

    /// Throws glint::Error (naming the setting) for a bad filter or sampler name or for
    /// adaptive sampling, which it does not do.
    VcmIntegrator(const RenderSettings& settings, const VcmSettings& vcm);
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities;
        capabilities.spectral = true;
        capabilities.motion_blur = true;       // one time per camera and light subpath pair
        capabilities.scattering_media = true;  // joins in media; merges on surfaces only
        capabilities.emitting_media = true;    // collected by the camera subpaths (subpath.h)
        return capabilities;
    }

    /// For an MPI job: each rank traces a share of every iteration's light subpaths, and the
    /// ranks exchange them (SubpathCodec) so that each merges and joins with all of them;
    /// every rank renders the whole camera pass, and its film is the one process's, bit for
    /// bit (docs/cluster.md).
    bool share_work(Cluster& cluster) override {
        m_cluster = &cluster;
        return true;
    }

    /// The merging radius of iteration `iteration` (0-based) from r_0 and alpha.
    static float radius_at(float r0, float alpha, int iteration);

private:
    struct Iteration;
    void trace_light_chunk(const Scene& scene, const Film& film, Iteration& it, int chunk) const;
    // Gives every rank the light subpaths and splats the others traced this iteration, and
    // adds all the splats to `film` in subpath order.
    void exchange_light_subpaths(const Scene& scene, Film& film, Iteration& it) const;
    void render_tile(const Scene& scene, Film& film, const Iteration& it, int tile) const;

    RenderSettings m_settings;
    VcmSettings m_vcm;
    std::unique_ptr<Filter> m_filter;
    Cluster* m_cluster = nullptr;
};

}  // namespace glint
