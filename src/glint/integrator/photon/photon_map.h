#pragma once
// Photons stored at surfaces, in a balanced kd-tree for k-nearest-neighbour queries
// (Jensen 2001, ch. 6): the tree is the photon array itself, reordered so that the median
// of every range splits it. Each node also keeps the tight bounds of its range, and a
// query skips a range whose box lies beyond the current search radius: photons lie on
// surfaces, so a split plane alone does not separate a query point from the photons of a
// nearby plane it does not touch (its search would visit every photon within the maximum
// radius of it in projection, a number that grows with the photon count).
#include <glint/core/spectrum.h>
#include <glint/integrator/transport/wavelength_sets.h>
#include <glint/math/bounds.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace glint {

struct Photon {
    Vec3 p;
    Vec3 wi;  // unit, towards where the photon came from
    Spectrum power;
    int set = 0;  // its wavelength set (transport/wavelength_sets.h); 0 in RGB mode
};

class PhotonMap {
public:
    PhotonMap() = default;
    explicit PhotonMap(std::vector<Photon> photons);

    /// The (at most) k photons nearest to `p` with squared distance below `max_distance2`,
    /// as (squared distance, index) pairs in `found` (a max-heap on distance: front() is the
    /// farthest). Returns the number of photons examined (for benchmarks).
    size_t nearest(const Vec3& p, int k, float max_distance2,
                   std::vector<std::pair<float, uint32_t>>& found) const;

    size_t size() const { return m_photons.size(); }
    const Photon& operator[](size_t i) const { return m_photons[i]; }

private:
    void build(size_t begin, size_t end);
    void search(size_t begin, size_t end, const Vec3& p, int k, float& max_distance2,
                std::vector<std::pair<float, uint32_t>>& found, size_t& examined) const;

    std::vector<Photon> m_photons;
    // What a search reads of the node at each median position, packed apart from the
    // photons' payload so that a query touches one cache line or two per node.
    struct Node {
        Bounds3 bounds;  // of the photons in the range whose median this is
        Vec3 p;          // the median photon's position
        uint32_t axis;   // split axis
    };
    std::vector<Node> m_nodes;
};

struct SurfaceInteraction;
class Bsdf;

/// Reflected radiance at `si` from the k photons nearest to it (within sqrt(max_distance2)):
/// the k-nearest-neighbour density estimate over the disc of radius r that reaches the k-th
/// photon (r = sqrt(max_distance2) when fewer are found), weighted by Jensen's cone filter
/// w = 1 - d / (1.1 r) and normalised by the filter's integral over the disc,
///   L = sum f(wo, wi_p) Phi_p w_p / ((1 - 2 / (3 * 1.1)) pi r^2).
/// Photons that arrived on the other side of the surface are ignored.
/// In spectral mode (`sets` spectral), the k nearest photons of every set set the radius,
/// and only those of the calling path's set (WavelengthSets::active_set) are summed: each
/// set's photons carry the power of all, so that is an estimate of the same radiance at
/// the path's wavelengths.
Spectrum radiance_estimate(const PhotonMap& map, const SurfaceInteraction& si, const Bsdf& bsdf,
                           int k, float max_distance2, const WavelengthSets& sets = {});

}  // namespace glint
