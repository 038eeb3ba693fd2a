#include <glint/core/error.h>
#include <glint/integrator/photon_grid.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace glint {

void PhotonGrid::build(const std::vector<Photon>& photons, float radius) {
    if (!(radius > 0.0f) || !std::isfinite(radius))
        throw Error("photon grid: the query radius must be a finite number > 0");
    m_radius = radius;
    m_cell = radius;
    m_inverse_cell = 1.0f / radius;
    // About two buckets per photon keeps occupied cells from sharing buckets.
    const size_t wanted = std::clamp<size_t>(2 * photons.size(), 16, size_t{1} << 30);
    const uint32_t buckets = std::bit_ceil(static_cast<uint32_t>(wanted));
    m_mask = buckets - 1;
    m_start.assign(static_cast<size_t>(buckets) + 1, 0);
    std::vector<Entry> entries(photons.size());
    std::vector<uint32_t> bucket(photons.size());
    m_coarse.assign(kCoarseBits / 64, 0);
    for (size_t i = 0; i < photons.size(); ++i) {
        // The coarse cells are 2r wide: the ball of radius r reaches at most two per axis,
        // those of its bounding box's corners.
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 offset((corner & 1) ? radius : -radius, (corner & 2) ? radius : -radius,
                              (corner & 4) ? radius : -radius);
            const uint32_t bit = coarse_bit(photons[i].p + offset);
            m_coarse[bit >> 6] |= uint64_t{1} << (bit & 63);
        }
        entries[i] = {photons[i].p, cell_of(photons[i].p)};
        bucket[i] = bucket_of(entries[i].cell);
        ++m_start[bucket[i] + 1];
    }
    for (uint32_t b = 0; b < buckets; ++b) m_start[b + 1] += m_start[b];
    // A stable counting sort: photons keep their order within a bucket, so the sums over a
    // query's photons come in the same order on every build of the same photons.
    m_entries.resize(photons.size());
    m_photons.resize(photons.size());
    std::vector<uint32_t> next(m_start.begin(), m_start.end() - 1);
    for (size_t i = 0; i < photons.size(); ++i) {
        const uint32_t slot = next[bucket[i]]++;
        m_entries[slot] = entries[i];
        m_photons[slot] = photons[i];
    }
}

}  // namespace glint
