// VolumePhotonView: the volume photons of a pass as the camera sees them, binned by film
// tiles, and their beam radiance estimate along a pixel's primary ray (preview_media.h).
#include <glint/camera/camera.h>
#include <glint/core/rng.h>
#include <glint/integrator/photon/preview_media.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/math/frame.h>
#include <glint/medium/henyey_greenstein.h>
#include <glint/scene/scene.h>

#include <tbb/parallel_for.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace glint {

void VolumePhotonView::build(const Scene& scene, const Medium* camera_medium,
                             const std::vector<std::vector<VolumePhoton>>& batches, int only_set,
                             float radius2, Vec2i origin, Vec2i size,
                             const WavelengthContext* wavelengths) {
    m_photons.clear();
    m_origin = origin;
    m_radius2 = radius2;
    m_tiles = Vec2i((size.x + kTile - 1) / kTile, (size.y + kTile - 1) / kTile);
    const size_t tile_count = static_cast<size_t>(m_tiles.x) * static_cast<size_t>(m_tiles.y);
    m_bin_start.assign(tile_count + 1, 0);
    m_bin_photons.clear();
    std::vector<const VolumePhoton*> all;
    for (const std::vector<VolumePhoton>& batch : batches)
        for (const VolumePhoton& photon : batch)
            if (only_set < 0 || photon.set == only_set) all.push_back(&photon);
    if (all.empty() || !(radius2 > 0.0f)) return;
    const float batches_read = only_set < 0 ? static_cast<float>(batches.size()) : 1.0f;
    const float kernel = 1.0f / (kPi * radius2 * batches_read);
    const float radius = std::sqrt(radius2);
    const Camera& camera = scene.camera();
    const Vec3 eye = camera.generate_ray(Vec2(0.5f), Vec2(0.5f)).origin;

    // Each photon's film footprint (a square round its projection, one pixel wider for the
    // jitter of the pixels' rays) and transmittance from the lens, in parallel.
    struct Footprint {
        Vec2i lo{0}, hi{-1};  // tiles, inclusive; hi < lo: not seen
        Spectrum T{0.0f};
    };
    std::vector<Footprint> footprints(all.size());
    tbb::parallel_for(size_t{0}, all.size(), [&](size_t i) {
        std::optional<WavelengthScope> scope;
        if (wavelengths != nullptr) scope.emplace(*wavelengths);
        const VolumePhoton& photon = *all[i];
        const std::optional<FilmProjection> centre = camera.project(photon.p);
        if (!centre) return;
        // The footprint's radius in pixels, from two points at the radius across the view.
        const Frame across = Frame::from_normal(glm::normalize(photon.p - eye));
        float pixels = 0.0f;
        for (const Vec3& axis : {across.to_world(Vec3(1, 0, 0)), across.to_world(Vec3(0, 1, 0))}) {
            const std::optional<FilmProjection> edge = camera.project(photon.p + radius * axis);
            if (!edge) return;
            pixels = std::max(pixels, glm::length(edge->film - centre->film));
        }
        pixels = pixels * 1.05f + 1.5f;
        const Vec2 lo = centre->film - Vec2(pixels) - Vec2(origin);
        const Vec2 hi = centre->film + Vec2(pixels) - Vec2(origin);
        if (hi.x < 0.0f || hi.y < 0.0f || lo.x >= static_cast<float>(size.x) ||
            lo.y >= static_cast<float>(size.y))
            return;
        Footprint& f = footprints[i];
        f.lo = glm::max(Vec2i(glm::floor(lo)) / kTile, Vec2i(0));
        f.hi = glm::min(Vec2i(glm::floor(hi)) / kTile, m_tiles - Vec2i(1));
        // Ratio tracking in grid media draws from a stream keyed by the photon.
        Rng rng(hash_combine(0x766f6c756d65ull, i));
        f.T = transmittance_through_interfaces(scene, Scene::ShadowRay{eye, photon.p - eye, 0.0f},
                                               camera_medium, &rng);
        if (f.T.is_black()) f.hi = Vec2i(-1);
    });

    // Counting sort into the tiles, photons in their order: the same bins for any threads.
    std::vector<uint32_t> index_of(all.size(), UINT32_MAX);
    for (size_t i = 0; i < all.size(); ++i) {
        const Footprint& f = footprints[i];
        if (f.hi.x < f.lo.x || f.hi.y < f.lo.y) continue;
        index_of[i] = static_cast<uint32_t>(m_photons.size());
        m_photons.push_back({all[i]->p, all[i]->wi, all[i]->power * f.T * kernel, all[i]->g});
        for (int ty = f.lo.y; ty <= f.hi.y; ++ty)
            for (int tx = f.lo.x; tx <= f.hi.x; ++tx)
                ++m_bin_start[static_cast<size_t>(ty * m_tiles.x + tx) + 1];
    }
    for (size_t t = 0; t < tile_count; ++t) m_bin_start[t + 1] += m_bin_start[t];
    m_bin_photons.resize(m_bin_start[tile_count]);
    // Padded by 3 so that the last bin's last four loads stay in bounds (lanes past a bin's
    // end are masked off; the NaNs would fail every test anyway).
    const size_t padded = m_bin_start[tile_count] + 3;
    m_bin_x.assign(padded, std::numeric_limits<float>::quiet_NaN());
    m_bin_y.assign(padded, std::numeric_limits<float>::quiet_NaN());
    m_bin_z.assign(padded, std::numeric_limits<float>::quiet_NaN());
    std::vector<uint32_t> fill(m_bin_start.begin(), m_bin_start.end() - 1);
    for (size_t i = 0; i < all.size(); ++i) {
        if (index_of[i] == UINT32_MAX) continue;
        const Footprint& f = footprints[i];
        const Vec3& p = m_photons[index_of[i]].p;
        for (int ty = f.lo.y; ty <= f.hi.y; ++ty) {
            for (int tx = f.lo.x; tx <= f.hi.x; ++tx) {
                const uint32_t k = fill[static_cast<size_t>(ty * m_tiles.x + tx)]++;
                m_bin_photons[k] = index_of[i];
                m_bin_x[k] = p.x;
                m_bin_y[k] = p.y;
                m_bin_z[k] = p.z;
            }
        }
    }
}

Spectrum VolumePhotonView::estimate(Vec2i pixel, const Vec3& origin, const Vec3& direction,
                                    float t_end) const {
    if (m_photons.empty()) return Spectrum(0.0f);
    const Vec2i tile = (pixel - m_origin) / kTile;
    if (tile.x < 0 || tile.y < 0 || tile.x >= m_tiles.x || tile.y >= m_tiles.y)
        return Spectrum(0.0f);
    const size_t t = static_cast<size_t>(tile.y * m_tiles.x + tile.x);
    const Vec3 wo = -direction;
    Spectrum sum(0.0f);
    // Four photons at a time (GCC/Clang vector extensions: SSE on x86-64), each lane
    // computing what one photon's test computes, in the same order (the same bits); the
    // photons within the radius then add in bin order, as one at a time.
    using Float4 = float __attribute__((vector_size(16)));
    using Int4 = int32_t __attribute__((vector_size(16)));
    const auto load = [](const float* from) {
        Float4 v;
        std::memcpy(&v, from, sizeof(v));
        return v;
    };
    const Float4 ox = origin.x - Float4{}, oy = origin.y - Float4{}, oz = origin.z - Float4{};
    const Float4 dx = direction.x + Float4{}, dy = direction.y + Float4{},
                 dz = direction.z + Float4{};
    const uint32_t end = m_bin_start[t + 1];
    for (uint32_t k = m_bin_start[t]; k < end; k += 4) {
        const Float4 vx = load(&m_bin_x[k]) - ox, vy = load(&m_bin_y[k]) - oy,
                     vz = load(&m_bin_z[k]) - oz;
        const Float4 along = vx * dx + vy * dy + vz * dz;
        const Float4 off2 = vx * vx + vy * vy + vz * vz - along * along;
        const Int4 within = (along > 0.0f) & (along < t_end) & (off2 < m_radius2);
        // Bit i set where lane i passed (one movmskps where SSE is there: GCC made four
        // extractions of the loop).
#if defined(__SSE__)
        uint32_t lanes =
            static_cast<uint32_t>(__builtin_ia32_movmskps(reinterpret_cast<Float4>(within)));
#else
        uint32_t lanes = 0;
        for (int lane = 0; lane < 4; ++lane)
            lanes |= static_cast<uint32_t>(within[lane] & 1) << lane;
#endif
        if (end - k < 4) lanes &= (1u << (end - k)) - 1u;  // past the bin's end
        for (; lanes != 0; lanes &= lanes - 1) {
            const Seen& photon =
                m_photons[m_bin_photons[k + static_cast<uint32_t>(std::countr_zero(lanes))]];
            sum += photon.power * HenyeyGreenstein(photon.g).eval(wo, photon.wi);
        }
    }
    return sum;
}

}  // namespace glint
