#include <glint/core/cancel.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/integrator/bidirectional/bdpt.h>
#include <glint/integrator/bidirectional/mlt.h>
#include <glint/integrator/transport/camera_connection.h>
#include <glint/integrator/transport/spectral_model.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <optional>

namespace glint {
namespace {

// Chains run in parallel before their splats reach the film, in chain order: bounds the
// splats held at once, independently of the thread count.
constexpr int kChainsPerBatch = 64;

// Keys of the RNGs: bootstrap sample i and chain c draw from disjoint families.
uint64_t bootstrap_key(uint64_t seed, uint64_t i) {
    return hash_combine(mix_bits(seed ^ 0x4d4c5442u), i);
}
uint64_t chain_key(uint64_t seed, uint64_t c) {
    return hash_combine(mix_bits(seed ^ 0x4d4c5443u), c);
}

// The target function the chains sample: the luminance of the contribution, 0 for
// anything not finite (which the chain must never move to).
float target(const Rgb& L) {
    const float f = L.luminance();
    return std::isfinite(f) && f > 0.0f ? f : 0.0f;
}

Splat splat_of(Vec2 film, const Rgb& rgb) {
    Splat splat;
    splat.film = film;
    splat.rgb = rgb;
    return splat;
}

}  // namespace

// One chain's splats, in the order it made them, and the rays it traced.
struct MltIntegrator::Chain {
    std::vector<Splat> splats;
    uint64_t rays = 0;
};

MltSettings MltSettings::read(const Params& p) {
    MltSettings s;
    s.bootstrap = p.get_int("mlt_bootstrap", s.bootstrap);
    s.chains = p.get_int("mlt_chains", s.chains);
    s.large_step = p.get_float("mlt_large_step", s.large_step);
    s.sigma = p.get_float("mlt_sigma", s.sigma);
    if (s.bootstrap < 1) p.fail_at("mlt_bootstrap", "'mlt_bootstrap' must be at least 1");
    if (s.chains < 1) p.fail_at("mlt_chains", "'mlt_chains' must be at least 1");
    if (!(s.large_step > 0.0f && s.large_step <= 1.0f))
        p.fail_at("mlt_large_step", "'mlt_large_step' must be in (0, 1]");
    if (!(s.sigma > 0.0f && s.sigma <= 1.0f))
        p.fail_at("mlt_sigma", "'mlt_sigma' must be in (0, 1]");
    return s;
}

MltIntegrator::MltIntegrator(const RenderSettings& settings, const MltSettings& mlt)
    : m_settings(settings), m_mlt(mlt) {
    refuse_adaptive_sampling(settings, "mlt");
}

std::unique_ptr<Integrator> MltIntegrator::create(const RenderSettings& settings,
                                                  const Params& params) {
    return std::make_unique<MltIntegrator>(settings, MltSettings::read(params));
}

int MltIntegrator::max_depth() const {
    return m_settings.max_depth >= 0 ? m_settings.max_depth : kDefaultMaxDepth;
}

MltSample MltIntegrator::evaluate(const Scene& scene, PssSampler& sampler, int depth,
                                  Vec2 film_size, MltWorkspace& ws, bool spectral,
                                  const WalkMedia* media) {
    MltSample result;
    const int strategies = depth + 2;
    sampler.set_stream(PssSampler::kConnectionStream);
    const int s = std::min(static_cast<int>(sampler.get_1d() * strategies), strategies - 1);
    const int t = strategies - s;

    sampler.set_stream(PssSampler::kCameraStream);
    const Vec2 u_film = sampler.get_2d();
    const Vec2 film_point = u_film * film_size;
    // Spectral mode: the hero wavelength is one more dimension of the state, so that
    // mutations explore the spectrum as they explore paths; the contribution is read in the
    // film's colour while its wavelengths are active.
    std::optional<WavelengthContext> context;
    std::optional<WavelengthScope> wavelengths;
    std::optional<SecondaryWavelengthsScope> terminated;
    if (spectral) {
        context = wavelengths_at(sampler.get_1d());
        wavelengths.emplace(*context);
        terminated.emplace();
    }
    const Ray ray = scene.camera().sample_ray(film_point, sampler);
    ws.arena.reset();
    // In media the hero channel and the tracking stream's seed are dimensions of the state
    // too (a mutation of the seed draws a new stream: those steps are large ones).
    std::optional<MediaWalk> media_walk = start_media_walk(media, sampler);
    MediaWalk* const walk = media_walk ? &*media_walk : nullptr;
    // The glow of emitting media along the camera subpath belongs to the s = 0 strategy: no
    // other strategy makes those paths. The emitting point counts as a vertex, as in volpath
    // and bdpt (glow after k scatterings is a path of k + 1 bounces): depth d takes the
    // segment after d - 1 scattering vertices, and depth 0 none.
    if (walk) walk->emission_depth = s == 0 && depth > 0 ? depth - 1 : MediaWalk::kNoDepth;
    // No roulette: the depth is fixed, and roulette would only add variance.
    generate_camera_subpath(scene, ray, sampler, ws.arena, ws.counter, WalkLimits{t, false},
                            ws.camera, walk);
    ws.light.clear();
    // s = 1 with t > 1 samples its light point afresh in connect_strategy.
    if (s > 1 || (s == 1 && t == 1)) {
        sampler.set_stream(PssSampler::kLightStream);
        generate_light_subpath(scene, ray.time, sampler, ws.arena, ws.counter, WalkLimits{s, false},
                               ws.light, walk);
    }
    sampler.set_stream(PssSampler::kConnectionStream);
    const StrategyContribution c =
        connect_strategy(scene, ws.light, ws.camera, s, t, sampler, ws.counter,
                         MisHeuristic::kBalance, ws.scratch, 0.0f, 1.0f, walk);
    const Spectrum L = walk ? c.L + walk->emitted : c.L;
    if (L.is_black()) return result;
    result.L = to_rgb(L * static_cast<float>(strategies));
    result.film = c.splat ? c.film : film_point;
    return result;
}

RenderStats MltIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    check_camera_motion_joinable(scene, "mlt", m_settings.where_of("integrator"));
    m_media = walk_media(scene);
    const WalkMedia* const media = m_media ? &*m_media : nullptr;
    const Vec2 film_size(static_cast<float>(film.width()), static_cast<float>(film.height()));
    const uint64_t pixels = static_cast<uint64_t>(film.width()) * film.height();
    const uint64_t mutations = pixels * static_cast<uint64_t>(m_settings.spp);
    const int depths = max_depth() + 1;
    RenderStats stats;

    // Bootstrap: the same number of states per depth, sample i at depth i % depths.
    const uint64_t per_depth =
        (static_cast<uint64_t>(m_mlt.bootstrap) + depths - 1) / static_cast<uint64_t>(depths);
    const uint64_t n_bootstrap = per_depth * depths;
    std::vector<float> weights(n_bootstrap);
    std::atomic<uint64_t> rays{0};
    tbb::parallel_for(tbb::blocked_range<uint64_t>(0, n_bootstrap, 256),
                      [&](const tbb::blocked_range<uint64_t>& range) {
                          throw_if_cancelled();  // the bootstrap has no progress of its own
                          MltWorkspace ws;
                          for (uint64_t i = range.begin(); i != range.end(); ++i) {
                              PssSampler sampler(bootstrap_key(m_settings.seed, i), m_mlt.sigma,
                                                 m_mlt.large_step);
                              sampler.start_iteration();
                              weights[i] =
                                  target(evaluate(scene, sampler, static_cast<int>(i % depths),
                                                  film_size, ws, m_settings.spectral, media)
                                             .L);
                          }
                          rays += ws.counter.rays;
                      });
    stats.rays = rays.load();
    // b = sum over depths of E[f at that depth]: each depth's mean is its sum / per_depth.
    // Summed in index order, in double, so b is the same for any thread count.
    std::vector<double> cdf(n_bootstrap);
    double sum = 0.0;
    for (uint64_t i = 0; i < n_bootstrap; ++i) {
        sum += weights[i];
        cdf[i] = sum;
    }
    const double b = sum / static_cast<double>(per_depth);
    stats.notes.push_back(fmt::format("mlt: b = {:.6g} from {} bootstrap samples", b, n_bootstrap));
    if (!(b > 0.0) || mutations == 0) {
        stats.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return stats;
    }
    // Every splat is C / f times its weight; mutations splat a weight of 1 in all, and a pixel
    // holds its share of b pixels (see the header).
    film.set_splat_scale(b * static_cast<double>(pixels) / static_cast<double>(mutations));

    const uint64_t chains = std::min<uint64_t>(m_mlt.chains, mutations);
    for (uint64_t first = 0; first < chains; first += kChainsPerBatch) {
        const uint64_t batch = std::min<uint64_t>(kChainsPerBatch, chains - first);
        std::vector<Chain> results(batch);
        tbb::parallel_for(uint64_t{0}, batch, [&](uint64_t k) {
            const uint64_t c = first + k;
            // The chain's start: a bootstrap state chosen in proportion to f, with the chain's
            // own RNG; mutations shared out as evenly as they go.
            Rng rng(chain_key(m_settings.seed, c), 1);
            const double u = rng.next_double() * sum;
            const uint64_t i = std::min<uint64_t>(
                std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin(), n_bootstrap - 1);
            const uint64_t count = mutations / chains + (c < mutations % chains ? 1 : 0);
            run_chain(scene, static_cast<int>(c), count, bootstrap_key(m_settings.seed, i),
                      static_cast<int>(i % depths), film_size, results[k]);
            progress.advance(count);
        });
        for (const Chain& chain : results) {
            film.add_splats(chain.splats);
            stats.rays += chain.rays;
        }
    }
    stats.samples = mutations;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

void MltIntegrator::run_chain(const Scene& scene, int chain, uint64_t mutations, uint64_t start_key,
                              int depth, Vec2 film_size, Chain& result) const {
    MltWorkspace ws;
    // The bootstrap sample's state, made again from its key (the same values, so the same
    // contribution), then the chain's own random numbers from there on.
    PssSampler sampler(start_key, m_mlt.sigma, m_mlt.large_step);
    sampler.start_iteration();
    const WalkMedia* const media = m_media ? &*m_media : nullptr;
    MltSample current = evaluate(scene, sampler, depth, film_size, ws, m_settings.spectral, media);
    sampler.accept();
    sampler.reseed(chain_key(m_settings.seed, static_cast<uint64_t>(chain)));
    float f_current = target(current.L);
    result.splats.reserve(2 * mutations);
    for (uint64_t m = 0; m < mutations; ++m) {
        sampler.start_iteration();
        const MltSample proposed =
            evaluate(scene, sampler, depth, film_size, ws, m_settings.spectral, media);
        const float f_proposed = target(proposed.L);
        // A chain that starts at f = 0 (only when b is 0, which renders nothing) moves on.
        const float a = f_current > 0.0f ? std::min(1.0f, f_proposed / f_current) : 1.0f;
        // Kelemen's expected values: both states get their share of this step, whichever
        // the chain keeps.
        if (a > 0.0f && f_proposed > 0.0f)
            result.splats.push_back(splat_of(proposed.film, proposed.L * (a / f_proposed)));
        if (a < 1.0f && f_current > 0.0f)
            result.splats.push_back(splat_of(current.film, current.L * ((1.0f - a) / f_current)));
        if (sampler.uniform() < a) {
            sampler.accept();
            current = proposed;
            f_current = f_proposed;
        } else {
            sampler.reject();
        }
    }
    result.rays = ws.counter.rays;
}

}  // namespace glint
