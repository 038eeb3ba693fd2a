#pragma once
// Photon tracing shared by the photon-mapping integrators: photons leave the lights in
// proportion to power and bounce through the scene; every non-specular hit is handed to a
// sink. Photons are split into fixed chunks, each traced sequentially with its own sink,
// and the sinks come back in chunk order, so results do not depend on the thread count.
#include <glint/core/arena.h>
#include <glint/core/cancel.h>
#include <glint/core/rng.h>
#include <glint/core/secondary_wavelengths.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/transport/light_path_start.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/wavelength_sets.h>
#include <glint/material/material.h>

#include <tbb/parallel_for.h>

#include <functional>
#include <optional>
#include <vector>

namespace glint {

struct PhotonHit {
    const SurfaceInteraction* si;
    const Bsdf* bsdf;
    Vec3 wi;         // unit, from the surface back towards where the photon came from
    Spectrum power;  // power of the photon (already divided by the light selection pmf)
    int bounces;     // scattering events before this hit (0: straight from the light)
    bool caustic;    // every earlier scattering event was specular (and there was one)
    int set = 0;     // the wavelength set it carries (use_wavelength_sets; 0 in RGB mode)
};

// How a chosen light emits a photon; the default is Light::sample_le.
using PhotonEmitter =
    std::function<std::optional<LightEmission>(const Light&, const Vec2&, const Vec2&, float)>;

class PhotonTracer {
public:
    // With `caustic_paths_only`, a photon ends at its first surface that is not purely
    // specular, after the sink has seen it: what a caustic map keeps is all it traces (the
    // photons up to there are the same as without it, keyed by their index).
    PhotonTracer(const Scene& scene, int max_bounces, PhotonEmitter emitter = {},
                 bool caustic_paths_only = false)
        : m_scene(scene),
          m_max_bounces(max_bounces),
          m_emitter(std::move(emitter)),
          m_caustic_paths_only(caustic_paths_only) {}

    // Spectral mode: the photons traced from now on carry `wavelengths` (those of the camera
    // points they will meet); nullptr for RGB mode. The context must outlive the tracing.
    void use_wavelengths(const WavelengthContext* wavelengths) { m_wavelengths = wavelengths; }
    // Spectral mode for prepared maps: photon i carries the wavelengths of set
    // sets.set_of_particle(i), and says so in its hits; nullptr (or RGB sets) for none. The
    // sets must outlive the tracing.
    void use_wavelength_sets(const WavelengthSets* sets) {
        m_sets = sets != nullptr && sets->spectral() ? sets : nullptr;
    }

    // Traces photons [first, first + count); photon i is keyed by (seed, i). `make_sink()`
    // makes the sink of each chunk; the sinks come back in chunk order.
    template <typename MakeSink>
    auto trace(uint64_t first, uint64_t count, uint64_t seed, uint64_t& rays,
               MakeSink&& make_sink) const {
        constexpr uint64_t kChunk = 2048;
        const uint64_t chunks = (count + kChunk - 1) / kChunk;
        std::vector<decltype(make_sink())> sinks;
        sinks.reserve(chunks);
        for (uint64_t c = 0; c < chunks; ++c) sinks.push_back(make_sink());
        std::atomic<uint64_t> total_rays{0};
        tbb::parallel_for(uint64_t{0}, chunks, [&](uint64_t chunk) {
            throw_if_cancelled();  // emission reports no progress: SIGINT stops it here
            std::optional<WavelengthScope> wavelengths;
            if (m_wavelengths != nullptr) wavelengths.emplace(*m_wavelengths);
            Arena arena;
            uint64_t chunk_rays = 0;
            const uint64_t end = std::min(count, (chunk + 1) * kChunk);
            for (uint64_t i = chunk * kChunk; i < end; ++i) {
                trace_one(first + i, seed, arena, sinks[chunk], chunk_rays);
            }
            total_rays += chunk_rays;
        });
        rays += total_rays.load();
        return sinks;
    }

private:
    template <typename Sink>
    void trace_one(uint64_t index, uint64_t seed, Arena& arena, Sink& sink, uint64_t& rays) const {
        std::optional<WavelengthScope> set_wavelengths;
        const int set = m_sets != nullptr ? m_sets->set_of_particle(index) : 0;
        if (m_sets != nullptr) set_wavelengths.emplace((*m_sets)[set]);
        std::optional<SecondaryWavelengthsScope> terminated;  // this photon's, in spectral mode
        if (m_wavelengths != nullptr || m_sets != nullptr) terminated.emplace();
        Rng rng(hash_combine(mix_bits(seed ^ 0x5bd1e995u), index));
        LightPathSamples u_start;
        u_start.u_light = rng.next_float();
        const Vec2 u1(rng.next_float(), rng.next_float());
        const Vec2 u2(rng.next_float(), rng.next_float());
        u_start.u_position = u1;
        u_start.u_direction = u2;
        u_start.u_select = rng.next_float();
        // One time per photon path, uniform over the shutter, only when the scene moves (so
        // still scenes keep their photons bit for bit).
        if (m_scene.camera().time_sampled())
            u_start.time = m_scene.camera().time_of_sample(rng.next_float());
        const std::optional<LightPathStart> start =
            m_emitter ? start_light_path(m_scene, u_start, m_emitter)
                      : start_light_path(m_scene, u_start);
        if (!start || start->beta.is_black()) return;
        Spectrum beta = start->beta;
        Ray ray = start->emission.ray;
        bool specular_only = true;
        for (int bounces = 0; bounces <= m_max_bounces; ++bounces) {
            arena.reset();
            ++rays;
            std::optional<SurfaceInteraction> hit = m_scene.intersect(ray);
            if (!hit) return;
            SurfaceInteraction& si = *hit;
            beta *= segment_transmittance(ray, si);
            const Bsdf* bsdf = shade(m_scene, ray, si, arena);
            if (!bsdf) return;
            const Vec3 wi = -glm::normalize(ray.direction);
            if (!bsdf->is_delta()) {
                sink.store(
                    PhotonHit{&si, bsdf, wi, beta, bounces, specular_only && bounces > 0, set});
                if (m_caustic_paths_only) return;
            }
            if (bounces == m_max_bounces) return;

            // A photon carries power: the BSDF in importance mode is the adjoint (no 1/eta^2
            // through refraction) with the shading-normal correction, wo towards the light.
            // A direction that disagrees with the geometric surface ends the photon, as it
            // ends every other walk (see sample_scattering).
            const Vec2 u(rng.next_float(), rng.next_float());
            const std::optional<Scattering> scattering = sample_scattering(
                si, *bsdf, si.to_local(wi), u, rng.next_float(), TransportMode::kImportance);
            if (!scattering) return;
            const BsdfSample& bs = scattering->sample;
            const Spectrum next = beta * bs.f * (abs_cos_theta(bs.wi) / bs.pdf);
            float survive;
            if (!survives_power_roulette(
                    next.max_value() / beta.max_value(), [&] { return rng.next_float(); }, survive))
                return;
            beta = next / survive;
            specular_only = specular_only && bs.is_delta();
            continue_ray(ray, si, *scattering);
        }
    }

    const Scene& m_scene;
    int m_max_bounces;
    PhotonEmitter m_emitter;
    bool m_caustic_paths_only;
    const WavelengthContext* m_wavelengths = nullptr;
    const WavelengthSets* m_sets = nullptr;
};

}  // namespace glint
