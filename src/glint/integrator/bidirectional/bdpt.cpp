#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/integrator/bidirectional/bdpt.h>
#include <glint/integrator/transport/camera_connection.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/spectral_model.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/material/material.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>

namespace glint {
namespace {

constexpr int kTileSize = 16;
// Tiles rendered in parallel before their splats reach the film, in tile order: bounds the
// splats held at once, independently of the thread count.
constexpr int kTilesPerBatch = 64;

bool is_point_like(const PathVertex& v) {
    return v.infinite || v.ng == Vec3(0.0f);
}

// The transmittance of the shadow ray from the connectible vertex `from` to `target`,
// leaving along `w` (unit): from a surface offset as its rays are, from a point in a medium
// where it is; in the medium it leaves into, through interfaces and their media.
Spectrum shadow_transmittance(const Scene& scene, const PathVertex& from, const Vec3& target,
                              const Vec3& w, MediaWalk& media) {
    const Scene::ShadowRay shadow = from.is_medium()
                                        ? Scene::ShadowRay{from.p, target - from.p, from.si.time}
                                        : Scene::shadow_ray(from.si, target);
    return transmittance_through_interfaces(scene, shadow, medium_leaving(from, w), &media.rng);
}

}  // namespace

namespace {

// A specular chain x_a .. x_b (delta vertices between non-delta x_{a-1} and x_{b+1}) is
// entered once from each side: the light walk makes x_a with p_L(a) (per unit area at x_a),
// the camera walk x_b with p_C(b), and every other density in the chain is a delta (1 in the
// ratios). Only their ratio matters to the weights (a strategy joins on one side of the
// chain or the other), and per unit area at the chain's first vertex it is wrong: what each
// walk really makes is the chain's far end, x_{b+1} (or x_{a-1}), with the density of its
// direction times |d omega / dA| through the chain. That Jacobian is G / cos at the start,
// with G the chain's generalised geometry term, the same both ways (etendue is conserved by
// reflection and refraction between ends in the same medium): the ratio is that of
// p_omega(a-1 -> a) |cos at x_{b+1}| and p_omega(b+1 -> b) |cos at x_{a-1}|. Stored per area
// at x_a and x_b instead, it is off by (d_{a-1,a}^2 / d_{b,b+1}^2) and two cosines: for a
// caustic under a glass ball lit from a ceiling, a factor of ~100 towards the camera walk,
// so that bdpt and vcm weighed light tracing and merging there far below what they are worth.
// Both entries are rewritten here, so the weights of every strategy of the path still come
// from one set of densities and sum to 1. Chains with an end at infinity or without a surface
// normal (a point light, a pinhole lens) are left as they are (no cosine to take there).
template <typename VertexAt>
void weigh_specular_chains(std::vector<MisVertex>& path, VertexAt&& vertex_at) {
    const int k = static_cast<int>(path.size());
    auto finite_surface = [](const PathVertex& v) { return !v.infinite && v.ng != Vec3(0.0f); };
    for (int i = 1; i + 1 < k; ++i) {
        if (!path[i].delta || path[i - 1].delta) continue;
        const int a = i;
        int b = a;
        while (b + 1 < k && path[b + 1].delta) ++b;
        if (b + 1 >= k) return;
        i = b;
        const PathVertex& before = vertex_at(a - 1);
        const PathVertex& first = vertex_at(a);
        const PathVertex& last = vertex_at(b);
        const PathVertex& after = vertex_at(b + 1);
        if (!finite_surface(before) || !finite_surface(after) || first.infinite || last.infinite)
            continue;
        const Vec3 d_in = first.p - before.p, d_out = after.p - last.p;
        const float in2 = glm::dot(d_in, d_in), out2 = glm::dot(d_out, d_out);
        if (!(in2 > 0.0f && out2 > 0.0f)) continue;
        const float cos_before = std::abs(glm::dot(before.ng, d_in)) / std::sqrt(in2);
        const float cos_first = std::abs(glm::dot(first.ng, d_in)) / std::sqrt(in2);
        const float cos_last = std::abs(glm::dot(last.ng, d_out)) / std::sqrt(out2);
        const float cos_after = std::abs(glm::dot(after.ng, d_out)) / std::sqrt(out2);
        if (!(cos_before > 0.0f && cos_first > 0.0f && cos_last > 0.0f && cos_after > 0.0f))
            continue;
        path[a].pdf_light *= in2 / cos_first * cos_after;
        path[b].pdf_camera *= out2 / cos_last * cos_before;
    }
}

// The path of light[0, s) and camera[0, t) as the weights see it, in `scratch`, for the
// connection (s, t) (merge false) or the merge of a light subpath's vertex s with camera
// vertex t - 1, which stands for both (merge true). Returns whether x_0 is a delta light.
bool fill_mis_path(const Scene& scene, std::span<const PathVertex> light,
                   std::span<const PathVertex> camera, int s, int t, const PathVertex& sampled,
                   bool merge, std::vector<MisVertex>& scratch, float volume_merge_scale) {
    const int k = s + t;
    auto light_at = [&](int i) -> const PathVertex& {
        return s == 1 && t > 1 && i == 0 && !merge ? sampled : light[i];
    };
    auto camera_at = [&](int j) -> const PathVertex& {
        return t == 1 && j == 0 ? sampled : camera[j];
    };
    scratch.resize(k);
    for (int i = 0; i < s; ++i) {
        const PathVertex& v = light_at(i);
        scratch[i] =
            MisVertex{v.pdf_fwd, v.pdf_rev, v.delta, v.is_medium() ? volume_merge_scale : 1.0f};
    }
    for (int j = 0; j < t; ++j) {
        const PathVertex& v = camera_at(j);
        scratch[k - 1 - j] =
            MisVertex{v.pdf_rev, v.pdf_fwd, v.delta, v.is_medium() ? volume_merge_scale : 1.0f};
    }
    // The densities the subpaths stored were for their own continuations; at the join the
    // path goes on to the other subpath, which changes four of them: each join vertex as the
    // other side's walk would reach it, and the vertex before it as the walk would go on.
    // A merge joins at x_s = pt, reached by the light walk as its own vertex s was: x_{s-1}
    // keeps the lobe that walk took there (a delta lobe leaves both densities at 0).
    const PathVertex* qs = s > 0 ? &light_at(s - 1) : nullptr;
    const PathVertex* qs_minus = s > 1 ? &light_at(s - 2) : nullptr;
    const PathVertex& pt = camera_at(t - 1);
    const PathVertex* pt_minus = t > 1 ? &camera_at(t - 2) : nullptr;
    const bool delta_qs = merge && qs && qs->delta;
    scratch[s].delta = false;
    if (qs && !merge) scratch[s - 1].delta = false;
    if (s == 0)
        scratch[0].pdf_light = emission_origin_pdf(scene, pt, *pt_minus);
    else if (delta_qs)
        scratch[s].pdf_light = 0.0f;
    else if (s == 1)
        scratch[s].pdf_light = emission_pdf(*qs, pt);
    else
        scratch[s].pdf_light = continuation_pdf(scene, qs_minus, *qs, pt);
    if (pt_minus) {
        scratch[s + 1].pdf_light =
            s > 0 ? continuation_pdf(scene, qs, pt, *pt_minus) : emission_pdf(pt, *pt_minus);
    }
    if (qs) scratch[s - 1].pdf_camera = continuation_pdf(scene, pt_minus, pt, *qs);
    if (qs_minus)
        scratch[s - 2].pdf_camera = delta_qs ? 0.0f : continuation_pdf(scene, &pt, *qs, *qs_minus);
    weigh_specular_chains(scratch, [&](int i) -> const PathVertex& {
        return i < s ? light_at(i) : camera_at(k - 1 - i);
    });
    return s > 0 && light_at(0).light && light_at(0).light->is_delta();
}

}  // namespace

float strategy_mis_weight(const Scene& scene, std::span<const PathVertex> light,
                          std::span<const PathVertex> camera, int s, int t,
                          const PathVertex& sampled, MisHeuristic heuristic,
                          std::vector<MisVertex>& scratch, float merge_eta,
                          float light_tracing_count, float volume_merge_scale) {
    // A light seen directly by the lens is made by (0, 2) or (1, 1); but (1, 1) is only done
    // for lights with a surface: a point, spot or infinite light seen directly is (0, 2)'s
    // alone (the environment) or nobody's (the others, invisible in every glint integrator).
    if (s + t == 2 && is_point_like(s == 0 ? camera[t - 1] : light[0])) return 1.0f;
    const bool delta_light =
        fill_mis_path(scene, light, camera, s, t, sampled, false, scratch, volume_merge_scale);
    return vcm_strategy_weight(scratch, s, false, delta_light, merge_eta, heuristic,
                               light_tracing_count);
}

float merge_mis_weight(const Scene& scene, std::span<const PathVertex> light,
                       std::span<const PathVertex> camera, int s, int t, float merge_eta,
                       MisHeuristic heuristic, std::vector<MisVertex>& scratch,
                       float light_tracing_count, float volume_merge_scale) {
    const bool delta_light =
        fill_mis_path(scene, light, camera, s, t, camera[t - 1], true, scratch, volume_merge_scale);
    return vcm_strategy_weight(scratch, s, true, delta_light, merge_eta, heuristic,
                               light_tracing_count);
}

StrategyContribution connect_strategy(const Scene& scene, std::span<const PathVertex> light,
                                      std::span<const PathVertex> camera, int s, int t,
                                      Sampler& sampler, RayCounter& counter, MisHeuristic heuristic,
                                      std::vector<MisVertex>& scratch, float merge_eta,
                                      float light_tracing_count, MediaWalk* media,
                                      float volume_merge_scale) {
    StrategyContribution result;
    // The draws come first, so that later draws never depend on what a strategy found.
    Vec2 u_lens(0.0f), u_light(0.0f);
    float u_choice = 0.0f, u_select = 0.0f;
    if (t == 1) {
        u_lens = sampler.get_2d();
    } else if (s == 1) {
        u_light = sampler.get_2d();
        u_choice = sampler.get_1d();
        u_select = sampler.get_1d();
    }
    if (t < 1 || t > static_cast<int>(camera.size()) || s + t < 2) return result;
    if (s > static_cast<int>(light.size()) && s != 1) return result;
    if (s == 1 && t == 1 && light.empty()) return result;

    PathVertex sampled;
    Spectrum L(0.0f);
    if (s == 0) {
        // The camera subpath found a light.
        const PathVertex& pt = camera[t - 1];
        if (!pt.is_emitter()) return result;
        if (pt.kind == PathVertex::Kind::kEscape) {
            if (!pt.light) {
                // A constant background is no light: only this strategy sees it.
                result.L = pt.beta * scene.background();
                if (media) result.L /= pt.r_u.average();
                result.weight = 1.0f;
                return result;
            }
            L = pt.beta * pt.light->le_escaped(pt.w_sky);
        } else {
            L = pt.beta * pt.light->le(pt.si, pt.si.wo);
        }
    } else if (t == 1) {
        // A light subpath vertex seen by the camera: a lens point, splatted where it lands.
        const PathVertex& qs = light[s - 1];
        if (s == 1) {
            // The light's own point: point, spot and infinite lights are invisible to the
            // camera, as in every glint integrator.
            if (is_point_like(qs)) return result;
        } else if (!qs.connectible()) {
            return result;
        }
        // qs.pdf_fwd of the light's own point is the light's choice times its area density.
        // The light's point keeps its subpath's time (PathVertex::si.time), as hits do.
        Rng* const rng = media ? &media->rng : nullptr;
        std::optional<CameraConnection> connection;
        if (s == 1)
            connection =
                connect_light_point_to_camera(scene, *qs.light, qs.p, qs.ng, qs.si.time, qs.pdf_fwd,
                                              u_lens, counter.rays, qs.medium, rng);
        else if (qs.is_medium())
            connection = connect_medium_point_to_camera(
                scene, qs.p, -qs.si.wo, qs.si.time, *qs.medium, qs.beta, u_lens, counter.rays, rng);
        else
            connection = connect_surface_to_camera(scene, qs.si, *qs.bsdf, qs.beta, u_lens,
                                                   counter.rays, qs.medium, rng);
        if (!connection) return result;
        const CameraWiSample* const lens = &connection->lens;
        L = connection->L;
        sampled.kind = PathVertex::Kind::kCamera;
        sampled.p = lens->p_lens;
        sampled.si.time = qs.si.time;  // where the camera stands for the MIS densities
        result.splat = true;
        result.film = lens->film;
    } else if (s == 1) {
        // Next-event estimation from the camera vertex.
        const PathVertex& pt = camera[t - 1];
        if (!pt.connectible()) return result;
        const LightPoint point = sample_light_point(scene, pt.p, Vec3(0.0f), u_light, u_choice,
                                                    u_select, LightChoice::kByPower);
        const LightSampler::Choice& choice = point.choice;
        const std::optional<LightSample>& ls = point.sample;
        if (!ls || ls->L.is_black() || !(ls->pdf > 0.0f)) return result;
        if (media) {
            const Spectrum f = scattering_towards(pt, ls->wi, TransportMode::kRadiance);
            if (f.is_black()) return result;
            ++counter.rays;
            const Spectrum visible = shadow_transmittance(scene, pt, ls->p, ls->wi, *media);
            if (visible.is_black()) return result;
            L = pt.beta * f * ls->L * (1.0f / (choice.pmf * ls->pdf)) * visible;
        } else {
            const Vec3 wi_local = pt.si.to_local(ls->wi);
            const Spectrum f = pt.bsdf->eval(pt.si.to_local(pt.si.wo), wi_local);
            if (f.is_black()) return result;
            ++counter.rays;
            const Spectrum visible = transmittance(scene, pt.si, ls->p);
            if (visible.is_black()) return result;
            L = pt.beta * f * ls->L * (abs_cos_theta(wi_local) / (choice.pmf * ls->pdf)) * visible;
        }
        sampled.kind = PathVertex::Kind::kLight;
        sampled.light = choice.light;
        sampled.infinite = choice.light->is_infinite() || choice.light->is_delta_direction();
        sampled.p = ls->p;
        sampled.ng = ls->n;
        sampled.w_sky = ls->wi;
        sampled.pdf_fwd = emission_origin_pdf(scene, sampled, pt);
    } else {
        // A vertex of each subpath, joined by a shadow ray.
        const PathVertex& qs = light[s - 1];
        const PathVertex& pt = camera[t - 1];
        if (!qs.connectible() || !pt.connectible()) return result;
        const Vec3 d = pt.p - qs.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return result;
        const Vec3 w = d / std::sqrt(dist2);  // from the light side to the camera side
        if (media) {
            // Surfaces and medium points alike: the scattering towards the other vertex with
            // its cosine (none in a medium), and the media between.
            const Spectrum f_light = scattering_towards(qs, w, TransportMode::kImportance);
            if (f_light.is_black()) return result;
            const Spectrum f_camera = scattering_towards(pt, -w, TransportMode::kRadiance);
            if (f_camera.is_black()) return result;
            ++counter.rays;
            const Spectrum visible = shadow_transmittance(scene, pt, qs.p, -w, *media);
            if (visible.is_black()) return result;
            L = qs.beta * f_light * f_camera * pt.beta * (1.0f / dist2) * visible;
        } else {
            const Vec3 w_light = qs.si.to_local(w), w_camera = pt.si.to_local(-w);
            const Spectrum f_light =
                qs.bsdf->eval(qs.si.to_local(qs.si.wo), w_light, TransportMode::kImportance,
                              qs.si.to_local(qs.si.ng));
            if (f_light.is_black()) return result;
            const Spectrum f_camera = pt.bsdf->eval(pt.si.to_local(pt.si.wo), w_camera);
            if (f_camera.is_black()) return result;
            const float g = abs_cos_theta(w_light) * abs_cos_theta(w_camera) / dist2;
            ++counter.rays;
            const Spectrum visible = transmittance(scene, pt.si, qs.p);
            if (visible.is_black()) return result;
            L = qs.beta * f_light * f_camera * pt.beta * g * visible;
        }
    }
    if (L.is_black()) return result;
    if (media) {
        // The hero channel's one-sample MIS over the channels (volpath's r_u): the density
        // of the whole path had channel c been the hero, over the hero's, is the product of
        // both subpaths' ratios; the sampled light point and lens add none.
        const bool light_vertex = s > 0 && !(s == 1 && t > 1);
        const Spectrum r_light = light_vertex ? light[s - 1].r_u : Spectrum(1.0f);
        const Spectrum& r_camera = camera[t - 1].r_u;
        // Subpaths with heroes of their own (vcm) are weighted each over its own channels.
        const float mean = media->own_hero ? r_light.average() * r_camera.average()
                                           : (r_light * r_camera).average();
        if (!(mean > 0.0f)) return result;
        L /= mean;
    }
    result.weight = strategy_mis_weight(scene, light, camera, s, t, sampled, heuristic, scratch,
                                        merge_eta, light_tracing_count, volume_merge_scale);
    result.L = L * result.weight;
    return result;
}

// What one thread renders a tile with.
struct BdptIntegrator::Worker {
    std::unique_ptr<Sampler> sampler;
    Arena arena;
    RayCounter counter;
    std::vector<PathVertex> camera, light;
    std::vector<MisVertex> scratch;
    std::vector<Spectrum> strategy_L;  // per debug image, for the current sample
};

// A tile's splats, all together and (for the debug view) per strategy image.
struct BdptIntegrator::TileResult {
    std::vector<Splat> splats;
    std::vector<std::vector<Splat>> strategy_splats;
    uint64_t samples = 0;
};

BdptIntegrator::BdptIntegrator(const RenderSettings& settings) : m_settings(settings) {
    blame_setting(settings, "filter",
                  [&] { m_filter = make_filter(settings.filter, settings.filter_radius); });
    blame_setting(settings, "sampler",
                  [&] { make_sampler(settings.sampler, settings.spp, settings.seed); });
    refuse_adaptive_sampling(settings, "bdpt");
    m_debug_strategies = std::find(settings.debug.begin(), settings.debug.end(), "strategies") !=
                         settings.debug.end();
}

std::unique_ptr<Integrator> BdptIntegrator::create(const RenderSettings& settings, const Params&) {
    return std::make_unique<BdptIntegrator>(settings);
}

int BdptIntegrator::debug_index(int s, int t) {
    const int n = s + t;
    if (n > kDebugMaxVertices) return debug_count() - 1;
    return (n - 1) * n / 2 - 1 + s;  // paths of 2 .. n-1 vertices come first
}

int BdptIntegrator::debug_count() {
    return kDebugMaxVertices * (kDebugMaxVertices + 1) / 2;
}

RenderStats BdptIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    check_camera_motion_joinable(scene, "bdpt", m_settings.where_of("integrator"));
    m_media = walk_media(scene);
    const int w = film.width(), h = film.height();
    // One light subpath per camera sample: the splats of spp paths per pixel (camera.h).
    const double splat_scale = 1.0 / static_cast<double>(m_settings.spp);
    film.set_splat_scale(splat_scale);
    std::vector<Film> strategy_films;
    if (m_debug_strategies) {
        for (int i = 0; i < debug_count(); ++i) {
            strategy_films.emplace_back(w, h, false);
            strategy_films.back().set_splat_scale(splat_scale);
        }
    }
    const auto prototype = make_sampler(m_settings.sampler, m_settings.spp, m_settings.seed);
    const int tiles_x = (w + kTileSize - 1) / kTileSize, tiles_y = (h + kTileSize - 1) / kTileSize;
    const int tiles = tiles_x * tiles_y;
    RenderStats stats;
    std::atomic<uint64_t> rays{0};
    for (int first = 0; first < tiles; first += kTilesPerBatch) {
        const int batch = std::min(kTilesPerBatch, tiles - first);
        std::vector<TileResult> results(batch);
        tbb::parallel_for(0, batch, [&](int b) {
            Worker worker;
            worker.sampler = prototype->clone();
            render_tile(scene, film, strategy_films, first + b, worker, results[b]);
            rays += worker.counter.rays;
            progress.advance(results[b].samples);
        });
        for (const TileResult& result : results) {
            film.add_splats(result.splats);
            for (size_t i = 0; i < result.strategy_splats.size(); ++i)
                strategy_films[i].add_splats(result.strategy_splats[i]);
            stats.samples += result.samples;
        }
    }
    for (int i = 0; i < static_cast<int>(strategy_films.size()); ++i) {
        std::string name = "bdpt_rest";
        for (int n = 2; n <= kDebugMaxVertices; ++n) {
            for (int s = 0; s < n; ++s) {
                if (debug_index(s, n - s) == i) name = fmt::format("bdpt_s{}_t{}", s, n - s);
            }
        }
        stats.images.push_back({name, strategy_films[i].resolve()});
    }
    stats.rays = rays.load();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

// A tile's samples: per camera sample a camera subpath and a light subpath, then every
// strategy (s, t) in a fixed order, t outer, s inner.
void BdptIntegrator::render_tile(const Scene& scene, Film& film, std::span<Film> strategy_films,
                                 int tile, Worker& worker, TileResult& result) const {
    const int tiles_x = (film.width() + kTileSize - 1) / kTileSize;
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, film.width());
    const int y1 = std::min(y0 + kTileSize, film.height());
    const int max_depth = m_settings.max_depth;
    // Paths of at most max_depth bounces: max_depth + 2 vertices, of which at least one
    // (the lens) is the camera's and, but for s = 0, one the light's.
    const WalkLimits camera_limits{max_depth >= 0 ? max_depth + 2 : kMaxVertices, true};
    const WalkLimits light_limits{max_depth >= 0 ? max_depth + 1 : kMaxVertices, true};
    const int images = static_cast<int>(strategy_films.size());
    result.strategy_splats.resize(images);
    worker.strategy_L.assign(images, Spectrum(0.0f));
    Sampler& sampler = *worker.sampler;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const Vec2i pixel(x, y);
            for (int index = 0; index < m_settings.spp; ++index) {
                const PathWavelengths wavelengths(
                    m_settings.spectral, detail::pixel_sample_key(m_settings.seed, pixel, index));
                sampler.start_pixel_sample(pixel, index);
                const FilterSample filter = m_filter->sample(sampler.get_pixel_2d());
                const Vec2 film_point = Vec2(pixel) + Vec2(0.5f) + filter.offset;
                const Ray ray = scene.camera().sample_ray(film_point, sampler);
                worker.arena.reset();
                std::optional<MediaWalk> media_walk =
                    start_media_walk(m_media ? &*m_media : nullptr, sampler);
                MediaWalk* const media = media_walk ? &*media_walk : nullptr;
                generate_camera_subpath(scene, ray, sampler, worker.arena, worker.counter,
                                        camera_limits, worker.camera, media);
                generate_light_subpath(scene, ray.time, sampler, worker.arena, worker.counter,
                                       light_limits, worker.light, media);
                std::fill(worker.strategy_L.begin(), worker.strategy_L.end(), Spectrum(0.0f));
                Spectrum L(0.0f);
                const int n_camera = static_cast<int>(worker.camera.size());
                const int n_light = std::max(1, static_cast<int>(worker.light.size()));
                for (int t = 1; t <= n_camera; ++t) {
                    for (int s = 0; s <= n_light; ++s) {
                        if (s + t < 2 || (max_depth >= 0 && s + t - 2 > max_depth)) continue;
                        const StrategyContribution c = connect_strategy(
                            scene, worker.light, worker.camera, s, t, sampler, worker.counter,
                            MisHeuristic::kBalance, worker.scratch, 0.0f, 1.0f, media);
                        if (c.L.is_black()) continue;
                        if (c.splat) {
                            result.splats.push_back({c.film, c.L});
                            if (images)
                                result.strategy_splats[debug_index(s, t)].push_back({c.film, c.L});
                        } else {
                            L += c.L;
                            if (images) worker.strategy_L[debug_index(s, t)] += c.L;
                        }
                    }
                }
                // Light that media emit along the camera subpath: only it samples that.
                if (media) L += media->emitted;
                AovSample aov{};
                if (film.has_aovs() && n_camera > 1) {
                    const PathVertex& first = worker.camera[1];
                    if (first.kind == PathVertex::Kind::kEscape)
                        aov = AovSample{scene.escaped_radiance(first.w_sky), Vec3(0.0f), kInfinity};
                    else if (first.is_medium())
                        aov = AovSample{Spectrum(0.0f), Vec3(0.0f),
                                        glm::length(first.p - ray.origin)};
                    else
                        aov = AovSample{first.si.material->albedo(first.si), first.si.shading.n(),
                                        first.si.t};
                }
                film.add_sample(pixel, L, filter.weight, film.has_aovs() ? &aov : nullptr);
                for (int i = 0; i < images; ++i)
                    strategy_films[i].add_sample(pixel, worker.strategy_L[i], filter.weight,
                                                 nullptr);
            }
            result.samples += static_cast<uint64_t>(m_settings.spp);
        }
    }
}

}  // namespace glint
