#pragma once
// Distance sampling and transmittance estimation in a medium, against its majorants: the
// two walks every integrator that meets media shares (pbrt-v4's SampleT_maj and its ratio
// tracking, written as free functions over the Medium interface).
//
// Delta tracking draws tentative collisions with density sigma_maj exp(-sigma_maj t) for one
// channel, the hero (chromatic media: Spectrum::value(hero)); the caller decides at each
// whether it is an absorption, a real scattering or a null collision, and weights the other
// channels by the ratio of their densities (volpath's r_u).
#include <glint/core/medium.h>

#include <cmath>

namespace glint {

/// exp(-sigma d), channel by channel, with exp(-0 * infinity) taken as 1: a channel the
/// medium does not attenuate stays 1 over an endless segment.
inline Spectrum attenuation(const Spectrum& sigma, float d) {
    if (sigma.is_constant()) {  // grey: one exp (the same bits as per value)
        const float s = sigma.value(0);
        return Spectrum(s == 0.0f ? 1.0f : std::exp(-s * d));
    }
    return sigma.map([d](float s) { return s == 0.0f ? 1.0f : std::exp(-s * d); });
}

/// Walks `ray` (any direction length) from its origin to parameter t_max through `medium`,
/// drawing tentative collisions against the hero channel's majorant from `rng`. At each it
/// calls `collide(t, point, sigma_maj, T_maj)`, with t in `ray`'s parameter, the medium's
/// coefficients there, the majorant and the majorant transmittance since the previous
/// collision (or the start); `collide` returns false to end the walk. Returns the majorant
/// transmittance from the last collision to t_max, or 1 when `collide` ended the walk.
template <typename Collide>
Spectrum sample_collisions(const Medium& medium, const Ray& ray, float t_max, int hero, Rng& rng,
                           Collide&& collide) {
    const float length = glm::length(ray.direction);
    const Ray unit{ray.origin, ray.direction / length, 0.0f, kInfinity};
    const float t_end = t_max * length;
    Spectrum T_maj(1.0f);
    bool ended = false;
    medium.majorants(unit, t_end, [&](const MajorantSegment& segment) {
        const float segment_end = std::min(segment.t_max, t_end);
        const float sigma = segment.sigma_maj.value(hero);
        float t = segment.t_min;
        if (sigma <= 0.0f) {
            T_maj *= attenuation(segment.sigma_maj, segment_end - t);
            return true;
        }
        for (;;) {
            const float step = -std::log(1.0f - rng.next_float()) / sigma;
            if (t + step >= segment_end) {
                T_maj *= attenuation(segment.sigma_maj, segment_end - t);
                return true;
            }
            t += step;
            T_maj *= attenuation(segment.sigma_maj, step);
            if (!collide(t / length, medium.at(unit.at(t)), segment.sigma_maj, T_maj)) {
                ended = true;
                return false;
            }
            T_maj = Spectrum(1.0f);
        }
    });
    return ended ? Spectrum(1.0f) : T_maj;
}

/// An unbiased estimate of the transmittance of `ray` from its origin to parameter t by
/// ratio tracking (Novak et al. 2014) against one scalar majorant per segment, the largest
/// channel's, so that the estimate draws the same collisions for every channel: the default
/// for media without a closed form.
Spectrum ratio_tracking_transmittance(const Medium& medium, const Ray& ray, float t, Rng& rng);

}  // namespace glint
