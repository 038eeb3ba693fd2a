#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/transport.h>
#include <glint/material/material.h>

namespace glint {

Spectrum estimate_direct_light(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                               Sampler& sampler, LightWeighting weighting, RayCounter& counter) {
    const std::optional<DirectLight> direct =
        sample_direct_light(scene, si, bsdf, si.to_local(si.wo), sampler, weighting);
    if (!direct) return Spectrum(0.0f);
    ++counter.rays;
    return scene.occluded(si, direct->target) ? Spectrum(0.0f) : direct->contribution;
}

SpecularChain follow_specular_chain(const Scene& scene, Ray ray, Spectrum beta, Sampler& sampler,
                                    Arena& arena, RayCounter& counter, int max_segments,
                                    AovSample* aov) {
    SpecularChain chain;
    for (int segment = 0; segment < max_segments; ++segment) {
        ++counter.rays;
        std::optional<SurfaceInteraction> hit(std::in_place);
        if (!scene.intersect(ray, *hit, chain.record)) {
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
