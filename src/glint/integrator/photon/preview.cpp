#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/core/rng.h>
#include <glint/core/sampler.h>
#include <glint/integrator/photon/pass_sampler.h>
#include <glint/integrator/photon/photon_tracer.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/photon/preview_restir.h>
#include <glint/integrator/transport/spectral_model.h>
#include <glint/integrator/transport/transport.h>
#include <glint/math/frame.h>
#include <glint/math/warp.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <bit>
#include <chrono>

namespace glint {
namespace {

// Knaus and Zwicker's alpha: the radius shrinks so that bias and variance both vanish.
constexpr float kRadiusShrinkAlpha = 2.0f / 3.0f;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Keeps the photons that reached their first non-specular surface through mirrors and glass.
struct CausticSink {
    std::vector<Photon> photons;
    void store(const PhotonHit& hit) {
        if (hit.caustic) photons.push_back({hit.si->p, hit.wi, hit.power});
    }
};

// The fraction of the light leaving the scene's surfaces that meets another surface rather
// than escaping: from surface points found by rays from random points of the bounds, the
// fraction of cosine-distributed directions that hit something (256 probes, fixed seed).
float enclosure(const Scene& scene) {
    const Bounds3& bounds = scene.stats().bounds;
    if (bounds.is_empty()) return 0.0f;
    Rng rng(0x2545f4914f6cdd1dull);
    int probes = 0, enclosed = 0;
    for (int i = 0; i < 4096 && probes < 256; ++i) {
        Ray ray;
        ray.origin = bounds.min +
                     bounds.extent() * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
        ray.direction = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const std::optional<SurfaceInteraction> hit = scene.intersect(ray);
        if (!hit) continue;
        // Light leaves the side the probe arrived from.
        const Vec3 n = glm::dot(hit->ng, ray.direction) < 0.0f ? hit->ng : -hit->ng;
        const Vec3 w = warp::square_to_cosine_hemisphere(Vec2(rng.next_float(), rng.next_float()));
        ++probes;
        if (scene.intersect(spawn_ray(*hit, Frame::from_normal(n).to_world(w)))) ++enclosed;
    }
    return probes > 0 ? static_cast<float>(enclosed) / static_cast<float>(probes) : 0.0f;
}

}  // namespace

PreviewSettings PreviewSettings::read(const Params& p) {
    PreviewSettings s;
    s.photons = p.get_int("preview_photons", s.photons);
    s.window = p.get_int("preview_window", s.window);
    s.radius = p.get_float("preview_radius", s.radius);
    s.volume_radius = p.get_float("preview_volume_radius", s.volume_radius);
    s.ambient = p.get_float("preview_ambient", s.ambient);
    s.bounces = p.get_int("preview_bounces", s.bounces);
    const std::string restir = p.get_string("preview_restir", "off");
    try {
        s.restir.mode = restir_mode_named(restir);
    } catch (const Error& e) {
        p.fail_at("preview_restir", fmt::format("'preview_restir': {}", e.what()));
    }
    s.restir.candidates = p.get_int("preview_restir_candidates", s.restir.candidates);
    s.restir.spatial = p.get_int("preview_restir_spatial", s.restir.spatial);
    s.restir.temporal = p.get_bool("preview_restir_temporal", s.restir.temporal);
    s.restir.history_cap = p.get_float("preview_restir_history", s.restir.history_cap);
    s.fog_interleave = p.get_bool("preview_fog_interleave", s.fog_interleave);
    if (s.photons < 0 || s.photons > 100000000)
        p.fail_at("preview_photons", "'preview_photons' must be in [0, 1e8] (photons per pass)");
    if (s.window < 1 || s.window > 1024)
        p.fail_at("preview_window", "'preview_window' must be in [1, 1024] (passes of photons)");
    if (!(s.radius >= 0.0f && s.radius <= 1e12f))
        p.fail_at("preview_radius",
                  "'preview_radius' must be in [0, 1e12] (0: from the scene's size)");
    if (!(s.volume_radius >= 0.0f && s.volume_radius <= 1e12f))
        p.fail_at("preview_volume_radius",
                  "'preview_volume_radius' must be in [0, 1e12] (0: from the scene's size)");
    if (!(s.ambient >= 0.0f && s.ambient <= 1e6f))
        p.fail_at("preview_ambient", "'preview_ambient' must be in [0, 1e6] (0: no ambient term)");
    if (s.bounces < 0 || s.bounces > 16)
        p.fail_at("preview_bounces",
                  "'preview_bounces' must be in [0, 16] (indirect bounces; 0: the ambient term)");
    if (s.restir.candidates < 1 || s.restir.candidates > 1024)
        p.fail_at("preview_restir_candidates",
                  "'preview_restir_candidates' must be in [1, 1024] (light samples per pixel)");
    if (!(s.restir.history_cap >= 0.0f && s.restir.history_cap <= 1000.0f))
        p.fail_at("preview_restir_history",
                  "'preview_restir_history' must be in [0, 1000] (the previous pass counts at "
                  "most this many times preview_restir_candidates)");
    if (s.restir.spatial < 0 || s.restir.spatial > 16)
        p.fail_at("preview_restir_spatial",
                  "'preview_restir_spatial' must be in [0, 16] (neighbours; 0: no spatial reuse)");
    return s;
}

std::unique_ptr<Integrator> PreviewIntegrator::create(const RenderSettings& settings,
                                                      const Params& params) {
    // No tile loop checks the sampler's name: check it here, before any scene is built.
    blame_setting(settings, "sampler",
                  [&] { make_sampler(settings.sampler, settings.spp, settings.seed); });
    // A pass is one sample in every pixel: there is nothing to adapt.
    refuse_adaptive_sampling(settings, "preview");
    return std::make_unique<PreviewIntegrator>(settings, PreviewSettings::read(params));
}

PreviewIntegrator::PreviewIntegrator(const RenderSettings& settings, const PreviewSettings& preview)
    : m_settings(settings), m_preview(preview) {}

PreviewIntegrator::~PreviewIntegrator() = default;

void PreviewIntegrator::scene_changed(SceneChange change) {
    // World-space photons do not depend on the camera; anything else may move them. ReSTIR's
    // history survives a camera move too (temporal reuse reprojects it).
    if (change != SceneChange::camera) m_scene = nullptr;
}

// Drops the photons and prepares what depends on the lights and objects.
void PreviewIntegrator::restart(const Scene& scene) {
    m_scene = &scene;
    m_restir.clear();  // the reservoirs name lights and points that may have moved
    m_batches.clear();
    m_grid = HashGrid();
    m_photons.clear();
    m_photon_passes = 0;
    m_media = walk_media(scene);
    m_light_centres.clear();
    for (const std::unique_ptr<Light>& light : scene.lights()) {
        const std::optional<LightBounds> bounds =
            light->is_infinite() ? std::nullopt : light->bounds();
        m_light_centres.push_back(bounds && !bounds->bounds.is_empty()
                                      ? std::optional<Vec3>(bounds->bounds.center())
                                      : std::nullopt);
    }
    m_volume_batches.clear();
    m_volume_view = VolumePhotonView();
    const Bounds3& bounds = scene.stats().bounds;
    const Vec3 extent = bounds.is_empty() ? Vec3(1.0f) : bounds.extent();
    const float diagonal = glm::length(extent);
    const float r0 = m_preview.radius > 0.0f ? m_preview.radius : diagonal / 400.0f;
    m_radius2 = r0 * r0;
    const float volume_r0 =
        m_preview.volume_radius > 0.0f ? m_preview.volume_radius : diagonal / 100.0f;
    m_volume_radius2 = volume_r0 * volume_r0;

    // Without a surface that scatters specularly no photon can be caustic: none is traced
    // (a scene of a thousand lamps would otherwise probe a projection map for each).
    m_specular_surfaces = ProjectionMap::scene_has_specular_surfaces(scene);
    m_projections.assign(scene.lights().size(), std::nullopt);
    // Projection maps only aim photons: with none, many lights would cost seconds for nothing.
    // A projection map aims at where the specular objects stand at one time: in a scene that
    // moves, photons (each with its own time) go everywhere instead.
    const bool aim = m_preview.photons > 0 && !scene.has_motion();
    for (size_t i = 0; aim && i < scene.lights().size(); ++i) {
        m_projections[i] = ProjectionMap::make_if_useful(scene, *scene.lights()[i]);
    }

    // The ambient term stands for the light that is neither direct nor caustic, after
    // Cohen et al.'s ambient term of progressive radiosity (1988). Light leaving a surface
    // meets another with probability c (enclosure(), 1 in a closed room) and is reflected
    // there with an albedo taken as 1/2, so the light of all later bounces is the lights'
    // power times k / (1 - k), k = c / 2; spread over the surfaces (the bounding box's
    // area A stands for theirs), that is an irradiance of power x k / (1 - k) / A and a
    // radiance of albedo x that / pi. The fraction 1 - c of directions that escape sees
    // the constant background instead (an environment light is sampled as direct light).
    const float c = enclosure(scene);
    const float k = 0.5f * c;
    Spectrum power(0.0f);
    for (const auto& light : scene.lights()) {
        const Spectrum p = light->power();
        if (light.get() != scene.environment() && p.is_finite()) power += p;
    }
    const float area = 2.0f * (extent.x * extent.y + extent.y * extent.z + extent.z * extent.x);
    const Spectrum bounced = area > 0.0f ? power * (k / (1.0f - k) / (kPi * area)) : Spectrum(0.0f);
    const Spectrum sky = scene.environment() ? Spectrum(0.0f) : scene.background() * (1.0f - c);
    // Made with no wavelengths active: the Spectrum values here hold RGB.
    m_ambient = to_rgb((bounced + sky) * m_preview.ambient);
}

void PreviewIntegrator::trace_photons(const Scene& scene, RenderStats& stats) {
    if (m_photon_passes > 0) {
        const float shrink = (m_photon_passes + kRadiusShrinkAlpha) / (m_photon_passes + 1.0f);
        m_radius2 *= shrink;
        m_volume_radius2 *= shrink;
    }
    const uint64_t count = static_cast<uint64_t>(m_preview.photons);
    PhotonEmitter emitter = [this](const Light& light, const Vec2& u1, const Vec2& u2, float u3) {
        const auto& projection = m_projections[static_cast<size_t>(light.index())];
        return projection ? projection->sample(light, u1, u2, u3) : light.sample_le(u1, u2, u3);
    };
    const int max_bounces = m_settings.max_depth >= 0 ? m_settings.max_depth : 32;
    // Batch g is photons [g count, (g + 1) count) of one sequence: every batch differs, and
    // the same passes trace the same photons for any thread count.
    const uint64_t first = static_cast<uint64_t>(m_photon_passes) * count;
    std::vector<Photon> batch;
    std::vector<VolumePhoton> volume_batch;
    if (m_media) {
        trace_photons_in_media(scene, emitter, first, count, m_settings.seed + 1, max_bounces,
                               batch, volume_batch, stats.rays);
    } else if (m_specular_surfaces) {
        PhotonTracer tracer(scene, max_bounces, emitter, true);
        tracer.use_wavelengths(m_settings.spectral ? &m_pass_wavelengths : nullptr);
        const auto sinks = tracer.trace(first, count, m_settings.seed + 1, stats.rays,
                                        [] { return CausticSink{}; });
        for (const CausticSink& sink : sinks)
            batch.insert(batch.end(), sink.photons.begin(), sink.photons.end());
    }
    // Each batch is an estimate on its own: its photons carry power per emitted photon.
    const float scale = count > 0 ? 1.0f / static_cast<float>(count) : 0.0f;
    for (Photon& photon : batch) {
        photon.power *= scale;
        photon.set = m_photon_passes;  // its batch: spectral mode reads the newest alone
    }
    for (VolumePhoton& photon : volume_batch) photon.power *= scale;

    const size_t window = static_cast<size_t>(m_preview.window);
    const size_t slot = static_cast<size_t>(m_photon_passes) % window;
    if (m_batches.size() < window) {
        m_batches.push_back(std::move(batch));
        m_volume_batches.push_back(std::move(volume_batch));
    } else {
        m_batches[slot] = std::move(batch);
        m_volume_batches[slot] = std::move(volume_batch);
    }
    ++m_photon_passes;

    // The kept photons, batch after batch: the grid holds their positions, and the photons
    // follow its storage order, so that a query reads the photons it finds side by side.
    size_t total = 0;
    for (const std::vector<Photon>& b : m_batches) total += b.size();
    std::vector<Vec3> positions;
    std::vector<const Photon*> kept;
    positions.reserve(total);
    kept.reserve(total);
    for (const std::vector<Photon>& b : m_batches) {
        for (const Photon& photon : b) {
            positions.push_back(photon.p);
            kept.push_back(&photon);
        }
    }
    m_grid.build(positions, std::sqrt(m_radius2), HashGrid::Numbering::kStorage);
    m_photons.resize(kept.size());
    for (size_t k = 0; k < kept.size(); ++k) m_photons[k] = *kept[m_grid.order()[k]];
}

// What the lanes of a block of pixels carry from its camera packet to its shadow packet.
struct PreviewIntegrator::CameraLanes {
    PerLane<PassSampler> samplers;
    PerLane<Vec2i> pixels;
    PerLane<Ray> rays;
    PerLane<SurfaceInteraction> si;
    PerLane<SpecularChain> chains;  // for the lanes whose camera ray met a mirror or glass
    PerLane<Spectrum> L;
    HashGrid::Cache photon_cache;  // the lanes' caustic estimates, one after the other
};

// The caustic photons within the radius of `si`, each batch an estimate of its own (Knaus
// and Zwicker): sum f Phi / (pi r^2) over the photons, divided by the batches kept.
Spectrum PreviewIntegrator::caustic_estimate(const SurfaceInteraction& si, const Bsdf& bsdf,
                                             HashGrid::Cache& cache) const {
    const Vec3 wo = si.to_local(si.wo);
    const float viewer_side = glm::dot(si.wo, si.ng);
    Spectrum sum(0.0f);
    // Spectral mode: the older batches carry other passes' wavelengths, so only this pass's
    // batch is read (it is an estimate on its own).
    const int newest = m_photon_passes - 1;
    // Strictly within the radius.
    m_grid.for_each_near<HashGrid::Ball::kOpen>(si.p, cache, [&](uint32_t index, float) {
        const Photon& photon = m_photons[index];
        if (m_settings.spectral && photon.set != newest) return;
        if (glm::dot(photon.wi, si.ng) * viewer_side <= 0.0f) return;  // the other side
        sum += bsdf.eval(wo, si.to_local(photon.wi)) * photon.power;
    });
    const float batches = m_settings.spectral ? 1.0f : static_cast<float>(m_batches.size());
    return sum / (kPi * m_radius2 * batches);
}

// Light leaving the first surface that is not purely specular towards the camera, but for
// the direct light: the caustic photons, and the path-traced bounces (or the ambient term).
Spectrum PreviewIntegrator::indirect_estimate(const Scene& scene, const SurfaceInteraction& si,
                                              const Bsdf& bsdf, Spectrum reflected,
                                              Sampler& sampler, Arena& arena, RayCounter& counter,
                                              HashGrid::Cache& cache) const {
    if (m_grid.size() > 0) reflected += caustic_estimate(si, bsdf, cache);
    if (m_preview.bounces > 0)
        reflected += bounce_estimate(scene, si, bsdf, sampler, arena, counter);
    else
        reflected += uplift(m_ambient, RgbRole::illuminant) * si.material->albedo(si);
    return reflected;
}

// The indirect light at the first non-specular surface x1 (reached from the camera through
// mirrors and glass, E S* x1), by a path of m_preview.bounces non-specular vertices x2, x3,
// ... traced from x1 by BSDF sampling, each found through any number of mirrors and glass,
// with next-event estimation at each. Which paths each of the preview's estimators carries,
// so that none is counted twice (S: a delta lobe, D: any other, L: a light):
//   direct light (ReSTIR or one light sample) at x1:        E S* x1 L
//   caustic photons at x1 (photons that met mirrors or glass
//   between the light and x1):                               E S* x1 S+ L
//   next-event estimation at x_k, k >= 2 (here):            E S* x1 (S* D){k-1} L
//   emission that BSDF sampling from x_k reaches through
//   one or more delta lobes, k >= 2 (here):                  E S* x1 (S* D){k-2} S+ L
// So emission that BSDF sampling reaches directly (x_k D-sampled straight into a light) is
// never counted here (next-event estimation has it, with no MIS), and emission reached
// from x1 through mirrors or glass is left to the photons; with preview_photons = 0 nothing
// else has those caustic paths, and the bounce counts them. A ray that escapes gathers a
// constant background always (nothing samples it) and an environment light only after a
// delta lobe (next-event estimation samples it otherwise). With these, the preview
// converges to `path`'s image where the scene has no caustics (longer caustic paths such as
// x1 D S+ L are counted, and are path's too; the only caustics it does not count are the
// ones the photons estimate with their radius' blur).
Spectrum PreviewIntegrator::bounce_estimate(const Scene& scene, const SurfaceInteraction& first,
                                            const Bsdf& first_bsdf, Sampler& sampler, Arena& arena,
                                            RayCounter& counter) const {
    const bool photons_carry_caustics = m_preview.photons > 0;
    Spectrum L(0.0f), beta(1.0f);
    SurfaceInteraction at = first;
    const Bsdf* bsdf = &first_bsdf;
    for (int bounce = 1; bounce <= m_preview.bounces; ++bounce) {
        std::optional<Scattering> scattering =
            sample_scattering(at, *bsdf, at.to_local(at.wo), sampler.get_2d(), sampler.get_1d());
        if (!scattering) break;
        beta *= scattering->weight;
        bool through_delta = scattering->sample.is_delta();
        // Emission reached through delta lobes, which next-event estimation cannot find.
        const bool count_caustic = bounce > 1 || !photons_carry_caustics;
        Ray ray = spawn_ray(at, scattering->wi);
        SurfaceInteraction next;
        const Bsdf* next_bsdf = nullptr;
        for (int segment = 0; segment < kMaxCameraSegments; ++segment) {
            ++counter.rays;
            if (!scene.intersect(ray, next)) {
                if (!scene.environment() || (through_delta && count_caustic))
                    L += beta * scene.escaped_radiance(ray.direction);
                return L;
            }
            beta *= segment_transmittance(ray, next);
            if (through_delta && count_caustic) L += beta * emitted_radiance(next);
            next_bsdf = shade(scene, ray, next, arena);
            if (!next_bsdf || !next_bsdf->is_delta()) break;
            scattering = sample_scattering(next, *next_bsdf, next.to_local(next.wo),
                                           sampler.get_2d(), sampler.get_1d());
            if (!scattering) return L;
            beta *= scattering->weight;
            through_delta = true;
            ray = spawn_specular_ray(next, ray, scattering->wi,
                                     scattering->sample.is_transmission(), scattering->sample.eta);
            next_bsdf = nullptr;
        }
        if (!next_bsdf || next_bsdf->is_delta()) break;
        L += beta * estimate_direct_light(scene, next, *next_bsdf, sampler, LightWeighting::kNone,
                                          counter);
        at = next;
        bsdf = next_bsdf;
    }
    return L;
}

// The one-ray form, which the packet form below must match bit for bit (it is tested
// against it): radiance along a camera ray through mirrors and glass to the first surface
// that is not purely specular, where direct light, the caustic photons and the ambient
// term meet.
Spectrum PreviewIntegrator::camera_sample(const Scene& scene, const Ray& ray, Sampler& sampler,
                                          Arena& arena, RayCounter& counter,
                                          HashGrid::Cache& cache) const {
    const SpecularChain chain = follow_specular_chain(scene, ray, Spectrum(1.0f), sampler, arena,
                                                      counter, kMaxCameraSegments, nullptr);
    Spectrum L = chain.emitted;
    if (chain.escaped) return L + chain.beta * scene.escaped_radiance(chain.ray.direction);
    if (!chain.hit) return L;
    const SurfaceInteraction& si = *chain.hit;
    const Bsdf& bsdf = *chain.bsdf;
    const Spectrum direct =
        estimate_direct_light(scene, si, bsdf, sampler, LightWeighting::kNone, counter);
    return L +
           chain.beta * indirect_estimate(scene, si, bsdf, direct, sampler, arena, counter, cache);
}

Ray PreviewIntegrator::pass_camera_ray(const Scene& scene, PassSampler& sampler, Vec2i pixel,
                                       int pass) {
    sampler.start_pixel_sample(pixel, pass);
    const Vec2 film_point = Vec2(pixel) + sampler.get_pixel_2d();
    return scene.camera().sample_ray(film_point, sampler);
}

// The camera rays of the block whose top-left pixel is `corner` (its lanes inside the film,
// which it returns) in pass `pass`, traced as one packet into `si`; `hit` receives the lanes
// that hit something.
uint32_t PreviewIntegrator::trace_camera_block(const Scene& scene, const Film& film, Vec2i corner,
                                               int pass, PerLane<PassSampler>& samplers,
                                               PerLane<Ray>& rays, PerLane<SurfaceInteraction>& si,
                                               uint32_t& hit, RayCounter& counter) {
    uint32_t active = 0;
    PerLane<const Ray*> ray_of{};
    PerLane<SurfaceInteraction*> si_of{};
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        const int x = corner.x + lane % kBlockWidth, y = corner.y + lane / kBlockWidth;
        if (x >= film.width() || y >= film.height()) continue;
        // The film may be a window: pixels are named in the full image.
        rays[lane] = pass_camera_ray(scene, samplers[lane], film.origin() + Vec2i(x, y), pass);
        ray_of[lane] = &rays[lane];
        si_of[lane] = &si[lane];
        active |= 1u << lane;
    }
    counter.rays += static_cast<uint64_t>(std::popcount(active));
    hit = scene.intersect_packet(ray_of, active, si_of, true);
    return active;
}

// The packet form: the camera rays of a block of 4 x 2 pixels are traced as one Embree
// packet, and the shadow rays of their direct-light samples as another; both are coherent
// (neighbouring pixels, one light), which Embree's packet kernels turn into fewer
// instructions per ray. A ray whose first hit is a mirror or glass goes on alone, retraced
// from the camera by follow_specular_chain (a few pixels; the chain then draws exactly
// what the one-ray form draws). Each lane takes the steps camera_sample() takes with the
// same draws, so each pixel gets what camera_sample() gives it, bit for bit.
void PreviewIntegrator::render_block(const Scene& scene, Film& film, Vec2i corner, int pass,
                                     CameraLanes& lanes, Arena& arena, RayCounter& counter) const {
    arena.reset();
    uint32_t hit = 0;
    const uint32_t active = trace_camera_block(scene, film, corner, pass, lanes.samplers,
                                               lanes.rays, lanes.si, hit, counter);
    for_each_lane(active, [&](int lane) {
        // The film may be a window: pixels are named in the full image.
        lanes.pixels[lane] = film.origin() + corner + Vec2i(lane % kBlockWidth, lane / kBlockWidth);
    });

    PerLane<Spectrum> emitted, beta, reflected;
    PerLane<const SurfaceInteraction*> surface{};
    PerLane<const Bsdf*> bsdf_of{};
    PerLane<Vec3> shadow_origins, shadow_directions;
    PerLane<float> shadow_times;
    uint32_t shading = 0, shadowed = 0;
    for_each_lane(active, [&](int lane) {
        const Ray& ray = lanes.rays[lane];
        Spectrum& L = lanes.L[lane];
        if (!(hit & (1u << lane))) {
            L = scene.escaped_radiance(ray.direction);
            return;
        }
        SurfaceInteraction& si = lanes.si[lane];
        beta[lane] = segment_transmittance(ray, si);
        emitted[lane] = beta[lane] * emitted_radiance(si);
        const Bsdf* bsdf = shade(scene, ray, si, arena);
        surface[lane] = &si;
        if (bsdf && bsdf->is_delta()) {
            // Through mirrors and glass, one ray at a time, from the camera again: the chain
            // traces and counts the camera ray anew (few pixels see a mirror or glass).
            --counter.rays;
            lanes.chains[lane] =
                follow_specular_chain(scene, ray, Spectrum(1.0f), lanes.samplers[lane], arena,
                                      counter, kMaxCameraSegments, nullptr);
            const SpecularChain& chain = lanes.chains[lane];
            emitted[lane] = chain.emitted;
            beta[lane] = chain.beta;
            if (chain.escaped) {
                L = chain.emitted + chain.beta * scene.escaped_radiance(chain.ray.direction);
                return;
            }
            bsdf = chain.hit ? chain.bsdf : nullptr;
            if (chain.hit) surface[lane] = &*chain.hit;
        }
        if (!bsdf) {
            L = emitted[lane];
            return;
        }
        bsdf_of[lane] = bsdf;
        shading |= 1u << lane;
        const SurfaceInteraction& at = *surface[lane];
        reflected[lane] = Spectrum(0.0f);
        const std::optional<DirectLight> direct = sample_direct_light(
            scene, at, *bsdf, at.to_local(at.wo), lanes.samplers[lane], LightWeighting::kNone);
        if (!direct) return;
        reflected[lane] = direct->contribution;
        const Scene::ShadowRay shadow = Scene::shadow_ray(at, direct->target);
        shadow_origins[lane] = shadow.origin;
        shadow_directions[lane] = shadow.direction;
        shadow_times[lane] = shadow.time;
        shadowed |= 1u << lane;
        ++counter.rays;
    });
    if (shadowed != 0) {
        const uint32_t blocked =
            scene.occluded_packet(shadow_origins, shadow_directions, shadow_times, shadowed, true);
        for_each_lane(blocked, [&](int lane) {
            // A surface that only bounds media may have blocked it: what it lets through.
            reflected[lane] =
                scene.has_interfaces()
                    ? reflected[lane] *
                          transmittance_through_interfaces(
                              scene, Scene::ShadowRay{shadow_origins[lane], shadow_directions[lane],
                                                      shadow_times[lane]})
                    : Spectrum(0.0f);
        });
    }
    for_each_lane(shading, [&](int lane) {
        lanes.L[lane] =
            emitted[lane] + beta[lane] * indirect_estimate(scene, *surface[lane], *bsdf_of[lane],
                                                           reflected[lane], lanes.samplers[lane],
                                                           arena, counter, lanes.photon_cache);
    });
    for_each_lane(active, [&](int lane) {
        film.add_sample(lanes.pixels[lane], lanes.L[lane], 1.0f, nullptr);
    });
}

RenderStats PreviewIntegrator::render_pass(const Scene& scene, Film& film, int pass,
                                           Progress& progress) {
    if (pass < 0) throw Error(fmt::format("preview: pass {} is negative", pass));
    RenderStats stats;
    const auto start = std::chrono::steady_clock::now();
    if (m_settings.spectral && m_preview.restir.mode != RestirMode::kOff) {
        throw Error(fmt::format(
            "{}: preview_restir keeps the previous pass's surfaces, whose BSDFs hold that "
            "pass's wavelengths; spectral mode needs preview_restir = \"off\"",
            m_settings.where_of("spectral")));
    }
    // Spectral mode: this pass's camera paths and photons carry one set of wavelengths.
    if (m_settings.spectral)
        m_pass_wavelengths =
            pass_wavelengths(mix_bits(m_settings.seed ^ 0x6a09e667u), m_spectral_passes++);
    const WavelengthContext* wavelengths = m_settings.spectral ? &m_pass_wavelengths : nullptr;
    if (m_scene != &scene) restart(scene);
    trace_photons(scene, stats);
    // Volume photons are seen from this pass's camera (it may have moved since they were traced).
    if (m_media) {
        m_volume_view.build(scene, m_media->camera, m_volume_batches,
                            m_settings.spectral ? m_photon_passes - 1 : -1, m_volume_radius2,
                            film.origin(), Vec2i(film.width(), film.height()),
                            m_settings.spectral ? &m_pass_wavelengths : nullptr);
    }
    m_timing.photons = seconds_since(start);

    const auto camera_start = std::chrono::steady_clock::now();
    const int w = film.width(), h = film.height();
    std::atomic<uint64_t> camera_rays{0};
    // In media that scatter the camera paths carry their medium one ray at a time
    // (preview_media.h); ReSTIR and the packets serve scenes without.
    if (m_media) {
        uint64_t rays = 0;
        render_media_pass(scene, film, pass, rays);
        camera_rays += rays;
    } else if (m_preview.restir.mode != RestirMode::kOff) {
        render_restir_pass(scene, film, pass, stats);
    } else {
        // Blocks of 4 x 2 pixels, a few rows of them per task, with one set of samplers and an
        // arena per task. Each pixel's sample depends only on (seed, pixel, pass) and the
        // photons, so the image is the same for any threads.
        const int block_rows = (h + kBlockHeight - 1) / kBlockHeight;
        tbb::parallel_for(
            tbb::blocked_range<int>(0, block_rows, 2), [&](const tbb::blocked_range<int>& rows) {
                std::optional<WavelengthScope> scope;
                if (wavelengths != nullptr) scope.emplace(*wavelengths);
                Arena arena;
                RayCounter counter;
                if (m_packets) {
                    auto lanes = std::make_unique<CameraLanes>();
                    for (PassSampler& sampler : lanes->samplers) sampler.set_seed(m_settings.seed);
                    for (int row = rows.begin(); row < rows.end(); ++row) {
                        for (int x = 0; x < w; x += kBlockWidth) {
                            // The block's paths share one dispersion state: one lane's
                            // dispersive glass has all eight read at the hero alone (still an
                            // estimate of their colour).
                            std::optional<SecondaryWavelengthsScope> terminated;
                            if (wavelengths != nullptr) terminated.emplace();
                            render_block(scene, film, Vec2i(x, row * kBlockHeight), pass, *lanes,
                                         arena, counter);
                        }
                    }
                } else {
                    PassSampler sampler;
                    sampler.set_seed(m_settings.seed);
                    HashGrid::Cache cache;
                    for (int y = rows.begin() * kBlockHeight;
                         y < std::min(h, rows.end() * kBlockHeight); ++y) {
                        for (int x = 0; x < w; ++x) {
                            const Vec2i pixel = film.origin() + Vec2i(x, y);
                            const Ray ray = pass_camera_ray(scene, sampler, pixel, pass);
                            arena.reset();
                            std::optional<SecondaryWavelengthsScope> terminated;
                            if (wavelengths != nullptr) terminated.emplace();
                            film.add_sample(
                                pixel, camera_sample(scene, ray, sampler, arena, counter, cache),
                                1.0f, nullptr);
                        }
                    }
                }
                camera_rays += counter.rays;
            });
    }
    stats.rays += camera_rays.load();
    m_timing.camera = seconds_since(camera_start);
    const uint64_t pixels = static_cast<uint64_t>(w) * static_cast<uint64_t>(h);
    stats.samples = pixels;
    progress.advance(pixels);
    stats.seconds = seconds_since(start);
    return stats;
}

size_t PreviewIntegrator::stored_volume_photons() const {
    size_t total = 0;
    for (const std::vector<VolumePhoton>& batch : m_volume_batches) total += batch.size();
    return total;
}

RenderStats PreviewIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    m_scene = nullptr;  // a render starts from no photons
    m_spectral_passes = 0;
    RenderStats stats;
    double photon_seconds = 0.0;
    for (int pass = 0; pass < m_settings.spp; ++pass) {
        const RenderStats pass_stats = render_pass(scene, film, pass, progress);
        stats.samples += pass_stats.samples;
        stats.rays += pass_stats.rays;
        photon_seconds += m_timing.photons;
    }
    stats.seconds = seconds_since(start);
    if (m_media) {
        stats.notes.push_back(fmt::format(
            "preview: {} volume photons kept, final volume radius {:.4g}; single scattering "
            "and volumetric caustics only (multiple scattering in media is volpath's)",
            stored_volume_photons(), volume_radius()));
        if (m_preview.restir.mode != RestirMode::kOff)
            stats.notes.push_back("preview: preview_restir is not used in media that scatter");
    }
    stats.notes.push_back(fmt::format(
        "preview: {} passes, {} caustic photons kept from the last {} batches, final radius "
        "{:.4g}; photon passes took {:.2f} s of {:.2f} s",
        m_photon_passes, m_grid.size(), m_batches.size(), std::sqrt(m_radius2), photon_seconds,
        stats.seconds));
    return stats;
}

}  // namespace glint
