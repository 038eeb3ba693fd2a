#pragma once
// Light tracing (particle tracing; Arvo and Kirk 1990, Dutré et al. 1993, Veach 1997 sec.
// 10.2): paths start at the lights, scatter through the scene in importance mode, and at
// every non-specular vertex connect to the camera's lens (Camera::sample_wi); what gets
// through is splatted to the film position the connection lands on.
//
// It finds the light a camera path cannot: a caustic from a point light seen directly (light
// -> glass -> diffuse surface -> camera), which path tracing can only reach by hitting a point
// light with a BSDF-sampled ray, i.e. never. It cannot see what only a camera path finds:
// mirrors and glass seen directly (a specular vertex cannot connect to the lens), and lights
// at infinity seen directly. The image converges to the path tracer's wherever every light
// path that reaches the pixel has a non-specular vertex last.
//
// spp counts light paths per pixel: width x height x spp paths in all. Paths are split into
// fixed chunks, each traced with its own random numbers keyed by (seed, path index), and
// the chunks' splats reach the film in chunk order, so the image is the same for any thread
// count.
//
// In participating media (glint.medium) the particle samples its distances by delta
// tracking, as volpath does, and every real scattering in a medium is a vertex that
// connects to the lens too: light -> glass -> fog -> camera is the volumetric caustic that
// camera paths find only by chance. A light starts in the medium around it
// (medium_containing). Glowing media start light paths too (MediumEmitters), chosen against
// the lights by power: the glowing point connects to the lens, then the particle leaves it
// in a uniform direction and scatters on as any other.
#include <glint/core/medium.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/transport/medium_emitters.h>

#include <optional>
#include <vector>

namespace glint {

class LightTracer final : public Integrator {
public:
    explicit LightTracer(const RenderSettings& settings);
    // Reads no settings of its own: spp, seed and max_depth are the common ones.
    static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Params& params);
    RenderStats render(const Scene& scene, Film& film, Progress& progress) override;
    IntegratorCapabilities capabilities() const override {
        IntegratorCapabilities capabilities;
        capabilities.spectral = true;
        capabilities.motion_blur = true;  // each path carries its time
        capabilities.scattering_media = true;
        capabilities.emitting_media = true;  // glowing media start light paths
        capabilities.glow_needs_shape = true;
        return capabilities;
    }

private:
    struct Chunk;
    struct Particle;
    enum class MediumEvent { kCrossed, kScattered, kEnded };
    void trace_path(const Scene& scene, uint64_t index, Chunk& chunk) const;
    void start_in_glowing_medium(const Scene& scene, float u_region, const Vec3& u_point,
                                 const Vec2& u_direction, const Vec2& u_lens, float time,
                                 Particle& particle, Chunk& chunk) const;
    void walk(const Scene& scene, Particle& particle, Chunk& chunk) const;
    MediumEvent through_medium(const Scene& scene, Particle& particle, float t_hit,
                               Chunk& chunk) const;
    void connect_to_camera(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                           const Particle& particle, const Vec2& u_lens, Chunk& chunk) const;
    void connect_light_to_camera(const Scene& scene, const LightEmission& emission,
                                 const Light& light, float light_pmf, const Medium* medium,
                                 const Vec2& u_lens, Chunk& chunk) const;

    RenderSettings m_settings;
    // Whether the scene has media (the walks then carry theirs), and the medium each light
    // sits in, by Light::index.
    bool m_with_media = false;
    std::vector<const Medium*> m_light_media;
    // The glowing media light paths start in, and the share of paths that start there (the
    // rest leave the lights); none without such media.
    std::optional<MediumEmitters> m_glow;
    float m_glow_share = 0.0f;
};

}  // namespace glint
