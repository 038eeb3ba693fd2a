#pragma once
// The start of every walk that leaves the lights (light tracing, photons, the light
// subpaths of bdpt, vcm and mlt): a light chosen in proportion to power, a ray from it, and
// the throughput the ray carries, power / pmf. The walks draw their random numbers from
// different sources (an Rng per particle, a Sampler), so they draw them and hand them in,
// always in this order: the light (1D), the ray's origin (2D), its direction (2D), the
// light's part (1D).
#include <glint/scene/scene.h>

#include <optional>

namespace glint {

/// The random numbers a light path starts with, in the order they are drawn.
struct LightPathSamples {
    float u_light;     ///< chooses the light (LightSampler::sample)
    Vec2 u_position;   ///< the ray's origin (Light::sample_le)
    Vec2 u_direction;  ///< the ray's direction
    float u_select;    ///< the light's part (triangle, side)
    /// The path's scene time (not a random number of its own: walks that draw one, only in
    /// scenes that move, map it with Camera::time_of_sample); every ray of the path keeps it.
    float time = 0.0f;
};

/// A light path's first ray, and what it carries.
struct LightPathStart {
    const Light* light = nullptr;  ///< the light chosen
    float pmf = 0.0f;              ///< the light sampler's probability of choosing it
    LightEmission emission;        ///< the ray and its densities (Light::sample_le)
    Spectrum beta;                 ///< emission.beta() / pmf: the power the ray carries
};

/// Light::sample_le, the default way a chosen light emits.
struct SampleLe {
    std::optional<LightEmission> operator()(const Light& light, const Vec2& u_position,
                                            const Vec2& u_direction, float u_select) const {
        return light.sample_le(u_position, u_direction, u_select);
    }
};

/// Starts a light path with `u`: nullopt when the scene has no light or the light emits no
/// ray. `emit` is how the chosen light emits (Light::sample_le, or a projection map that
/// aims photons at specular objects); it is called as sample_le is.
template <typename Emit = SampleLe>
std::optional<LightPathStart> start_light_path(const Scene& scene, const LightPathSamples& u,
                                               Emit&& emit = {}) {
    const LightSampler::Choice choice = scene.light_sampler().sample(u.u_light);
    if (!choice.light) return std::nullopt;
    std::optional<LightEmission> emission =
        emit(*choice.light, u.u_position, u.u_direction, u.u_select);
    if (!emission) return std::nullopt;
    emission->ray.time = u.time;
    const Spectrum beta = emission->beta() / choice.pmf;
    return LightPathStart{choice.light, choice.pmf, std::move(*emission), beta};
}

}  // namespace glint
