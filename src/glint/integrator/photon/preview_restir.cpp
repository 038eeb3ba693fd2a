// The preview's pass with ReSTIR (PreviewIntegrator::render_restir_pass); the plain pass and
// the rest of the preview are in preview.cpp.
#include <glint/integrator/photon/preview_restir.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <bit>

namespace glint {
namespace {

// A pixel's surface as reuse sees it: the first surface that is not purely specular on its
// camera path, whose last ray started at `last_origin` (the camera's `camera_origin` unless
// a mirror or glass turned the path).
void set_reuse_surface(ReuseSurface& surface, const SurfaceInteraction& si, const Bsdf* bsdf,
                       const Vec3& last_origin, const Vec3& camera_origin) {
    surface.p = si.p;
    surface.ng = si.ng;
    surface.shading = si.shading;
    surface.wo_local = si.to_local(si.wo);
    surface.bsdf = bsdf;
    surface.time = si.time;
    surface.seen_directly = last_origin == camera_origin;
    surface.depth = glm::length(si.p - last_origin) +
                    (surface.seen_directly ? 0.0f : glm::length(last_origin - camera_origin));
}

}  // namespace

// What the lanes of a block carry through its first stage.
struct PreviewIntegrator::RestirLanes {
    PerLane<PassSampler> samplers;
    PerLane<Ray> rays;
    PerLane<SurfaceInteraction> si;
    PerLane<SpecularChain> chains;  // for the lanes whose camera ray met a mirror or glass
    PerLane<Scene::ShadowRay> shadows;
    HashGrid::Cache photon_cache;
};

// The first stage for row y, one pixel at a time: each pixel finds its surface (through
// mirrors and glass), draws its light candidates, merges the previous pass's reservoir and
// gathers everything but direct light. The form the packet form is tested against.
void PreviewIntegrator::restir_first_stage_row(const Scene& scene, const Film& film, int y,
                                               int pass, RestirState& state, PassSampler& sampler,
                                               Arena& arena, Arena& scratch, RayCounter& counter,
                                               HashGrid::Cache& cache) const {
    RestirDi& restir = state.restir;
    const int w = film.width();
    for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
        const Vec2i pixel = film.origin() + Vec2i(x, y);
        const Ray ray = pass_camera_ray(scene, sampler, pixel, pass);
        const SpecularChain chain = follow_specular_chain(
            scene, ray, Spectrum(1.0f), sampler, arena, counter, kMaxCameraSegments, nullptr);
        ReuseSurface& surface = restir.surface(x, y);
        surface = ReuseSurface{};
        state.rest[i] = chain.emitted;
        if (chain.escaped) {
            state.rest[i] += chain.beta * scene.escaped_radiance(chain.ray.direction);
            continue;
        }
        if (!chain.hit) continue;
        const SurfaceInteraction& si = *chain.hit;
        set_reuse_surface(surface, si, chain.bsdf, chain.ray.origin, ray.origin);
        restir.generate(scene, x, y, sampler, counter);
        scratch.reset();
        state.beta[i] = chain.beta;
        state.rest[i] += chain.beta * indirect_estimate(scene, si, *chain.bsdf, Spectrum(0.0f),
                                                        sampler, scratch, counter, cache);
    }
}

// The first stage for the 4 x 2 pixels of the block at `corner`: their camera rays as one
// Embree packet and visibility reuse's shadow rays as another, as render_block() traces the
// plain pass. A camera ray that meets a mirror or glass goes on alone from the camera
// (follow_specular_chain), as there. Each lane takes the one-ray form's steps with the
// same draws from its own sampler, so every pixel gets the same reservoir and sums, bit for
// bit.
void PreviewIntegrator::restir_first_stage_block(const Scene& scene, const Film& film, Vec2i corner,
                                                 int pass, RestirState& state, RestirLanes& lanes,
                                                 Arena& arena, Arena& scratch,
                                                 RayCounter& counter) const {
    RestirDi& restir = state.restir;
    const int w = film.width();
    uint32_t hit = 0;
    const uint32_t active = trace_camera_block(scene, film, corner, pass, lanes.samplers,
                                               lanes.rays, lanes.si, hit, counter);

    PerLane<const SurfaceInteraction*> surface_of{};
    PerLane<const Bsdf*> bsdf_of{};
    uint32_t shading = 0, shadowed = 0;
    for_each_lane(active, [&](int lane) {
        const int x = corner.x + lane % kBlockWidth, y = corner.y + lane / kBlockWidth;
        const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
        ReuseSurface& surface = restir.surface(x, y);
        surface = ReuseSurface{};
        const Ray& ray = lanes.rays[lane];
        if (!(hit & (1u << lane))) {
            state.rest[i] = scene.escaped_radiance(ray.direction);
            return;
        }
        SurfaceInteraction& si = lanes.si[lane];
        Spectrum beta = segment_transmittance(ray, si);
        Spectrum emitted = beta * emitted_radiance(si);
        const Bsdf* bsdf = shade(scene, ray, si, arena);
        const SurfaceInteraction* at = &si;
        Vec3 last_origin = ray.origin;
        if (bsdf && bsdf->is_delta()) {
            // The chain traces and counts the camera ray anew.
            --counter.rays;
            SpecularChain& chain = lanes.chains[lane];
            chain = follow_specular_chain(scene, ray, Spectrum(1.0f), lanes.samplers[lane], arena,
                                          counter, kMaxCameraSegments, nullptr);
            emitted = chain.emitted;
            beta = chain.beta;
            if (chain.escaped) {
                state.rest[i] =
                    chain.emitted + chain.beta * scene.escaped_radiance(chain.ray.direction);
                return;
            }
            bsdf = chain.hit ? chain.bsdf : nullptr;
            if (chain.hit) at = &*chain.hit;
            last_origin = chain.ray.origin;
        }
        state.rest[i] = emitted;
        if (!bsdf) return;
        set_reuse_surface(surface, *at, bsdf, last_origin, ray.origin);
        state.beta[i] = beta;
        surface_of[lane] = at;
        bsdf_of[lane] = bsdf;
        shading |= 1u << lane;
        const std::optional<Scene::ShadowRay> shadow =
            restir.draw_candidates(scene, x, y, lanes.samplers[lane]);
        if (!shadow) return;
        lanes.shadows[lane] = *shadow;
        shadowed |= 1u << lane;
    });
    PerLane<Spectrum> visible;
    if (shadowed != 0) {
        counter.rays += static_cast<uint64_t>(std::popcount(shadowed));
        const PerLane<const Medium*> no_media{};
        const PerLane<Rng*> no_streams{};
        transmittance_packet(scene, lanes.shadows, no_media, no_streams, shadowed, visible);
    }
    for_each_lane(shading, [&](int lane) {
        const int x = corner.x + lane % kBlockWidth, y = corner.y + lane / kBlockWidth;
        const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
        restir.reuse_history(scene, x, y, (shadowed >> lane) & 1u ? visible[lane] : Spectrum(0.0f),
                             lanes.samplers[lane], counter);
        scratch.reset();
        state.rest[i] += state.beta[i] * indirect_estimate(scene, *surface_of[lane], *bsdf_of[lane],
                                                           Spectrum(0.0f), lanes.samplers[lane],
                                                           scratch, counter, lanes.photon_cache);
    });
}

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

    // Rows of blocks, two per task (or 4 rows, one pixel at a time), each task with its
    // samplers and its share of the arenas.
    const int block_rows = (h + kBlockHeight - 1) / kBlockHeight;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, block_rows, 2), [&](const tbb::blocked_range<int>& rows) {
            Arena& arena = state.arenas[restir.buffer()].local();
            Arena scratch;
            RayCounter counter;
            if (m_packets) {
                auto lanes = std::make_unique<RestirLanes>();
                for (PassSampler& sampler : lanes->samplers) sampler.set_seed(m_settings.seed);
                for (int row = rows.begin(); row < rows.end(); ++row)
                    for (int x = 0; x < w; x += kBlockWidth)
                        restir_first_stage_block(scene, film, Vec2i(x, row * kBlockHeight), pass,
                                                 state, *lanes, arena, scratch, counter);
            } else {
                PassSampler sampler;
                sampler.set_seed(m_settings.seed);
                HashGrid::Cache cache;
                for (int y = rows.begin() * kBlockHeight;
                     y < std::min(h, rows.end() * kBlockHeight); ++y)
                    restir_first_stage_row(scene, film, y, pass, state, sampler, arena, scratch,
                                           counter, cache);
            }
            rays += counter.rays;
        });

    tbb::parallel_for(tbb::blocked_range<int>(0, h, 4), [&](const tbb::blocked_range<int>& rows) {
        RayCounter counter;
        // Each pixel's neighbours are drawn from a key of its own (the same for any threads).
        auto key_of = [&](int x, int y) {
            const Vec2i pixel = film.origin() + Vec2i(x, y);
            const uint64_t packed = (static_cast<uint64_t>(static_cast<uint32_t>(pixel.x)) << 32) |
                                    static_cast<uint32_t>(pixel.y);
            return hash_combine(pass_key, packed);
        };
        // The neighbours are drawn this many pixels ahead, so that their loads are under way
        // when the pixel is shaded.
        constexpr int kAhead = 8;
        RestirDi::SpatialDraw draws[kAhead];
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < std::min(w, kAhead); ++x)
                restir.draw_neighbours(x, y, key_of(x, y), draws[x]);
            for (int x = 0; x < w; ++x) {
                const size_t i =
                    static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
                const Vec2i pixel = film.origin() + Vec2i(x, y);
                RestirDi::SpatialDraw& draw = draws[x % kAhead];
                const Spectrum direct = restir.shade(scene, x, y, draw, counter);
                if (x + kAhead < w)
                    restir.draw_neighbours(x + kAhead, y, key_of(x + kAhead, y), draw);
                film.add_sample(pixel, state.rest[i] + state.beta[i] * direct, 1.0f, nullptr);
            }
        }
        rays += counter.rays;
    });
    restir.end_pass();
    stats.rays += rays.load();
}

}  // namespace glint
