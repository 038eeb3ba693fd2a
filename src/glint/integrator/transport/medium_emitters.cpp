#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/medium_emitters.h>
#include <glint/material/material.h>

#include <algorithm>

namespace glint {

MediumEmitters::MediumEmitters(const Scene& scene) {
    for (const std::unique_ptr<Medium>& medium : scene.media()) {
        if (!medium->emits() || !medium->is_homogeneous()) continue;
        Bounds3 box;
        for (const ScenePlacement& placement : scene.placements()) {
            for (const Material* material : placement.materials) {
                if (material && material->medium_interface().inside == medium.get()) {
                    box.expand(placement.shape->bounds().transformed(placement.to_world));
                    break;
                }
            }
        }
        if (box.is_empty()) {
            m_unbounded.push_back(medium.get());
            continue;
        }
        // Homogeneous: the source is the same everywhere (the RGB one, for choosing).
        const MediumPoint point = medium->at(box.center());
        const Vec3 extent = box.extent();
        const float volume = extent.x * extent.y * extent.z;
        const float power = (point.sigma_a * point.emission).average() * 4.0f * kPi * volume;
        if (!(power > 0.0f) || !std::isfinite(power)) continue;
        m_regions.push_back({medium.get(), box, volume, power});
        m_total_power += power;
    }
    float before = 0.0f;
    for (const Region& region : m_regions) {
        m_cdf.push_back(before / m_total_power);
        before += region.power;
    }
}

std::optional<MediumEmitters::Start> MediumEmitters::sample(const Scene& scene, float u_region,
                                                            const Vec3& u_point) const {
    if (m_regions.empty()) return std::nullopt;
    const size_t i = static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), u_region) -
                                         m_cdf.begin()) -
                     1;
    const Region& region = m_regions[std::min(i, m_regions.size() - 1)];
    const Vec3 p = region.box.min + u_point * region.box.extent();
    if (medium_containing(scene, p) != region.medium) return std::nullopt;
    const float pdf = (region.power / m_total_power) / region.volume;
    const MediumPoint point = region.medium->at(p);
    return Start{p, region.medium, point.sigma_a * point.emission / pdf};
}

}  // namespace glint
