#pragma once
// Photons stored at surfaces, in a balanced kd-tree for k-nearest-neighbour queries
// (Jensen 2001, ch. 6): the tree is the photon array itself, reordered so that the median
// of every range splits it.
#include <glint/core/spectrum.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace glint {

struct Photon {
    Vec3 p;
    Vec3 wi;  // unit, towards where the photon came from
    Spectrum power;
};

class PhotonMap {
public:
    PhotonMap() = default;
    explicit PhotonMap(std::vector<Photon> photons);

    // The (at most) k photons nearest to `p` within sqrt(max_distance2), as
    // (squared distance, index) pairs in `found` (a max-heap on distance).
    void nearest(const Vec3& p, int k, float max_distance2,
                 std::vector<std::pair<float, uint32_t>>& found) const;

    size_t size() const { return m_photons.size(); }
    const Photon& operator[](size_t i) const { return m_photons[i]; }

private:
    void build(size_t begin, size_t end);
    void search(size_t begin, size_t end, const Vec3& p, int k, float& max_distance2,
                std::vector<std::pair<float, uint32_t>>& found) const;

    std::vector<Photon> m_photons;
    std::vector<uint8_t> m_axis;  // split axis of the node at each median position
};

struct SurfaceInteraction;
class Bsdf;

// Reflected radiance at `si` from the k photons nearest to it (within
// sqrt(max_distance2)), with Jensen's cone filter; photons that arrived on the other side
// of the surface are ignored.
Spectrum radiance_estimate(const PhotonMap& map, const SurfaceInteraction& si, const Bsdf& bsdf,
                           int k, float max_distance2);

}  // namespace glint
