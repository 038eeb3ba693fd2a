#pragma once
// Unidirectional path tracing with next-event estimation, combined with BSDF sampling by
// multiple importance sampling (power heuristic, Veach 1997), and Russian roulette.
#include <glint/integrator/integrator.h>

#include <optional>

namespace glint {

//
// The two single-strategy variants exist to validate the combination: all three must
// converge to the same image (tests/integrator/test_path.cpp).
enum class DirectLighting {
    kMis,        // "path": light sampling and BSDF sampling, power heuristic
    kLightOnly,  // "path_light": next-event estimation only (emitters found by BSDF rays ignored)
    kBsdfOnly,   // "path_bsdf": no light sampling; point and spot lights are invisible
};

class PathIntegrator final : public TileIntegrator {
public:
    PathIntegrator(const RenderSettings& settings, DirectLighting strategy)
        : TileIntegrator(settings), m_strategy(strategy) {}
    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                RayCounter& counter, AovSample* aov) const override;
    void li_packet(const CameraPacket& packet, const Scene& scene, Arena& arena,
                   RayCounter& counter, PerLane<Spectrum>& radiance) const override;

private:
    struct Path;

    static uint32_t trace_paths(const Scene& scene, PerLane<Path>& paths, uint32_t active,
                                bool coherent, RayCounter& counter);
    void escape(const Scene& scene, Path& path, int depth) const;
    bool scatter_at_hit(const Scene& scene, Path& path, int depth, Arena& arena) const;
    std::optional<Vec3> sample_light(const Scene& scene, Path& path) const;
    bool continue_path(Path& path, int depth) const;

    DirectLighting m_strategy;
};

}  // namespace glint
