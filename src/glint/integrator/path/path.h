#pragma once
// Unidirectional path tracing with next-event estimation, combined with BSDF sampling by
// multiple importance sampling (power heuristic, Veach 1997), and Russian roulette.
#include <glint/integrator/tile/tile_integrator.h>

#include <optional>

namespace glint {

//
// The two single-strategy variants exist to validate the combination: all three must
// converge to the same image (tests/integrator/path/test_path.cpp).
enum class DirectLighting {
    kMis,        // "path": light sampling and BSDF sampling, power heuristic
    kLightOnly,  // "path_light": next-event estimation only (emitters found by BSDF rays ignored)
    kBsdfOnly,   // "path_bsdf": no light sampling; point and spot lights are invisible
};

struct PathPacketTest;  // tests/integrator/path/test_path.cpp

class PathIntegrator final : public TileIntegrator {
public:
    PathIntegrator(const RenderSettings& settings, DirectLighting strategy)
        : TileIntegrator(settings), m_strategy(strategy) {}
    // One path, bounce after bounce: the loop a reader follows (path.cpp).
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;

private:
    // A path between the steps of a bounce.
    struct PathState {
        // Starts a path along a camera ray. Sets every field a path reads before writing
        // it; `si` is left as it was (intersect() writes all of it).
        void start(const Ray& camera_ray, Sampler& path_sampler, AovSample* features) {
            L = Spectrum(0.0f);
            beta = Spectrum(1.0f);
            ray = camera_ray;
            specular_bounce = true;
            bsdf_pdf = 0.0f;
            previous_point = Vec3(0.0f);
            previous_normal = Vec3(0.0f);
            eta_scale = 1.0f;
            sampler = &path_sampler;
            aov = features;
            aov_open = features != nullptr;
            aov_tint = Spectrum(1.0f);
        }

        Spectrum L{0.0f};
        Spectrum beta{1.0f};
        Ray ray;
        bool specular_bounce = true;  // the camera "samples" its ray like a delta lobe
        float bsdf_pdf = 0.0f;
        Vec3 previous_point{0.0f};   // where the last BSDF sample was taken, for MIS
        Vec3 previous_normal{0.0f};  // its shading normal (the light tree's pmf needs it)
        float eta_scale = 1.0f;
        SurfaceInteraction si;  // each bounce's hit, written over the last one's
        const Bsdf* bsdf = nullptr;
        Vec3 wo_local{0.0f};
        Spectrum direct{0.0f};  // light sampling's contribution, if its shadow ray gets through
        Sampler* sampler = nullptr;
        AovSample* aov = nullptr;
        // The features follow perfect specular (delta) bounces to the first diffuse or glossy
        // hit, as OIDN recommends, so that reflections and refractions have features too:
        // open while only delta surfaces were hit, `aov_tint` their albedos' product.
        bool aov_open = false;
        Spectrum aov_tint{1.0f};
    };

    // The steps of one bounce, shared by li() and the packet loop. Those that draw samples
    // take the type of the path's sampler: Sampler, or the final SobolSampler, whose draws
    // the packet loop then makes as direct, inlined calls (path.sampler must be one).
    void escape(const Scene& scene, PathState& path, int depth) const;
    bool scatter_at_hit(const Scene& scene, PathState& path, int depth, Arena& arena) const;
    template <typename SamplerType>
    std::optional<Vec3> sample_light(const Scene& scene, PathState& path) const;
    template <typename SamplerType>
    bool continue_path(PathState& path, int depth) const;

    // The packet form (end of path.cpp): a pixel's samples advance together, one bounce at
    // a time, so that each bounce's rays and then its shadow rays go to Embree as packets.
    // Each sample gets what li() gives it, bit for bit (tests/integrator/path/test_path.cpp).
    struct PacketWorker;
    std::unique_ptr<Worker> make_worker(const Sampler& prototype) const override;
    PixelMoments render_pixel(const Scene& scene, Film& film, Vec2i pixel, Worker& worker,
                              int first, int count) const override;
    void trace_packet(const Scene& scene, PerLane<PathState>& paths, int count, Arena& arena,
                      RayCounter& counter) const;
    template <typename SamplerType>
    void trace_packet_with(const Scene& scene, PerLane<PathState>& paths, int count, Arena& arena,
                           RayCounter& counter) const;

    DirectLighting m_strategy;

    friend struct PathPacketTest;  // tests compare the packet loop with li()
};

}  // namespace glint
