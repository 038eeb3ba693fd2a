// The preview's pass with ReSTIR (PreviewIntegrator::render_restir_pass); the plain pass and
// the rest of the preview are in preview.cpp.
#include <glint/integrator/photon/preview_restir.h>
#include <glint/integrator/transport/transport.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

namespace glint {

// A pass with ReSTIR: first every pixel finds its surface (through mirrors and glass), draws
// its light candidates, merges the previous pass's reservoir and gathers everything but
// direct light; then, once all pixels have their reservoirs, every pixel merges its
// neighbours' and shades its final sample with one shadow ray. Each pixel's numbers come
// from (seed, pixel, pass) and the second stage reads only the first's results, so the image
// is the same for any thread count.
void PreviewIntegrator::render_restir_pass(const Scene& scene, Film& film, int pass,
                                           RenderStats& stats) {
    const int w = film.width(), h = film.height();
    RestirState* found = nullptr;
    for (const auto& candidate : m_restir)
        if (candidate->size == Vec2i(w, h) && candidate->origin == film.origin())
            found = candidate.get();
    if (!found) {
        if (m_restir.size() >= 2) m_restir.erase(m_restir.begin());  // the older size
        m_restir.push_back(
            std::make_unique<RestirState>(m_preview.restir, Vec2i(w, h), film.origin()));
        found = m_restir.back().get();
    }
    RestirState& state = *found;
    RestirDi& restir = state.restir;
    restir.begin_pass(scene, w, h, film.origin(), true);
    for (Arena& arena : state.arenas[restir.buffer()]) arena.reset();
    const size_t pixels = static_cast<size_t>(w) * static_cast<size_t>(h);
    state.rest.assign(pixels, Spectrum(0.0f));
    state.beta.assign(pixels, Spectrum(0.0f));
    std::atomic<uint64_t> rays{0};
    const uint64_t pass_key = hash_combine(mix_bits(m_settings.seed), static_cast<uint64_t>(pass));

    tbb::parallel_for(tbb::blocked_range<int>(0, h, 4), [&](const tbb::blocked_range<int>& rows) {
        Arena& arena = state.arenas[restir.buffer()].local();
        Arena scratch;
        RayCounter counter;
        PassSampler sampler;
        sampler.set_seed(m_settings.seed);
        HashGrid::Cache cache;
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < w; ++x) {
                const size_t i =
                    static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
                const Vec2i pixel = film.origin() + Vec2i(x, y);
                const Ray ray = pass_camera_ray(scene, sampler, pixel, pass);
                const SpecularChain chain =
                    follow_specular_chain(scene, ray, Spectrum(1.0f), sampler, arena, counter,
                                          kMaxCameraSegments, nullptr);
                ReuseSurface& surface = restir.surface(x, y);
                surface = ReuseSurface{};
                state.rest[i] = chain.emitted;
                if (chain.escaped) {
                    state.rest[i] += chain.beta * scene.escaped_radiance(chain.ray.direction);
                    continue;
                }
                if (!chain.hit) continue;
                const SurfaceInteraction& si = *chain.hit;
                surface.p = si.p;
                surface.ng = si.ng;
                surface.shading = si.shading;
                surface.wo_local = si.to_local(si.wo);
                surface.bsdf = chain.bsdf;
                surface.time = si.time;
                // The last ray starts at the camera unless a mirror or glass turned it.
                surface.seen_directly = chain.ray.origin == ray.origin;
                surface.depth =
                    glm::length(si.p - chain.ray.origin) +
                    (surface.seen_directly ? 0.0f : glm::length(chain.ray.origin - ray.origin));
                restir.generate(scene, x, y, sampler, counter);
                scratch.reset();
                state.beta[i] = chain.beta;
                state.rest[i] +=
                    chain.beta * indirect_estimate(scene, si, *chain.bsdf, Spectrum(0.0f), sampler,
                                                   scratch, counter, cache);
            }
        }
        rays += counter.rays;
    });

    tbb::parallel_for(tbb::blocked_range<int>(0, h, 4), [&](const tbb::blocked_range<int>& rows) {
        RayCounter counter;
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < w; ++x) {
                const size_t i =
                    static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
                const Vec2i pixel = film.origin() + Vec2i(x, y);
                const uint64_t packed =
                    (static_cast<uint64_t>(static_cast<uint32_t>(pixel.x)) << 32) |
                    static_cast<uint32_t>(pixel.y);
                const Spectrum direct =
                    restir.shade(scene, x, y, hash_combine(pass_key, packed), counter);
                film.add_sample(pixel, state.rest[i] + state.beta[i] * direct, 1.0f, nullptr);
            }
        }
        rays += counter.rays;
    });
    restir.end_pass();
    stats.rays += rays.load();
}

}  // namespace glint
