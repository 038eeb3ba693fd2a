#include <glint/core/sampler.h>
#include <glint/integrator/path.h>
#include <glint/integrator/shading.h>
#include <glint/material/material.h>

namespace glint {
namespace {

float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// Direct light at `si` from one light chosen by power, weighted against BSDF sampling.
Spectrum sample_direct(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                       const Vec3& wo_local, Sampler& sampler, RayCounter& counter, bool use_mis) {
    // 2D first: the Sobol sampler hands out a 2D value and two 1D values per index shuffle.
    const Vec2 u = sampler.get_2d();
    const float u_light = sampler.get_1d();
    const float u_select = sampler.get_1d();
    const LightSampler::Choice choice = scene.light_sampler().sample(u_light);
    if (!choice.light) return Spectrum(0.0f);
    const std::optional<LightSample> ls = choice.light->sample_li(si.p, u, u_select);
    if (!ls || ls->L.is_black()) return Spectrum(0.0f);
    const Vec3 wi_local = si.to_local(ls->wi);
    float bsdf_pdf = 0.0f;
    const Spectrum f = bsdf.eval_pdf(wo_local, wi_local, bsdf_pdf) * abs_cos_theta(wi_local);
    if (f.is_black()) return Spectrum(0.0f);
    ++counter.rays;
    if (scene.occluded(si, ls->p)) return Spectrum(0.0f);
    const float light_pdf = choice.pmf * ls->pdf;
    if (ls->is_delta || !use_mis) return f * ls->L / light_pdf;
    const float weight = power_heuristic(light_pdf, bsdf_pdf);
    return f * ls->L * (weight / light_pdf);
}

// Weight of emission that BSDF sampling reached (an area light hit or an escaped ray into
// an environment light), against light sampling's chance of finding the same light there:
// counted fully after a specular bounce, which light sampling cannot follow, and by the
// BSDF-only strategy; not at all by the light-only one, which already counted it.
template <typename LightPdf>
float bsdf_emission_weight(DirectLighting strategy, bool specular_bounce, float bsdf_pdf,
                           const LightPdf& light_pdf) {
    if (specular_bounce || strategy == DirectLighting::kBsdfOnly) return 1.0f;
    if (strategy == DirectLighting::kLightOnly) return 0.0f;
    return power_heuristic(bsdf_pdf, light_pdf());
}

void record_aov(AovSample* aov, const SurfaceInteraction& si, const Material* material) {
    aov->albedo = material ? material->albedo(si) : Spectrum(0.0f);
    aov->normal = si.shading.n();
    aov->depth = si.t;
}

}  // namespace

Spectrum PathIntegrator::li(const Ray& camera_ray, const Scene& scene, Sampler& sampler,
                            Arena& arena, RayCounter& counter, AovSample* aov) const {
    Spectrum L(0.0f);
    Spectrum beta(1.0f);
    Ray ray = camera_ray;
    bool specular_bounce = true;  // the camera "samples" its ray like a delta lobe
    float bsdf_pdf = 0.0f;
    Vec3 previous_point(0.0f);  // where the last BSDF sample was taken, for MIS
    float eta_scale = 1.0f;
    SurfaceInteraction si;  // each bounce's hit, written over the last one's

    for (int depth = 0;; ++depth) {
        ++counter.rays;
        if (!scene.intersect(ray, si)) {
            const Spectrum escaped = scene.escaped_radiance(ray.direction);
            if (aov && depth == 0) *aov = AovSample{escaped, Vec3(0.0f), kInfinity};
            if (const Light* environment = scene.environment()) {
                L += beta * escaped *
                     bsdf_emission_weight(m_strategy, specular_bounce, bsdf_pdf, [&] {
                         return scene.light_sampler().pmf(*environment) *
                                environment->pdf_li_escaped(ray.direction);
                     });
            } else {
                L += beta * escaped;  // a constant background is no light: nothing samples it
            }
            break;
        }

        // Emission reached by BSDF sampling; light sampling already counted the rest of it.
        if (si.area_light) {
            const Spectrum Le = si.area_light->le(si, si.wo);
            if (!Le.is_black()) {
                L += beta * Le * bsdf_emission_weight(m_strategy, specular_bounce, bsdf_pdf, [&] {
                         return scene.light_sampler().pmf(*si.area_light) *
                                si.area_light->pdf_li(previous_point, si);
                     });
            }
        }

        // Beer-Lambert absorption along the segment just travelled inside a medium.
        if (!si.front_face) {
            const Spectrum sigma = si.material->interior_absorption();
            if (!sigma.is_black()) beta *= exp(sigma * (-si.t * glm::length(ray.direction)));
        }

        const Bsdf* bsdf = shade(scene, ray, si, arena);
        if (aov && depth == 0) record_aov(aov, si, si.material);
        if (!bsdf) break;
        if (m_settings.max_depth >= 0 && depth >= m_settings.max_depth) break;

        const Vec3 wo_local = si.to_local(si.wo);
        if (!bsdf->is_delta() && !scene.light_sampler().empty() &&
            m_strategy != DirectLighting::kBsdfOnly) {
            L += beta * sample_direct(scene, si, *bsdf, wo_local, sampler, counter,
                                      m_strategy == DirectLighting::kMis);
        }

        const Vec2 u = sampler.get_2d();
        const float u_lobe = sampler.get_1d();
        const std::optional<BsdfSample> bs = bsdf->sample(wo_local, u, u_lobe);
        if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) break;
        const Vec3 wi = si.to_world(bs->wi);
        // A shading normal can send light through the geometric surface; refuse it.
        const bool geometric_transmission = glm::dot(wi, si.ng) * glm::dot(si.wo, si.ng) < 0.0f;
        if (geometric_transmission != bs->is_transmission()) break;
        beta *= bs->f * (abs_cos_theta(bs->wi) / bs->pdf);
        specular_bounce = bs->is_delta();
        bsdf_pdf = bs->pdf;
        if (bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
        previous_point = si.p;
        if (bs->is_delta()) {
            ray = spawn_specular_ray(si, ray, wi, bs->is_transmission(), bs->eta);
        } else {
            respawn_ray(ray, si, wi);
        }

        // Russian roulette on the throughput without the radiance scaling of refraction,
        // which would otherwise kill paths that are about to leave the glass.
        const float rr_throughput = (beta * eta_scale).max_value();
        if (depth >= 2 && rr_throughput < 1.0f) {
            const float q = std::max(0.0f, 1.0f - rr_throughput);
            if (sampler.get_1d() < q) break;
            beta /= 1.0f - q;
        }
        if (beta.is_black()) break;
    }
    return L;
}

}  // namespace glint
