#include <glint/medium/delta_tracking.h>

namespace glint {

Spectrum ratio_tracking_transmittance(const Medium& medium, const Ray& ray, float t, Rng& rng) {
    const float length = glm::length(ray.direction);
    const Ray unit{ray.origin, ray.direction / length, 0.0f, kInfinity};
    const float t_end = t * length;
    Spectrum T(1.0f);
    medium.majorants(unit, t_end, [&](const MajorantSegment& segment) {
        const float sigma = segment.sigma_maj.max_value();
        if (sigma <= 0.0f) return true;
        const float segment_end = std::min(segment.t_max, t_end);
        for (float s = segment.t_min;;) {
            s -= std::log(1.0f - rng.next_float()) / sigma;
            if (s >= segment_end) return true;
            const MediumPoint point = medium.at(unit.at(s));
            // Each tentative collision keeps the fraction of the majorant that is null.
            T *= (Spectrum(1.0f) - (point.sigma_a + point.sigma_s) / sigma).clamped(0.0f, 1.0f);
            if (T.is_black()) return false;
        }
    });
    return T;
}

}  // namespace glint
