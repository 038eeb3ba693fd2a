#include <glint/cluster/cluster.h>
#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/progress.h>
#include <glint/core/rng.h>
#include <glint/integrator/bidirectional/bdpt.h>
#include <glint/integrator/bidirectional/subpath_exchange.h>
#include <glint/integrator/bidirectional/vcm.h>
#include <glint/integrator/transport/camera_connection.h>
#include <glint/integrator/transport/hash_grid.h>
#include <glint/integrator/transport/spectral_model.h>
#include <glint/material/material.h>
#include <glint/medium/henyey_greenstein.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <tuple>

namespace glint {
namespace {

constexpr int kCameraTileSize = 16;
// Light subpaths per chunk: the unit of parallel work of the light pass and of the fixed
// order in which its splats reach the film.
constexpr int kLightPathsPerChunk = 256;
// The light subpaths take their random numbers from a sampler of their own, seeded apart
// from the camera's, so that the two subpaths of a pixel are independent.
constexpr uint64_t kLightSeedSalt = 0x56434d4c49474854ULL;

// A photon: vertex `vertex` (>= 1) of light subpath `path`. The grid keeps a copy of its
// position, so that a gather rejects the photons outside its disc without reaching for the
// vertex (a cache miss each: the vertices are large and scattered over the subpaths).
struct PhotonRef {
    uint32_t path;
    uint32_t vertex;
};

}  // namespace

// What the passes of one iteration share.
struct VcmIntegrator::Iteration {
    int index = 0;
    float radius = 0.0f;
    float eta = 0.0f;                  // n_L pi r^2: the merges' count against a connection's 1
    float merge_scale = 0.0f;          // the kernel over the light subpaths: 1 / (n_L pi r^2)
    float light_tracing_count = 1.0f;  // n_L / n_C: light tracing's count (bdpt_mis.h)
    WalkLimits camera_limits, light_limits;
    const Sampler* camera_sampler = nullptr;  // prototypes
    const Sampler* light_sampler = nullptr;
    std::vector<std::vector<PathVertex>> light_paths;  // n_L of them
    std::vector<float> light_times;                    // each light path's scene time
    const WalkMedia* media = nullptr;                  // the scene's, null for none
    // Merging at points in media (with media only): the light vertices there, their grid,
    // MisVertex::merge_scale there (4 r / 3) and the ball's kernel 1 / (n_L 4/3 pi r^3).
    std::vector<PhotonRef> volume_photons;
    HashGrid volume_grid;
    float volume_merge_scale = 0.0f;
    float volume_kernel = 0.0f;
    // This process's light subpaths [first_light, end_light) (all of them but in an MPI
    // job), traced in chunks of kLightPathsPerChunk from first_light on.
    size_t first_light = 0, end_light = 0;
    std::vector<Arena> arenas;               // per chunk: the light BSDFs
    std::vector<std::vector<Splat>> splats;  // per chunk
    std::vector<Arena> received_arenas;      // per rank: BSDFs of received subpaths
    std::vector<PhotonRef> photons;          // the light vertices merges use, in the grid
    HashGrid grid;
    mutable std::atomic<uint64_t> rays{0};
    Progress* progress = nullptr;
};

VcmSettings VcmSettings::read(const Params& p) {
    VcmSettings s;
    s.radius = p.get_float("vcm_radius", s.radius);
    s.alpha = p.get_float("vcm_alpha", s.alpha);
    s.light_paths = p.get_int("vcm_light_paths", s.light_paths);
    s.volume_merging = p.get_bool("vcm_volume_merging", s.volume_merging);
    if (!(s.radius >= 0.0f && s.radius <= 1e12f))
        p.fail_at("vcm_radius", "'vcm_radius' must be in [0, 1e12] (0: from the scene's size)");
    if (!(s.alpha > 0.0f && s.alpha <= 1.0f))
        p.fail_at("vcm_alpha", "'vcm_alpha' must be in (0, 1] (1 keeps the radius fixed)");
    if (s.light_paths < 0 || s.light_paths > VcmSettings::kMaxLightPaths)
        p.fail_at("vcm_light_paths",
                  fmt::format("'vcm_light_paths' must be in [0, {}] (0: one per pixel)",
                              VcmSettings::kMaxLightPaths));
    return s;
}

VcmIntegrator::VcmIntegrator(const RenderSettings& settings, const VcmSettings& vcm)
    : m_settings(settings), m_vcm(vcm) {
    blame_setting(settings, "filter",
                  [&] { m_filter = make_filter(settings.filter, settings.filter_radius); });
    blame_setting(settings, "sampler",
                  [&] { make_sampler(settings.sampler, settings.spp, settings.seed); });
    refuse_adaptive_sampling(settings, "vcm");
}

std::unique_ptr<Integrator> VcmIntegrator::create(const RenderSettings& settings,
                                                  const Params& params) {
    return std::make_unique<VcmIntegrator>(settings, VcmSettings::read(params));
}

float VcmIntegrator::radius_at(float r0, float alpha, int iteration) {
    return r0 * std::pow(static_cast<float>(iteration + 1), 0.5f * (alpha - 1.0f));
}

RenderStats VcmIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    check_camera_motion_joinable(scene, "vcm", m_settings.where_of("integrator"));
    const std::optional<WalkMedia> media = walk_media(scene);
    const int w = film.width(), h = film.height();
    const size_t pixels = static_cast<size_t>(w) * h;
    const size_t n_light = m_vcm.light_paths > 0 ? static_cast<size_t>(m_vcm.light_paths) : pixels;
    // Every light subpath of an iteration is kept for the merges: at least its light vertex
    // and its first hit, and the grid's entry for each. Checked before anything is
    // allocated, so that too many paths for this machine is a clear error, not a failed
    // allocation halfway through.
    constexpr uint64_t kLeastVerticesPerPath = 2;
    check_memory(static_cast<uint64_t>(n_light) *
                     (sizeof(std::vector<PathVertex>) +
                      kLeastVerticesPerPath * (sizeof(PathVertex) + 2 * sizeof(uint32_t))),
                 fmt::format("vcm's {} light subpaths per iteration ({})", n_light,
                             m_vcm.light_paths > 0 ? "vcm_light_paths" : "one per pixel"));
    // A light subpath's splat is an estimate of the whole image as one light path per pixel
    // would make it (the lens importance is normalised over the frame, camera.h): n_L of them
    // per iteration make pixels / n_L of that image each. With n_L = pixels the scale is
    // 1 / spp (exactly: both roundings are of the same quotient), as bdpt's.
    film.set_splat_scale(static_cast<double>(pixels) /
                         (static_cast<double>(n_light) * m_settings.spp));
    const SceneStats& scene_stats = scene.stats();
    const float scene_size =
        scene_stats.bounds.is_empty() ? 1.0f : glm::length(scene_stats.bounds.extent());
    const float r0 = m_vcm.radius > 0.0f ? m_vcm.radius : scene_size / 256.0f;
    const auto camera_sampler = make_sampler(m_settings.sampler, m_settings.spp, m_settings.seed);
    const auto light_sampler = make_sampler(m_settings.sampler, m_settings.spp,
                                            mix_bits(m_settings.seed ^ kLightSeedSalt));
    const int max_depth = m_settings.max_depth;

    Iteration it;
    // Paths of at most max_depth bounces: max_depth + 2 vertices, as bdpt's.
    it.camera_limits = WalkLimits{max_depth >= 0 ? max_depth + 2 : kMaxVertices, true};
    it.light_limits = WalkLimits{max_depth >= 0 ? max_depth + 1 : kMaxVertices, true};
    it.camera_sampler = camera_sampler.get();
    it.light_sampler = light_sampler.get();
    it.light_tracing_count =
        static_cast<float>(static_cast<double>(n_light) / static_cast<double>(pixels));
    it.light_paths.resize(n_light);
    it.media = media ? &*media : nullptr;
    it.light_times.assign(n_light, 0.0f);
    std::tie(it.first_light, it.end_light) =
        m_cluster ? m_cluster->share(n_light) : std::pair<uint64_t, uint64_t>{0, n_light};
    if (m_cluster) it.received_arenas.resize(static_cast<size_t>(m_cluster->size()));
    const size_t own_lights = it.end_light - it.first_light;
    const int chunks =
        static_cast<int>((own_lights + kLightPathsPerChunk - 1) / kLightPathsPerChunk);
    it.arenas.resize(chunks);
    it.splats.resize(chunks);
    it.progress = &progress;
    const int tiles_x = (w + kCameraTileSize - 1) / kCameraTileSize,
              tiles_y = (h + kCameraTileSize - 1) / kCameraTileSize;
    RenderStats stats;
    std::vector<Vec3> positions;  // of it.photons
    for (int iteration = 0; iteration < m_settings.spp; ++iteration) {
        it.index = iteration;
        it.radius = radius_at(r0, m_vcm.alpha, iteration);
        const double area = kPi * static_cast<double>(it.radius) * it.radius;
        it.eta = static_cast<float>(static_cast<double>(n_light) * area);
        it.merge_scale = static_cast<float>(1.0 / (static_cast<double>(n_light) * area));
        if (it.media && m_vcm.volume_merging) {
            const double volume = 4.0 / 3.0 * area * it.radius;
            it.volume_merge_scale = 4.0f / 3.0f * it.radius;
            it.volume_kernel = static_cast<float>(1.0 / (static_cast<double>(n_light) * volume));
        }

        tbb::parallel_for(0, chunks, [&](int chunk) { trace_light_chunk(scene, film, it, chunk); });
        if (m_cluster) {
            exchange_light_subpaths(scene, film, it);
        } else {
            for (std::vector<Splat>& splats : it.splats) film.add_splats(splats);
        }

        // The photons in subpath order, vertex order within a subpath.
        it.photons.clear();
        positions.clear();
        for (size_t i = 0; i < n_light; ++i) {
            const std::vector<PathVertex>& path = it.light_paths[i];
            for (size_t v = 1; v < path.size(); ++v) {
                if (path[v].is_surface() && path[v].connectible()) {
                    it.photons.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(v)});
                    positions.push_back(path[v].p);
                }
            }
        }
        it.grid.build(positions, it.radius);
        if (it.volume_merge_scale > 0.0f) {
            it.volume_photons.clear();
            positions.clear();
            for (size_t i = 0; i < n_light; ++i) {
                const std::vector<PathVertex>& path = it.light_paths[i];
                for (size_t v = 1; v < path.size(); ++v) {
                    if (!path[v].is_medium()) continue;
                    it.volume_photons.push_back(
                        {static_cast<uint32_t>(i), static_cast<uint32_t>(v)});
                    positions.push_back(path[v].p);
                }
            }
            it.volume_grid.build(positions, it.radius);
        }

        tbb::parallel_for(0, tiles_x * tiles_y,
                          [&](int tile) { render_tile(scene, film, it, tile); });
        stats.samples += pixels;
    }
    stats.rays = it.rays.load();
    stats.notes.push_back(
        fmt::format("vcm: {} light subpaths per iteration, merging radius {:.4g} at the first "
                    "iteration, {:.4g} at the last",
                    n_light, r0, radius_at(r0, m_vcm.alpha, m_settings.spp - 1)));
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

// Spectral mode: every path of an iteration carries the same wavelengths, since each camera
// subpath joins light vertices traced by other threads and merges with many of them; the
// iterations' wavelengths differ and stratify the spectrum (pass_wavelengths), so the image
// still integrates over it.

// The light subpaths of one chunk, and their joins to the lens (t = 1). Light subpath i draws
// from the light sampler at (pixel (i mod width, i div width), iteration) -- rows past the
// image's last stand for the subpaths beyond one per pixel; the sampler keys on the pixel
// alone, so they are as independent as those of real pixels: the subpath (subpath.h), then a
// lens point (2D) per strategy (s, 1), s = 1, 2, ...
void VcmIntegrator::trace_light_chunk(const Scene& scene, const Film& film, Iteration& it,
                                      int chunk) const {
    const int w = film.width();
    const size_t begin = it.first_light + static_cast<size_t>(chunk) * kLightPathsPerChunk;
    const size_t end = std::min(it.end_light, begin + kLightPathsPerChunk);
    const int max_depth = m_settings.max_depth;
    const WavelengthContext iteration_wavelengths =
        pass_wavelengths(mix_bits(m_settings.seed ^ 0x7c3a1u), static_cast<uint32_t>(it.index));
    std::optional<WavelengthScope> wavelengths;
    if (m_settings.spectral) wavelengths.emplace(iteration_wavelengths);
    auto sampler = it.light_sampler->clone();
    Arena& arena = it.arenas[chunk];
    arena.reset();  // the BSDFs of this chunk's subpaths live until the camera pass is done
    std::vector<Splat>& splats = it.splats[chunk];
    splats.clear();
    RayCounter counter;
    std::vector<MisVertex> scratch;
    // t = 1 stands the lens point it samples in for the camera subpath.
    const PathVertex no_camera[1] = {};
    for (size_t i = begin; i < end; ++i) {
        const Vec2i pixel(static_cast<int>(i % w), static_cast<int>(i / w));
        sampler->start_pixel_sample(pixel, it.index);
        std::optional<SecondaryWavelengthsScope> terminated;  // this light path's
        if (m_settings.spectral) terminated.emplace();
        std::vector<PathVertex>& light = it.light_paths[i];
        // One time per light subpath; the camera subpaths that join it take the same.
        const float time = scene.camera().sample_time(*sampler);
        // In media a hero of its own (a camera subpath merges with many light subpaths).
        std::optional<MediaWalk> media_walk = start_media_walk(it.media, *sampler);
        MediaWalk* const walk = media_walk ? &*media_walk : nullptr;
        if (walk) walk->own_hero = true;
        generate_light_subpath(scene, time, *sampler, arena, counter, it.light_limits, light, walk);
        it.light_times[i] = time;
        for (int s = 1; s <= static_cast<int>(light.size()); ++s) {
            if (max_depth >= 0 && s - 1 > max_depth) break;
            const StrategyContribution c = connect_strategy(
                scene, light, no_camera, s, 1, *sampler, counter, MisHeuristic::kBalance, scratch,
                it.eta, it.light_tracing_count, walk, it.volume_merge_scale);
            if (!c.L.is_black()) splats.push_back({c.film, c.L});
        }
    }
    it.rays += counter.rays;
}

// Each rank sends its subpaths (with their times) and its splats; every rank takes the
// others' in rank order, which is subpath order: the film receives the splats in the order
// one process adds them, and the subpaths, BSDFs made again, are the ones it would hold.
void VcmIntegrator::exchange_light_subpaths(const Scene& scene, Film& film, Iteration& it) const {
    const SubpathCodec codec(scene);
    std::vector<uint8_t> own;
    for (size_t i = it.first_light; i < it.end_light; ++i)
        codec.write(it.light_paths[i], it.light_times[i], own);
    std::vector<Splat> own_splats;
    for (const std::vector<Splat>& splats : it.splats)
        own_splats.insert(own_splats.end(), splats.begin(), splats.end());
    SubpathCodec::write_splats(own_splats, own);
    const std::vector<std::vector<uint8_t>> parts = m_cluster->all_gather_bytes(own);
    const size_t n_light = it.light_paths.size();
    for (int r = 0; r < m_cluster->size(); ++r) {
        if (r == m_cluster->rank()) {
            film.add_splats(own_splats);
            continue;
        }
        const auto [first, end] = m_cluster->share_of(r, n_light);
        Arena& arena = it.received_arenas[static_cast<size_t>(r)];
        arena.reset();
        const std::vector<uint8_t>& bytes = parts[static_cast<size_t>(r)];
        size_t at = 0;
        for (size_t i = first; i < end; ++i)
            codec.read(bytes, at, it.light_paths[i], it.light_times[i], arena);
        std::vector<Splat> splats;
        SubpathCodec::read_splats(bytes, at, splats);
        film.add_splats(splats);
    }
}

namespace {

// A camera subpath's joins and merges, summed for the film. In spectral mode a light subpath
// that went through dispersive glass carries its hero wavelength alone (its other values are
// 0); the film reads such a value at the hero alone when it stands alone, but a camera path
// sums it with joins that carry all four wavelengths, and the film would read the sum over
// four, a quarter of the hero's estimate. So those contributions are kept apart and, when
// they meet others, given the weight the film's mean over four needs (Spectrum::hero_only).
// A camera subpath that itself went through the glass is read at its hero anyway.
class PathSum {
public:
    explicit PathSum(bool spectral) : m_spectral(spectral) {}
    PathSum& operator+=(const Spectrum& value) {
        (m_spectral && hero_alone(value) ? m_hero : m_all) += value;
        return *this;
    }
    Spectrum total() const {
        if (m_hero.is_black()) return m_all;
        if (m_all.is_black() || secondary_wavelengths_terminated()) return m_all + m_hero;
        return m_all + m_hero.hero_only();
    }

private:
    static bool hero_alone(const Spectrum& v) {
        return v.value(0) != 0.0f && v.value(1) == 0.0f && v.value(2) == 0.0f && v.value(3) == 0.0f;
    }
    bool m_spectral;
    Spectrum m_all{0.0f}, m_hero{0.0f};
};

}  // namespace

// One camera subpath per pixel of the tile: every connection with one light subpath (t >= 2,
// t outer, s inner, as bdpt), then the merges at each of its vertices in order. Pixel j (row-
// major) connects to light subpath j mod n_L: each camera subpath needs one light subpath
// independent of itself, and any fixed choice is unbiased; with n_L >= pixels each pixel has
// one of its own (the default: its own pixel's), with fewer the pixels that share one are n_L
// apart in scan order, rows apart, so the error they share is not a visible block.
// Draws, from the camera sampler at (pixel, iteration): the filter (2D), the camera ray, the
// subpath (subpath.h), then the strategies' draws (connect_strategy).
void VcmIntegrator::render_tile(const Scene& scene, Film& film, const Iteration& it,
                                int tile) const {
    const int tiles_x = (film.width() + kCameraTileSize - 1) / kCameraTileSize;
    const int x0 = (tile % tiles_x) * kCameraTileSize, y0 = (tile / tiles_x) * kCameraTileSize;
    const int x1 = std::min(x0 + kCameraTileSize, film.width());
    const int y1 = std::min(y0 + kCameraTileSize, film.height());
    const int max_depth = m_settings.max_depth;
    const WavelengthContext iteration_wavelengths =
        pass_wavelengths(mix_bits(m_settings.seed ^ 0x7c3a1u), static_cast<uint32_t>(it.index));
    std::optional<WavelengthScope> wavelengths;
    if (m_settings.spectral) wavelengths.emplace(iteration_wavelengths);
    auto sampler = it.camera_sampler->clone();
    HashGrid::Cache cache;  // a tile's camera vertices are near each other
    HashGrid::Cache volume_cache;
    Arena arena;
    RayCounter counter;
    std::vector<PathVertex> camera;
    std::vector<MisVertex> scratch;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const Vec2i pixel(x, y);
            sampler->start_pixel_sample(pixel, it.index);
            // This camera path's. Joins with a light path that went through dispersive glass
            // carry that path's hero alone; summed with the camera path's other joins, the
            // film reads them at all four wavelengths: with dispersion, vcm in spectral mode
            // is biased (docs/spectral.md).
            std::optional<SecondaryWavelengthsScope> terminated;
            if (m_settings.spectral) terminated.emplace();
            const FilterSample filter = m_filter->sample(sampler->get_pixel_2d());
            const Vec2 film_point = Vec2(pixel) + Vec2(0.5f) + filter.offset;
            // The light subpath this camera subpath joins, and its time (joins see one scene;
            // merges meet photons of every time, as sppm's, docs/integrators.md).
            const size_t light_index =
                (static_cast<size_t>(y) * film.width() + x) % it.light_paths.size();
            const std::vector<PathVertex>& light = it.light_paths[light_index];
            const Ray ray =
                scene.camera().sample_ray_at(film_point, *sampler, it.light_times[light_index]);
            arena.reset();
            std::optional<MediaWalk> media_walk = start_media_walk(it.media, *sampler);
            MediaWalk* const walk = media_walk ? &*media_walk : nullptr;
            if (walk) walk->own_hero = true;
            generate_camera_subpath(scene, ray, *sampler, arena, counter, it.camera_limits, camera,
                                    walk);
            PathSum L(m_settings.spectral);
            const int n_camera = static_cast<int>(camera.size());
            const int n_light = std::max(1, static_cast<int>(light.size()));
            for (int t = 2; t <= n_camera; ++t) {
                for (int s = 0; s <= n_light; ++s) {
                    if (max_depth >= 0 && s + t - 2 > max_depth) continue;
                    L += connect_strategy(scene, light, camera, s, t, *sampler, counter,
                                          MisHeuristic::kBalance, scratch, it.eta,
                                          it.light_tracing_count, walk, it.volume_merge_scale)
                             .L;
                }
            }
            // Merges at the camera subpath's points in media, with the light subpaths' there:
            // the photons in a ball of radius r estimate sigma_s times the phase-weighted
            // radiance arriving (their density of collisions holds sigma_s), so each merge is
            // divided by sigma_s at the camera point (volumetric photon mapping's estimate,
            // UPBP's point-point merge).
            for (int t = 2; it.volume_merge_scale > 0.0f && t <= n_camera; ++t) {
                const PathVertex& pt = camera[t - 1];
                if (!pt.is_medium()) continue;
                const Spectrum per_sigma_s = pt.medium->at(pt.p).sigma_s.map(
                    [](float v) { return v > 0.0f ? 1.0f / v : 0.0f; });
                const HenyeyGreenstein phase(pt.medium->phase_asymmetry());
                it.volume_grid.for_each_near(pt.p, volume_cache, [&](uint32_t index, float) {
                    const PhotonRef& ref = it.volume_photons[index];
                    const int s = static_cast<int>(ref.vertex);
                    if (max_depth >= 0 && s + t - 2 > max_depth) return;
                    const std::vector<PathVertex>& path = it.light_paths[ref.path];
                    const PathVertex& photon = path[ref.vertex];
                    if (photon.medium != pt.medium) return;
                    const float f = phase.eval(pt.si.wo, photon.si.wo);
                    if (!(f > 0.0f)) return;
                    const float weight =
                        merge_mis_weight(scene, std::span(path).first(ref.vertex), camera, s, t,
                                         it.eta, MisHeuristic::kBalance, scratch,
                                         it.light_tracing_count, it.volume_merge_scale);
                    const float r_u = pt.r_u.average() * photon.r_u.average();
                    if (!(r_u > 0.0f)) return;
                    L +=
                        pt.beta * photon.beta * per_sigma_s * (f * it.volume_kernel * weight / r_u);
                });
            }
            for (int t = 2; t <= n_camera; ++t) {
                const PathVertex& pt = camera[t - 1];
                if (!pt.is_surface() || !pt.connectible()) continue;
                const Vec3 wo_local = pt.si.to_local(pt.si.wo);
                it.grid.for_each_near(pt.p, cache, [&](uint32_t index, float) {
                    const PhotonRef& ref = it.photons[index];
                    const int s = static_cast<int>(ref.vertex);
                    if (max_depth >= 0 && s + t - 2 > max_depth) return;
                    const std::vector<PathVertex>& path = it.light_paths[ref.path];
                    const PathVertex& photon = path[ref.vertex];
                    // A photon on the other side of a surface (a thin wall) lights that side.
                    if (!(glm::dot(photon.ng, pt.ng) > 0.0f)) return;
                    const Spectrum f = pt.bsdf->eval(wo_local, pt.si.to_local(photon.si.wo));
                    if (f.is_black()) return;
                    const float weight =
                        merge_mis_weight(scene, std::span(path).first(ref.vertex), camera, s, t,
                                         it.eta, MisHeuristic::kBalance, scratch,
                                         it.light_tracing_count, it.volume_merge_scale);
                    // In media each subpath is weighted over its own hero's channels.
                    const float r_u = walk ? pt.r_u.average() * photon.r_u.average() : 1.0f;
                    if (!(r_u > 0.0f)) return;
                    L += pt.beta * f * photon.beta * (it.merge_scale * weight / r_u);
                });
            }
            // Light that media emit along the camera subpath: only it samples that.
            if (walk) L += walk->emitted;
            AovSample aov{};
            if (film.has_aovs() && n_camera > 1) {
                const PathVertex& first = camera[1];
                if (first.kind == PathVertex::Kind::kEscape)
                    aov = AovSample{scene.escaped_radiance(first.w_sky), Vec3(0.0f), kInfinity};
                else if (first.is_medium())
                    aov = AovSample{Spectrum(0.0f), Vec3(0.0f), glm::length(first.p - ray.origin)};
                else
                    aov = AovSample{first.si.material->albedo(first.si), first.si.shading.n(),
                                    first.si.t};
            }
            film.add_sample(pixel, L.total(), filter.weight, film.has_aovs() ? &aov : nullptr);
        }
    }
    it.progress->advance(static_cast<uint64_t>(x1 - x0) * (y1 - y0));
    it.rays += counter.rays;
}

}  // namespace glint
