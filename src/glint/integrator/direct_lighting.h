#pragma once
// Next-event estimation with one light chosen by power, without MIS: the estimator the
// photon-mapping integrators use for direct light (their maps hold only indirect light).
#include <glint/core/sampler.h>
#include <glint/material/bsdf.h>
#include <glint/scene/scene.h>

namespace glint {

inline Spectrum sample_one_light(const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf,
                                 Sampler& sampler, uint64_t& rays) {
    const Vec2 u = sampler.get_2d();  // 2D first, see sample_direct in path.cpp
    const LightSampler::Choice choice = scene.light_sampler().sample(sampler.get_1d());
    const float u_select = sampler.get_1d();
    if (!choice.light) return Spectrum(0.0f);
    const std::optional<LightSample> ls = choice.light->sample_li(si.p, u, u_select);
    if (!ls || ls->L.is_black()) return Spectrum(0.0f);
    const Vec3 wi = si.to_local(ls->wi);
    const Spectrum f = bsdf.eval(si.to_local(si.wo), wi) * abs_cos_theta(wi);
    if (f.is_black()) return Spectrum(0.0f);
    ++rays;
    if (scene.occluded(si, ls->p)) return Spectrum(0.0f);
    return f * ls->L / (choice.pmf * ls->pdf);
}

}  // namespace glint
