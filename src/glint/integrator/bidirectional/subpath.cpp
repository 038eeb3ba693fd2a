#include <glint/integrator/bidirectional/subpath.h>
#include <glint/integrator/transport/light_path_start.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>

namespace glint {
namespace {

// Unit direction from `from` towards `to` (towards the sky for a vertex at infinity).
Vec3 direction_to(const PathVertex& from, const PathVertex& to) {
    return to.infinite ? to.w_sky : glm::normalize(to.p - from.p);
}

// Appends to `path` the vertices a ray leaving path.back() finds, scattering in `mode`.
// `beta` is the throughput carried by `ray`, `pdf_dir` the solid-angle density with which
// path.back() chose it.
void random_walk(const Scene& scene, Ray ray, Spectrum beta, float pdf_dir, TransportMode mode,
                 Sampler& sampler, Arena& arena, RayCounter& counter, const WalkLimits& limits,
                 std::vector<PathVertex>& path) {
    // Roulette looks at the throughput of the scattering alone (the path tracer's rule), with
    // the radiance scaling of refraction taken out, so light about to leave glass survives.
    Spectrum rr_beta(1.0f);
    float eta_scale = 1.0f;
    while (static_cast<int>(path.size()) < limits.max_vertices) {
        ++counter.rays;
        PathVertex vertex;
        if (!scene.intersect(ray, vertex.si)) {
            // A camera walk that escapes sees the environment (or the background) there.
            if (mode == TransportMode::kRadiance) {
                vertex.kind = PathVertex::Kind::kEscape;
                vertex.infinite = true;
                vertex.w_sky = glm::normalize(ray.direction);
                vertex.light = scene.environment();
                vertex.beta = beta;
                vertex.pdf_fwd = pdf_dir;
                path.push_back(std::move(vertex));
            }
            return;
        }
        const Spectrum transmittance = segment_transmittance(ray, vertex.si);
        beta *= transmittance;
        rr_beta *= transmittance;
        vertex.kind = PathVertex::Kind::kSurface;
        vertex.p = vertex.si.p;
        vertex.ng = vertex.si.ng;
        vertex.light = vertex.si.area_light;
        vertex.beta = beta;
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

        // Throughput roulette: from the third hit on (depth 2), survival in proportion to the
        // throughput, where it is below 1 (not path's square root: transport/roulette.h).
        const int depth = static_cast<int>(path.size()) - 2;
        float survival = 1.0f;
        if (limits.roulette && !survives_throughput_roulette(
                                   depth, (rr_beta * eta_scale).max_value(),
                                   [&] { return sampler.get_1d(); }, survival))
            return;
        if (survival < 1.0f) {
            beta /= survival;
            rr_beta /= survival;
        }
        if (beta.is_black()) return;
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
    return pdf;
}

void generate_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, Arena& arena,
                             RayCounter& counter, const WalkLimits& limits,
                             std::vector<PathVertex>& path) {
    path.clear();
    const CameraPdf pdf = scene.camera().pdf_we_at(ray);
    PathVertex lens;
    lens.kind = PathVertex::Kind::kCamera;
    lens.p = ray.origin;
    lens.si.time = ray.time;  // the path's scene time
    // The camera ray's weight We cos / (pdf_pos pdf_dir) is 1 (camera.h).
    lens.beta = Spectrum(1.0f);
    lens.pdf_fwd = pdf.pos;
    path.push_back(std::move(lens));
    random_walk(scene, ray, Spectrum(1.0f), pdf.dir, TransportMode::kRadiance, sampler, arena,
                counter, limits, path);
}

void generate_light_subpath(const Scene& scene, float time, Sampler& sampler, Arena& arena,
                            RayCounter& counter, const WalkLimits& limits,
                            std::vector<PathVertex>& path) {
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
    path.push_back(std::move(start));
    const Spectrum& beta = begun->beta;
    if (beta.is_black() || limits.max_vertices < 2) return;
    random_walk(scene, emission->ray, beta, emission->pdf_dir, TransportMode::kImportance, sampler,
                arena, counter, limits, path);
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
    } else {
        if (!v.bsdf || !prev) return 0.0f;
        const Vec3 w_prev = direction_to(v, *prev);
        pdf = v.bsdf->pdf(v.si.to_local(w_prev), v.si.to_local(w_next));
    }
    return solid_angle_to_area(pdf, v, next);
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
