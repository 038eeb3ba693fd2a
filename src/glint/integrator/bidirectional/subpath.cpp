#include <glint/integrator/bidirectional/subpath.h>
#include <glint/integrator/transport/light_path_start.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/medium/delta_tracking.h>
#include <glint/medium/henyey_greenstein.h>

#include <bit>

namespace glint {
namespace {

// Unit direction from `from` towards `to` (towards the sky for a vertex at infinity).
Vec3 direction_to(const PathVertex& from, const PathVertex& to) {
    return to.infinite ? to.w_sky : glm::normalize(to.p - from.p);
}

// Crossings of interfaces (surfaces that only bound media) a walk may make in a row before
// it is given up: a ray caught between coincident interfaces would never end.
constexpr int kMaxCrossings = 1024;

// Appends to `path` the vertices a ray leaving path.back() finds, scattering in `mode`.
// `beta` is the throughput carried by `ray`, `pdf_dir` the solid-angle density with which
// path.back() chose it; with `media`, `medium` is the medium the ray starts in.
void random_walk(const Scene& scene, Ray ray, Spectrum beta, float pdf_dir, TransportMode mode,
                 Sampler& sampler, Arena& arena, RayCounter& counter, const WalkLimits& limits,
                 std::vector<PathVertex>& path, MediaWalk* media, const Medium* medium) {
    // Roulette looks at the throughput of the scattering alone (the path tracer's rule), with
    // the radiance scaling of refraction taken out, so light about to leave glass survives.
    Spectrum rr_beta(1.0f);
    float eta_scale = 1.0f;
    Spectrum r_u(1.0f);
    int crossings = 0;
    // Throughput roulette: from the third hit on (depth 2), survival in proportion to the
    // throughput, where it is below 1 (not path's square root: transport/roulette.h). In
    // media over the hero's density averaged with the other channels' (volpath's rule).
    const auto survives_roulette = [&] {
        const int depth = static_cast<int>(path.size()) - 2;
        float survival = 1.0f;
        const float throughput = media ? (rr_beta * eta_scale / r_u.average()).max_value()
                                       : (rr_beta * eta_scale).max_value();
        if (limits.roulette && !survives_throughput_roulette(
                                   depth, throughput, [&] { return sampler.get_1d(); }, survival))
            return false;
        if (survival < 1.0f) {
            beta /= survival;
            rr_beta /= survival;
        }
        return !beta.is_black();
    };
    PassedSurfaces passed;
    while (static_cast<int>(path.size()) < limits.max_vertices) {
        ++counter.rays;
        PathVertex vertex;
        // In media, one traversal past the interfaces Embree can skip (passed.count stays 0
        // otherwise): the legs between them are segments of their own media.
        passed.count = 0;
        const bool hit = media ? scene.intersect_surface_passing(ray, vertex.si, passed)
                               : scene.intersect(ray, vertex.si);
        const Ray traced = ray;
        SegmentEnd end = SegmentEnd::kReached;
        float t_scatter = 0.0f, sigma_t = 0.0f;
        if (media) {
            walk_legs(
                scene, traced, passed, hit ? vertex.si.t : kInfinity, medium,
                [&](const Ray& leg, float length) {
                    ray = leg;
                    // Emission along the leg: a camera walk collects it where the path
                    // so far (its scattering vertices) leaves room under max_vertices.
                    const int depth = static_cast<int>(path.size()) - 1;
                    const bool collect = mode == TransportMode::kRadiance && medium->emits() &&
                                         (media->emission_depth == MediaWalk::kEveryDepth
                                              ? depth + 2 < limits.max_vertices
                                              : depth == media->emission_depth);
                    Spectrum weight, emitted;
                    end = through_medium(*medium, ray, length, media->hero, media->rng, weight, r_u,
                                         t_scatter, sigma_t, collect ? &emitted : nullptr);
                    if (collect) media->emitted += beta * emitted;
                    beta *= weight;
                    rr_beta *= weight;
                    return end == SegmentEnd::kReached;
                });
            crossings += passed.count;
            if (crossings > kMaxCrossings) return;
        }
        if (end == SegmentEnd::kAbsorbed) return;
        if (end == SegmentEnd::kReached) ray = traced;
        if (end == SegmentEnd::kScattered) {
            vertex.kind = PathVertex::Kind::kMedium;
            vertex.p = ray.at(t_scatter);
            vertex.si.p = vertex.p;
            vertex.si.wo = -glm::normalize(ray.direction);
            vertex.si.time = ray.time;
            vertex.medium = medium;
            vertex.sigma_t = sigma_t;
            vertex.beta = beta;
            vertex.r_u = r_u;
            vertex.pdf_fwd = solid_angle_to_area(pdf_dir, path.back(), vertex);
            path.push_back(std::move(vertex));
            PathVertex& v = path.back();
            PathVertex& prev = path[path.size() - 2];
            if (static_cast<int>(path.size()) >= limits.max_vertices) return;
            // Phase sampling is exact: the throughput keeps its value. Henyey-Greenstein
            // is symmetric, so the reverse density is the forward one.
            const HenyeyGreenstein phase(medium->phase_asymmetry());
            const PhaseSample ps = phase.sample(v.si.wo, sampler.get_2d());
            if (!(ps.p > 0.0f)) return;
            pdf_dir = ps.p;
            prev.pdf_rev = solid_angle_to_area(ps.p, v, prev);
            ray = Ray{v.p, ps.wi, 0.0f, kInfinity, ray.time};
            if (!survives_roulette()) return;
            continue;
        }
        if (!hit) {
            // A camera walk that escapes sees the environment (or the background) there.
            if (mode == TransportMode::kRadiance) {
                vertex.kind = PathVertex::Kind::kEscape;
                vertex.infinite = true;
                vertex.w_sky = glm::normalize(ray.direction);
                vertex.light = scene.environment();
                vertex.beta = beta;
                vertex.r_u = r_u;
                vertex.medium = medium;
                vertex.pdf_fwd = pdf_dir;
                path.push_back(std::move(vertex));
            }
            return;
        }
        if (media && vertex.si.material->is_interface()) {
            // Only the medium changes: the ray goes straight on, and no vertex is made.
            medium = medium_beyond(vertex.si, ray.direction, medium);
            ray = spawn_ray(vertex.si, ray.direction);
            if (++crossings > kMaxCrossings) return;
            continue;
        }
        if (!media) {
            const Spectrum transmittance = segment_transmittance(ray, vertex.si);
            beta *= transmittance;
            rr_beta *= transmittance;
        }
        vertex.kind = PathVertex::Kind::kSurface;
        vertex.p = vertex.si.p;
        vertex.ng = vertex.si.ng;
        vertex.light = vertex.si.area_light;
        vertex.beta = beta;
        vertex.r_u = r_u;
        vertex.medium = medium;
        vertex.pdf_fwd = solid_angle_to_area(pdf_dir, path.back(), vertex);
        vertex.bsdf = shade(scene, ray, vertex.si, arena);
        path.push_back(std::move(vertex));
        PathVertex& v = path.back();
        PathVertex& prev = path[path.size() - 2];
        if (!v.bsdf || static_cast<int>(path.size()) >= limits.max_vertices) return;

        const Vec3 wo_local = v.si.to_local(v.si.wo);
        const Vec2 u = sampler.get_2d();
        const float u_lobe = sampler.get_1d();
        const std::optional<Scattering> scattering =
            sample_scattering(v.si, *v.bsdf, wo_local, u, u_lobe, mode);
        if (!scattering) return;
        const BsdfSample& bs = scattering->sample;
        // The reverse density: the walk from the other end, arriving along wi, choosing wo.
        float pdf_rev = 0.0f;
        if (bs.is_delta()) {
            v.delta = true;
            pdf_dir = 0.0f;
        } else {
            pdf_dir = bs.pdf;
            pdf_rev = v.bsdf->pdf(bs.wi, wo_local);
        }
        prev.pdf_rev = solid_angle_to_area(pdf_rev, v, prev);
        beta *= scattering->weight;
        rr_beta *= scattering->weight;
        if (mode == TransportMode::kRadiance && bs.is_transmission()) eta_scale *= bs.eta * bs.eta;
        continue_ray(ray, v.si, *scattering);
        if (media) medium = medium_beyond(v.si, ray.direction, medium);
        crossings = 0;
        if (!survives_roulette()) return;
    }
}

}  // namespace

float solid_angle_to_area(float pdf_solid, const PathVertex& from, const PathVertex& to) {
    if (to.infinite) return pdf_solid;
    const Vec3 d = to.p - from.p;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return 0.0f;
    float pdf = pdf_solid / dist2;
    if (to.ng != Vec3(0.0f)) pdf *= std::abs(glm::dot(to.ng, d)) / std::sqrt(dist2);
    if (to.is_medium()) pdf *= to.sigma_t;
    return pdf;
}

void generate_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, Arena& arena,
                             RayCounter& counter, const WalkLimits& limits,
                             std::vector<PathVertex>& path, MediaWalk* media) {
    path.clear();
    const CameraPdf pdf = scene.camera().pdf_we_at(ray);
    PathVertex lens;
    lens.kind = PathVertex::Kind::kCamera;
    lens.p = ray.origin;
    lens.si.time = ray.time;  // the path's scene time
    // The camera ray's weight We cos / (pdf_pos pdf_dir) is 1 (camera.h).
    lens.beta = Spectrum(1.0f);
    lens.pdf_fwd = pdf.pos;
    lens.medium = media ? media->media->camera : nullptr;
    const Medium* const start_medium = lens.medium;
    path.push_back(std::move(lens));
    random_walk(scene, ray, Spectrum(1.0f), pdf.dir, TransportMode::kRadiance, sampler, arena,
                counter, limits, path, media, start_medium);
}

void generate_light_subpath(const Scene& scene, float time, Sampler& sampler, Arena& arena,
                            RayCounter& counter, const WalkLimits& limits,
                            std::vector<PathVertex>& path, MediaWalk* media) {
    path.clear();
    LightPathSamples u_start;
    u_start.time = time;
    u_start.u_light = sampler.get_1d();
    u_start.u_position = sampler.get_2d();
    u_start.u_direction = sampler.get_2d();
    u_start.u_select = sampler.get_1d();
    const std::optional<LightPathStart> begun = start_light_path(scene, u_start);
    if (!begun) return;
    const Light& light = *begun->light;
    const LightEmission* const emission = &begun->emission;
    if (!(emission->pdf_pos > 0.0f) || !(emission->pdf_dir > 0.0f)) return;
    PathVertex start;
    start.kind = PathVertex::Kind::kLight;
    start.light = &light;
    start.infinite = light.is_infinite() || light.is_delta_direction();
    start.p = emission->ray.origin;
    start.si.time = time;
    start.ng = emission->n;
    start.w_sky = -emission->ray.direction;
    start.beta = emission->Le;
    // A light at infinity starts with its direction (solid angle), then a point on the disc
    // its rays cross; every other light with its point, then a direction.
    start.pdf_fwd = begun->pmf * (start.infinite ? emission->pdf_dir : emission->pdf_pos);
    if (media) {
        const auto& starts = media->media->light_start;
        const int index = light.index();
        start.medium =
            index >= 0 && static_cast<size_t>(index) < starts.size() ? starts[index] : nullptr;
    }
    const Medium* const start_medium = start.medium;
    path.push_back(std::move(start));
    const Spectrum& beta = begun->beta;
    if (beta.is_black() || limits.max_vertices < 2) return;
    random_walk(scene, emission->ray, beta, emission->pdf_dir, TransportMode::kImportance, sampler,
                arena, counter, limits, path, media, start_medium);
    if (path.front().infinite && path.size() > 1) {
        PathVertex& first = path[1];
        first.pdf_fwd = emission->pdf_pos;
        if (first.is_surface())
            first.pdf_fwd *= std::abs(glm::dot(first.ng, emission->ray.direction));
    }
}

float continuation_pdf(const Scene& scene, const PathVertex* prev, const PathVertex& v,
                       const PathVertex& next) {
    const Vec3 w_next = direction_to(v, next);
    float pdf = 0.0f;
    if (v.kind == PathVertex::Kind::kCamera) {
        pdf = scene.camera().pdf_we_at(Ray{v.p, w_next, 0.0f, kInfinity, v.si.time}).dir;
    } else if (v.is_medium()) {
        if (!prev) return 0.0f;
        pdf = HenyeyGreenstein(v.medium->phase_asymmetry()).eval(direction_to(v, *prev), w_next);
    } else {
        if (!v.bsdf || !prev) return 0.0f;
        const Vec3 w_prev = direction_to(v, *prev);
        pdf = v.bsdf->pdf(v.si.to_local(w_prev), v.si.to_local(w_next));
    }
    return solid_angle_to_area(pdf, v, next);
}

std::optional<MediaWalk> start_media_walk(const WalkMedia* media, Sampler& sampler) {
    if (!media) return std::nullopt;
    MediaWalk walk;
    walk.media = media;
    walk.hero = std::min(static_cast<int>(sampler.get_1d() * Spectrum::active_values()),
                         Spectrum::active_values() - 1);
    walk.rng.seed(stream_seed(sampler.get_1d()));
    return walk;
}

Spectrum scattering_towards(const PathVertex& v, const Vec3& w, TransportMode mode) {
    if (v.is_medium())
        return Spectrum(HenyeyGreenstein(v.medium->phase_asymmetry()).eval(v.si.wo, w));
    const Vec3 w_local = v.si.to_local(w);
    const Vec3 wo_local = v.si.to_local(v.si.wo);
    const Spectrum f = mode == TransportMode::kImportance
                           ? v.bsdf->eval(wo_local, w_local, mode, v.si.to_local(v.si.ng))
                           : v.bsdf->eval(wo_local, w_local);
    return f * abs_cos_theta(w_local);
}

const Medium* medium_leaving(const PathVertex& v, const Vec3& w) {
    if (v.is_surface()) return medium_beyond(v.si, w, v.medium);
    return v.medium;
}

float emission_pdf(const PathVertex& v, const PathVertex& next) {
    if (!v.light) return 0.0f;
    if (v.infinite) {
        float pdf = v.light->pdf_le(Ray{next.p, -v.w_sky}, Vec3(0.0f)).pos;
        if (next.is_surface()) pdf *= std::abs(glm::dot(next.ng, v.w_sky));
        return pdf;
    }
    const Vec3 w = glm::normalize(next.p - v.p);
    return solid_angle_to_area(v.light->pdf_le(Ray{v.p, w}, v.ng).dir, v, next);
}

float emission_origin_pdf(const Scene& scene, const PathVertex& v, const PathVertex& next) {
    if (!v.light) return 0.0f;
    const float pmf = scene.light_sampler().pmf(*v.light);
    if (v.infinite) return pmf * v.light->pdf_le(Ray{next.p, -v.w_sky}, Vec3(0.0f)).dir;
    const Vec3 w = glm::normalize(next.p - v.p);
    return pmf * v.light->pdf_le(Ray{v.p, w}, v.ng).pos;
}

}  // namespace glint
