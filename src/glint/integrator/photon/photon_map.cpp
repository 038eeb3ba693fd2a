#include <glint/core/interaction.h>
#include <glint/integrator/photon/photon_map.h>
#include <glint/material/bsdf.h>

#include <algorithm>

namespace glint {

PhotonMap::PhotonMap(std::vector<Photon> photons)
    : m_photons(std::move(photons)), m_nodes(m_photons.size()) {
    build(0, m_photons.size());
    for (size_t i = 0; i < m_photons.size(); ++i) m_nodes[i].p = m_photons[i].p;
}

void PhotonMap::build(size_t begin, size_t end) {
    if (begin >= end) return;
    Bounds3 bounds;
    for (size_t i = begin; i < end; ++i) bounds.expand(m_photons[i].p);
    const size_t mid = begin + (end - begin) / 2;
    m_nodes[mid].bounds = bounds;
    if (end - begin < 2) return;
    const Vec3 extent = bounds.extent();
    const uint8_t axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    std::nth_element(m_photons.begin() + static_cast<std::ptrdiff_t>(begin),
                     m_photons.begin() + static_cast<std::ptrdiff_t>(mid),
                     m_photons.begin() + static_cast<std::ptrdiff_t>(end),
                     [axis](const Photon& a, const Photon& b) { return a.p[axis] < b.p[axis]; });
    m_nodes[mid].axis = axis;
    build(begin, mid);
    build(mid + 1, end);
}

namespace {

// Squared distance from p to the nearest point of box b (0 inside). Summed in the order
// glm::dot sums, so that it never exceeds the squared distance to a photon in the box.
float distance2_to_box(const Vec3& p, const Bounds3& b) {
    const Vec3 gap = glm::max(glm::max(b.min - p, p - b.max), Vec3(0.0f));
    return glm::dot(gap, gap);
}

}  // namespace

size_t PhotonMap::nearest(const Vec3& p, int k, float max_distance2,
                          std::vector<std::pair<float, uint32_t>>& found) const {
    found.clear();
    if (m_photons.empty() || k <= 0) return 0;
    size_t examined = 0;
    search(0, m_photons.size(), p, k, max_distance2, found, examined);
    return examined;
}

void PhotonMap::search(size_t begin, size_t end, const Vec3& p, int k, float& max_distance2,
                       std::vector<std::pair<float, uint32_t>>& found, size_t& examined) const {
    if (begin >= end) return;
    const size_t mid = begin + (end - begin) / 2;
    // No photon of this range can be nearer than its box.
    const Node& node = m_nodes[mid];
    if (!(distance2_to_box(p, node.bounds) < max_distance2)) return;
    ++examined;
    const float d2 = length_squared(node.p - p);
    if (d2 < max_distance2) {
        found.emplace_back(d2, static_cast<uint32_t>(mid));
        std::push_heap(found.begin(), found.end());
        if (static_cast<int>(found.size()) > k) {
            std::pop_heap(found.begin(), found.end());
            found.pop_back();
        }
        // Full: only photons nearer than the farthest kept one can enter now.
        if (static_cast<int>(found.size()) == k) max_distance2 = found.front().first;
    }
    // The side that contains p first: it shrinks the radius soonest.
    const bool left_first = p[node.axis] < node.p[node.axis];
    search(left_first ? begin : mid + 1, left_first ? mid : end, p, k, max_distance2, found,
           examined);
    search(left_first ? mid + 1 : begin, left_first ? end : mid, p, k, max_distance2, found,
           examined);
}

namespace {
constexpr float kConeFilter = 1.1f;  // Jensen's k for the cone filter
}

Spectrum radiance_estimate(const PhotonMap& map, const SurfaceInteraction& si, const Bsdf& bsdf,
                           int k, float max_distance2, const WavelengthSets& sets) {
    const int set = sets.active_set();
    thread_local std::vector<std::pair<float, uint32_t>> found;
    map.nearest(si.p, k, max_distance2, found);
    if (found.empty()) return Spectrum(0.0f);
    const float r2 = static_cast<int>(found.size()) == k ? found.front().first : max_distance2;
    if (!(r2 > 0.0f) || !std::isfinite(r2)) return Spectrum(0.0f);
    const float r = std::sqrt(r2);
    const Vec3 wo = si.to_local(si.wo);
    const float viewer_side = glm::dot(si.wo, si.ng);
    Spectrum sum(0.0f);
    for (const auto& [d2, index] : found) {
        const Photon& photon = map[index];
        if (photon.set != set) continue;  // another set's wavelengths
        if (glm::dot(photon.wi, si.ng) * viewer_side <= 0.0f)
            continue;  // arrived on the other side
        const float weight = 1.0f - std::sqrt(d2) / (kConeFilter * r);
        sum += bsdf.eval(wo, si.to_local(photon.wi)) * photon.power * weight;
    }
    return sum / ((1.0f - 2.0f / (3.0f * kConeFilter)) * kPi * r2);
}

}  // namespace glint
