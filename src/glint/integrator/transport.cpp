#include <glint/integrator/shading.h>
#include <glint/integrator/transport.h>
#include <glint/material/material.h>

namespace glint {

std::optional<LightArrival> sample_light_arrival(const Light& light, const SurfaceInteraction& si,
                                                 const Bsdf& bsdf, const Vec3& wo_local,
                                                 const Vec2& u, float u_select) {
    const std::optional<LightSample> ls = light.sample_li(si.p, u, u_select);
    if (!ls || ls->L.is_black()) return std::nullopt;
    const Vec3 wi_local = si.to_local(ls->wi);
    LightArrival arrival{*ls, Spectrum(0.0f), 0.0f};
    arrival.f_cos = bsdf.eval_pdf(wo_local, wi_local, arrival.bsdf_pdf) * abs_cos_theta(wi_local);
    if (arrival.f_cos.is_black()) return std::nullopt;
    return arrival;
}

std::optional<DirectLight> sample_direct_light(const Scene& scene, const SurfaceInteraction& si,
                                               const Bsdf& bsdf, const Vec3& wo_local,
                                               Sampler& sampler, LightWeighting weighting) {
    // 2D first: the Sobol sampler hands out a 2D value and two 1D values per index shuffle.
    const Vec2 u = sampler.get_2d();
    const float u_light = sampler.get_1d();
    const float u_select = sampler.get_1d();
    const LightSampler::Choice choice = scene.light_sampler().sample(u_light);
    if (!choice.light) return std::nullopt;
    const std::optional<LightArrival> arrival =
        sample_light_arrival(*choice.light, si, bsdf, wo_local, u, u_select);
    if (!arrival) return std::nullopt;
    const LightSample& ls = arrival->light;
    const float light_pdf = choice.pmf * ls.pdf;
    if (ls.is_delta || weighting == LightWeighting::kNone)
        return DirectLight{arrival->f_cos * ls.L / light_pdf, ls.p};
    const float weight = power_heuristic(light_pdf, arrival->bsdf_pdf);
    return DirectLight{arrival->f_cos * ls.L * (weight / light_pdf), ls.p};
}

Spectrum estimate_direct_light(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                               Sampler& sampler, LightWeighting weighting, RayCounter& counter) {
    const std::optional<DirectLight> direct =
        sample_direct_light(scene, si, bsdf, si.to_local(si.wo), sampler, weighting);
    if (!direct) return Spectrum(0.0f);
    ++counter.rays;
    return scene.occluded(si, direct->target) ? Spectrum(0.0f) : direct->contribution;
}

std::optional<Scattering> sample_scattering(const SurfaceInteraction& si, const Bsdf& bsdf,
                                            const Vec3& wo_local, const Vec2& u, float u_lobe) {
    const std::optional<BsdfSample> bs = bsdf.sample(wo_local, u, u_lobe);
    if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) return std::nullopt;
    const Vec3 wi = si.to_world(bs->wi);
    const bool geometric_transmission = glm::dot(wi, si.ng) * glm::dot(si.wo, si.ng) < 0.0f;
    if (geometric_transmission != bs->is_transmission()) return std::nullopt;
    return Scattering{*bs, wi, bs->f * (abs_cos_theta(bs->wi) / bs->pdf)};
}

void continue_ray(Ray& ray, SurfaceInteraction& si, const Scattering& scattering) {
    const BsdfSample& bs = scattering.sample;
    if (bs.is_delta())
        ray = spawn_specular_ray(si, ray, scattering.wi, bs.is_transmission(), bs.eta);
    else
        respawn_ray(ray, si, scattering.wi);
}

DeltaLobes delta_lobes(const Bsdf& bsdf, const Vec3& wo_local) {
    // Delta BSDFs choose among at most two lobes by u_lobe alone (reflection below the
    // Fresnel reflectance, refraction above), so the two ends of its range find both. A
    // sampled delta lobe's f |cos| is its whole weight; its pdf is the chance of picking it,
    // which following every lobe replaces by 1.
    DeltaLobes result;
    uint32_t found = 0;
    for (const float u_lobe : {0.0f, 0x1.fffffep-1f}) {
        const std::optional<BsdfSample> bs = bsdf.sample(wo_local, Vec2(0.5f), u_lobe);
        if (!bs || !bs->is_delta() || (bs->flags & found) || bs->f.is_black()) continue;
        found |= bs->flags & (kBsdfReflection | kBsdfTransmission);
        BsdfSample lobe = *bs;
        lobe.pdf = 1.0f;
        result.lobes[result.count++] = lobe;
    }
    return result;
}

SpecularChain follow_specular_chain(const Scene& scene, Ray ray, Spectrum beta, Sampler& sampler,
                                    Arena& arena, RayCounter& counter, int max_segments,
                                    AovSample* aov) {
    SpecularChain chain;
    for (int segment = 0; segment < max_segments; ++segment) {
        ++counter.rays;
        std::optional<SurfaceInteraction> hit = scene.intersect(ray);
        if (!hit) {
            if (aov && segment == 0)
                *aov = AovSample{scene.escaped_radiance(ray.direction), Vec3(0.0f), kInfinity};
            chain.escaped = true;
            break;
        }
        SurfaceInteraction& si = *hit;
        beta *= segment_transmittance(ray, si);
        chain.emitted += beta * emitted_radiance(si);
        const Bsdf* bsdf = shade(scene, ray, si, arena);
        if (aov && segment == 0) *aov = AovSample{si.material->albedo(si), si.shading.n(), si.t};
        if (!bsdf) break;
        if (!bsdf->is_delta()) {
            chain.hit = std::move(hit);
            chain.bsdf = bsdf;
            break;
        }
        const Vec2 u = sampler.get_2d();
        const std::optional<Scattering> s =
            sample_scattering(si, *bsdf, si.to_local(si.wo), u, sampler.get_1d());
        if (!s) break;
        beta *= s->weight;
        continue_ray(ray, si, *s);
    }
    chain.beta = beta;
    chain.ray = ray;
    return chain;
}

}  // namespace glint
