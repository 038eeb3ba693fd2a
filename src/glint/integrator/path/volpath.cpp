#include <glint/integrator/path/volpath.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>
#include <glint/material/material.h>
#include <glint/medium/delta_tracking.h>
#include <glint/medium/henyey_greenstein.h>

#include <bit>

namespace glint {

// One camera path between the steps of a bounce.
struct VolPathIntegrator::Walk {
    Spectrum L{0.0f};
    Spectrum beta{1.0f};
    // Per channel, the density with which the path so far would have been sampled with that
    // channel as hero, over the hero's: contributions are divided by its mean.
    Spectrum r_u{1.0f};
    // r_u over the density of the last direction sampled, and over the hero's probability of
    // crossing the media since: times a light's density, the light-sampling strategy's
    // density in the same units (for the balance heuristic at an emitter BSDF or phase
    // sampling reached).
    Spectrum r_l{1.0f};
    Ray ray;
    const Medium* medium = nullptr;
    int hero = 0;
    int depth = 0;
    bool specular_bounce = true;  // the camera samples its ray like a delta lobe
    float eta_scale = 1.0f;
    Vec3 previous_point{0.0f};
    // The shading normal at previous_point (zero at a medium vertex): the light tree's
    // choice there depends on it, so MIS against light sampling asks with it too.
    Vec3 previous_normal{0.0f};
    SurfaceInteraction si;
    Sampler* sampler = nullptr;
    Rng rng;  // distances and collision events, whose number varies from path to path
    AovSample* aov = nullptr;
};

namespace {

// What a light sample contributes from a scattering point, light sampling weighted against
// BSDF or phase sampling by the balance heuristic (see volpath.h): `scatter(wi)` gives the
// BSDF times cosine (or the phase function) towards wi and sets the density with which the
// walk would sample wi. The draws are sample_direct_light's, in its order.
// `surface` is the surface point scattering, or null for a point `p` in `medium`.
template <typename Scatter>
Spectrum direct_light(const Scene& scene, const Vec3& p, float time,
                      const SurfaceInteraction* surface, const Medium* medium, Sampler& sampler,
                      Rng& rng, const Spectrum& r_u, Scatter&& scatter) {
    const Vec2 u = sampler.get_2d();
    const float u_light = sampler.get_1d();
    const float u_select = sampler.get_1d();
    if (scene.light_sampler().empty()) return Spectrum(0.0f);
    const LightPoint point = sample_light_point(
        scene, p, surface ? surface->shading.n() : Vec3(0.0f), u, u_light, u_select);
    const std::optional<LightSample>& ls = point.sample;
    if (!ls || ls->L.is_black() || ls->pdf <= 0.0f) return Spectrum(0.0f);
    float scatter_pdf = 0.0f;
    const Spectrum f = scatter(ls->wi, scatter_pdf);
    if (f.is_black()) return Spectrum(0.0f);
    // From a surface the shadow ray starts off it, in the medium on the light's side.
    const Scene::ShadowRay shadow =
        surface ? Scene::shadow_ray(*surface, ls->p) : Scene::ShadowRay{p, ls->p - p, time};
    if (surface) medium = medium_beyond(*surface, ls->wi, medium);
    Spectrum passing(1.0f);
    const Spectrum T = transmittance_through_interfaces(scene, shadow, medium, &rng, &passing);
    if (T.is_black()) return Spectrum(0.0f);
    const float light_pdf = point.choice.pmf * ls->pdf;
    const Spectrum densities =
        ls->is_delta ? r_u * light_pdf : r_u * (Spectrum(light_pdf) + passing * scatter_pdf);
    const float mean = densities.average();
    return mean > 0.0f ? f * T * ls->L / mean : Spectrum(0.0f);
}

// Emission that BSDF or phase sampling reached: counted fully after a specular bounce,
// which light sampling cannot follow; otherwise weighted against light sampling's chance
// of the same light (`light_pdf()`: its choice probability times its density).
template <typename WalkState, typename LightPdf>
void add_emission(WalkState& walk, const Spectrum& Le, LightPdf&& light_pdf) {
    if (Le.is_black()) return;
    const Spectrum densities = walk.specular_bounce ? walk.r_u : walk.r_u + walk.r_l * light_pdf();
    const float mean = densities.average();
    if (mean > 0.0f) walk.L += walk.beta * Le / mean;
}

}  // namespace

std::unique_ptr<Integrator> VolPathIntegrator::create(const RenderSettings& settings,
                                                      const Params&) {
    return std::make_unique<VolPathIntegrator>(settings);
}

RenderStats VolPathIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    if (scene.media().empty()) return m_path.render(scene, film, progress);
    return TileIntegrator::render(scene, film, progress);
}

RenderStats VolPathIntegrator::render_pass(const Scene& scene, Film& film, int pass,
                                           Progress& progress) {
    if (scene.media().empty()) return m_path.render_pass(scene, film, pass, progress);
    return TileIntegrator::render_pass(scene, film, pass, progress);
}

void VolPathIntegrator::scene_changed(SceneChange change) {
    m_path.scene_changed(change);
    TileIntegrator::scene_changed(change);
}

Spectrum VolPathIntegrator::li(const Ray& ray, const Scene& scene, Sampler& sampler, Arena& arena,
                               RayCounter& counter, AovSample* aov) const {
    Walk walk;
    walk.ray = ray;
    walk.medium = scene.camera_medium();
    walk.sampler = &sampler;
    walk.aov = aov;
    walk.hero = std::min(static_cast<int>(sampler.get_1d() * Spectrum::active_values()),
                         Spectrum::active_values() - 1);
    walk.rng.seed(stream_seed(sampler.get_1d()));
    PassedSurfaces passed;
    for (int crossings = 0; crossings < 1024;) {
        ++counter.rays;
        // One traversal past the interfaces Embree can skip: the legs between them are
        // segments of their own media, each walked as if its ray had been traced alone.
        const bool hit = scene.intersect_surface_passing(walk.ray, walk.si, passed);
        const float t_hit = hit ? walk.si.t : kInfinity;
        const Ray traced = walk.ray;
        MediumStep step = MediumStep::kCrossed;
        walk_legs(scene, traced, passed, t_hit, walk.medium, [&](const Ray& leg, float length) {
            walk.ray = leg;
            step = scatter_in_medium(scene, walk, length);
            return step == MediumStep::kCrossed;
        });
        crossings += passed.count;
        if (step == MediumStep::kEnded) break;
        if (step == MediumStep::kScattered) continue;
        walk.ray = traced;
        if (!hit) {
            escape(scene, walk);
            break;
        }
        if (walk.si.material->is_interface()) {
            // Only the medium changes: the ray goes straight on, and no bounce is counted.
            walk.medium = medium_beyond(walk.si, walk.ray.direction, walk.medium);
            walk.ray = spawn_ray(walk.si, walk.ray.direction);
            ++crossings;
            continue;
        }
        if (!scatter_at_surface(scene, walk, arena)) break;
    }
    return walk.L;
}

// The walk's segment through its medium up to t_hit: the path ends there (absorbed, or at
// the depth limit), scatters (its ray is the new direction), or reaches t_hit with its
// throughput and densities carried across.
VolPathIntegrator::MediumStep VolPathIntegrator::scatter_in_medium(const Scene& scene, Walk& walk,
                                                                   float t_hit) const {
    const Medium& medium = *walk.medium;
    Ray& ray = walk.ray;
    if (!samples_distances(medium)) {
        // Absorption alone (absorbing glass): its transmittance, no sampling.
        const float t = std::isinf(t_hit) ? 1e30f : t_hit;
        walk.beta *= medium.transmittance(ray, t, walk.rng);
        return walk.beta.is_black() ? MediumStep::kEnded : MediumStep::kCrossed;
    }
    const int hero = walk.hero;
    MediumStep outcome = MediumStep::kCrossed;
    const Spectrum T_maj = sample_collisions(
        medium, ray, t_hit, hero, walk.rng,
        [&](float t, const MediumPoint& point, const Spectrum& sigma_maj, const Spectrum& T) {
            outcome = collide(scene, walk, t, point, sigma_maj, T);
            return outcome == MediumStep::kCrossed;
        });
    if (outcome == MediumStep::kEnded) return MediumStep::kEnded;
    if (outcome == MediumStep::kScattered) {
        // Roulette as at a surface, on the throughput the ratios leave.
        float survival;
        if (!survives_path_roulette(
                walk.depth, (walk.beta / walk.r_u.average()).max_value(),
                [&] { return walk.sampler->get_1d(); }, survival))
            return MediumStep::kEnded;
        if (survival < 1.0f) walk.beta /= survival;
        return MediumStep::kScattered;
    }
    const float T_hero = T_maj.value(hero);
    if (T_hero <= 0.0f) return MediumStep::kEnded;
    walk.beta *= T_maj / T_hero;
    walk.r_u *= T_maj / T_hero;
    // Light sampling's density for MIS takes the transmittance as its shadow ray estimated
    // it: the closed form in a homogeneous medium, so here the probability of crossing,
    // T_hero; ratio tracking elsewhere, so here the ratios along this walk's own tentative
    // collisions, as pbrt-v4's r_l (the null collisions' share is in collide()).
    if (medium.is_homogeneous())
        walk.r_l /= T_hero;
    else
        walk.r_l *= T_maj / T_hero;
    return MediumStep::kCrossed;
}

// A tentative collision at parameter t of the walk's ray, with the medium's coefficients
// `point` there, majorant sigma_maj, and majorant transmittance T since the last one: the
// medium's emission, then absorption (kEnded), real scattering (kScattered) or a null
// collision (kCrossed: the walk goes on), chosen with the hero channel's probabilities.
VolPathIntegrator::MediumStep VolPathIntegrator::collide(const Scene& scene, Walk& walk, float t,
                                                         const MediumPoint& point,
                                                         const Spectrum& sigma_maj,
                                                         const Spectrum& T) const {
    const int hero = walk.hero;
    const float sigma_hero = sigma_maj.value(hero);
    const float T_hero = T.value(hero);
    if (!point.emission.is_black() && walk.depth < m_settings.depth_limit()) {
        // Emission is collected at every tentative collision, weighted over the heroes.
        const float pdf = sigma_hero * T_hero;
        const float r_e = (walk.r_u * sigma_maj * T / pdf).average();
        if (r_e > 0.0f) walk.L += walk.beta * T * point.sigma_a * point.emission / (pdf * r_e);
    }
    const float p_absorb = point.sigma_a.value(hero) / sigma_hero;
    const float p_scatter = point.sigma_s.value(hero) / sigma_hero;
    const float u = walk.rng.next_float();
    if (u < p_absorb) return MediumStep::kEnded;
    if (u < p_absorb + p_scatter) {
        if (walk.depth++ >= m_settings.depth_limit()) return MediumStep::kEnded;
        const float pdf = T_hero * point.sigma_s.value(hero);
        walk.beta *= T * point.sigma_s / pdf;
        walk.r_u *= T * point.sigma_s / pdf;
        if (walk.beta.is_black() || walk.r_u.is_black()) return MediumStep::kEnded;
        scatter_by_phase(scene, walk, walk.ray.at(t));
        return MediumStep::kScattered;
    }
    // A null collision: the ray goes on, each channel weighted by its null share.
    const Spectrum sigma_n = (sigma_maj - point.sigma_a - point.sigma_s).clamped(0.0f, kInfinity);
    const float pdf = T_hero * sigma_n.value(hero);
    if (pdf <= 0.0f) return MediumStep::kEnded;
    walk.beta *= T * sigma_n / pdf;
    walk.r_u *= T * sigma_n / pdf;
    // Ratio tracking of a shadow ray along these collisions would weigh by sigma_n / sigma_maj
    // (the density of null collisions is in neither strategy's ratio): see scatter_in_medium.
    walk.r_l *= T * sigma_maj / pdf;
    return walk.beta.is_black() || walk.r_u.is_black() ? MediumStep::kEnded : MediumStep::kCrossed;
}

// Scattering at point p of the walk's medium: light sampling with the phase function, then
// the next direction sampled from it.
void VolPathIntegrator::scatter_by_phase(const Scene& scene, Walk& walk, const Vec3& p) const {
    const Vec3 wo = -glm::normalize(walk.ray.direction);
    const HenyeyGreenstein phase(walk.medium->phase_asymmetry());
    Sampler& sampler = *walk.sampler;
    walk.L += walk.beta * direct_light(scene, p, walk.ray.time, nullptr, walk.medium, sampler,
                                       walk.rng, walk.r_u, [&](const Vec3& wi, float& pdf_wi) {
                                           pdf_wi = phase.eval(wo, wi);
                                           return Spectrum(pdf_wi);
                                       });
    // Phase sampling is exact: the throughput keeps its value, p / pdf = 1.
    const PhaseSample ps = phase.sample(wo, sampler.get_2d());
    walk.r_l = walk.r_u / ps.p;
    walk.specular_bounce = false;
    walk.previous_point = p;
    walk.previous_normal = Vec3(0.0f);
    walk.ray = Ray{p, ps.wi, 0.0f, kInfinity, walk.ray.time};
}

// A path whose ray left the scene: the environment light (weighted against light
// sampling) or the constant background.
void VolPathIntegrator::escape(const Scene& scene, Walk& walk) const {
    const Spectrum escaped = scene.escaped_radiance(walk.ray.direction);
    if (walk.aov && walk.depth == 0 && walk.specular_bounce)
        *walk.aov = AovSample{escaped, Vec3(0.0f), kInfinity};
    if (const Light* environment = scene.environment()) {
        add_emission(walk, escaped, [&] {
            return scene.light_sampler().pmf(walk.previous_point, walk.previous_normal,
                                             *environment) *
                   environment->pdf_li_escaped(walk.ray.direction);
        });
    } else {
        const float mean = walk.r_u.average();
        if (mean > 0.0f) walk.L += walk.beta * escaped / mean;
    }
}

// At a surface that scatters: emission reached, light sampling with the BSDF, BSDF
// sampling of the next direction (and the medium beyond it), roulette. False when the path
// ends there.
bool VolPathIntegrator::scatter_at_surface(const Scene& scene, Walk& walk, Arena& arena) const {
    SurfaceInteraction& si = walk.si;
    if (si.area_light) {
        add_emission(walk, emitted_radiance(si), [&] {
            return scene.light_sampler().pdf_li(walk.previous_point, walk.previous_normal, si);
        });
    }
    const Bsdf* bsdf = shade(scene, walk.ray, si, arena);
    if (walk.aov && walk.depth == 0 && walk.specular_bounce) {
        walk.aov->albedo = si.material->albedo(si);
        walk.aov->normal = si.shading.n();
        walk.aov->depth = si.t;
    }
    if (!bsdf) return false;
    if (walk.depth++ >= m_settings.depth_limit()) return false;
    const Vec3 wo_local = si.to_local(si.wo);
    Sampler& sampler = *walk.sampler;
    if (!bsdf->is_delta()) {
        walk.L += walk.beta * direct_light(scene, si.p, si.time, &si, walk.medium, sampler,
                                           walk.rng, walk.r_u, [&](const Vec3& wi, float& pdf_wi) {
                                               const Vec3 wi_local = si.to_local(wi);
                                               return bsdf->eval_pdf(wo_local, wi_local, pdf_wi) *
                                                      abs_cos_theta(wi_local);
                                           });
    }
    const Vec2 u = sampler.get_2d();
    const float u_lobe = sampler.get_1d();
    const std::optional<Scattering> scattering = sample_scattering(si, *bsdf, wo_local, u, u_lobe);
    if (!scattering) return false;
    const BsdfSample& bs = scattering->sample;
    walk.beta *= scattering->weight;
    walk.specular_bounce = bs.is_delta();
    if (!bs.is_delta()) walk.r_l = walk.r_u / bs.pdf;
    if (bs.is_transmission()) walk.eta_scale *= bs.eta * bs.eta;
    walk.previous_point = si.p;
    walk.previous_normal = si.shading.n();
    walk.medium = medium_beyond(si, scattering->wi, walk.medium);
    continue_ray(walk.ray, si, *scattering);
    float survival;
    if (!survives_path_roulette(
            walk.depth, (walk.beta * walk.eta_scale / walk.r_u.average()).max_value(),
            [&] { return sampler.get_1d(); }, survival))
        return false;
    if (survival < 1.0f) walk.beta /= survival;
    return !walk.beta.is_black();
}

}  // namespace glint
