#pragma once
// Interleaved single scattering for the preview's camera rays in fog (issue 29).
//
// The light a medium scatters towards the lens along a pixel's primary ray changes slowly
// from pixel to pixel, except where the ray's leg through the medium jumps (an object's
// silhouette, the medium's own boundary). So a pass estimates it (a light sample and a
// shadow ray: the preview's dearest part in fog) in only one pixel of each 2 x 2 block, a
// different one each pass, and gives every pixel the mean of the estimates in its 3 x 3
// neighbourhood whose legs resemble its own: interleaved sampling with a discontinuity
// buffer (Keller and Heidrich 2001). A pixel none of whose picked neighbours resembles it
// estimates its own, so the estimate never crosses a silhouette. The price is a blur of
// about a pixel along the shadows' and beams' edges in the fog; the light's amount is kept
// (each estimate is unbiased and the pixels read them in equal shares where the fog is
// smooth). `preview_fog_interleave = false` estimates every pixel's own.
#include <glint/core/ray.h>
#include <glint/core/spectrum.h>

#include <cstdint>
#include <vector>

namespace glint {

class Medium;

/// The first leg of a pixel's primary ray through a medium that scatters, whose single
/// scattering the pass estimates after every camera ray is traced.
struct DeferredLeg {
    /// The leg as a ray from where it starts.
    Ray ray() const {
        Ray r;
        r.origin = origin;
        r.direction = direction;
        r.time = time;
        return r;
    }

    Vec3 origin{0.0f};               ///< where the leg starts
    Vec3 direction{0.0f};            ///< the primary ray's, unit
    float time = 0.0f;               ///< the primary ray's scene time
    float length = 0.0f;             ///< to the leg's end (infinite: the ray left the scene)
    float start = 0.0f;              ///< from the lens to where the leg starts
    const Medium* medium = nullptr;  ///< the leg's medium; nullptr: the pixel has no leg
    Spectrum beta{1.0f};             ///< the camera path's throughput where the leg starts
};

/// Which pixels of a film window estimate their leg's single scattering in a pass, and
/// what each pixel then reads.
class InterleavedFog {
public:
    /// Pixels per block side: one pixel of each block is picked per pass.
    static constexpr int kBlock = 2;

    /// Makes room for a window of `size` pixels for pass `pass`, none estimated yet, and
    /// picks the pass's pixels. Every pixel's leg must then be written (its medium nullptr
    /// where it has none) before estimates() is asked.
    void reset(Vec2i size, int pass);
    Vec2i size() const { return m_size; }

    /// The leg of pixel (x, y), relative to the window's corner: write it, then call
    /// finish_leg(x, y).
    DeferredLeg& leg(int x, int y) { return m_legs[index(x, y)]; }
    const DeferredLeg& leg(int x, int y) const { return m_legs[index(x, y)]; }
    /// Notes what of pixel (x, y)'s leg its neighbours compare with theirs.
    void finish_leg(int x, int y) {
        const DeferredLeg& leg = m_legs[index(x, y)];
        m_keys[index(x, y)] = {leg.medium, leg.start, leg.length};
    }

    /// Whether the pass picks (x, y) in its block: one pixel per block, chosen by a hash of the
    /// block and the pass, so that every pixel is picked in about a quarter of the passes.
    bool picked(int x, int y) const {
        return m_choice[block_index(x, y)] == (x % kBlock) + kBlock * (y % kBlock);
    }
    /// Whether (x, y) estimates its own leg: it has one, and it is picked, or no picked pixel
    /// of its 3 x 3 neighbourhood has a leg like it. Call after every leg is recorded.
    bool estimates(int x, int y) const;
    /// The estimate of pixel (x, y), which estimates() chose: the leg's single scattering
    /// times its beta.
    void set_estimate(int x, int y, const Spectrum& value);
    /// The single scattering pixel (x, y) reads: the mean of the estimates in its 3 x 3
    /// neighbourhood whose legs resemble its own (its own among them when it estimates);
    /// 0 for a pixel without a leg. Call after every estimate is set.
    Spectrum reconstruct(int x, int y) const;

    /// Whether two legs are alike enough to share an estimate: the same medium, and starts
    /// and lengths within 5 % of the smaller (both infinite counts as alike).
    static bool alike(const DeferredLeg& a, const DeferredLeg& b) {
        return alike(Key{a.medium, a.start, a.length}, Key{b.medium, b.start, b.length});
    }

private:
    // What of a leg the neighbours compare, packed apart from the legs so that the 3 x 3
    // comparisons read few cache lines.
    struct Key {
        const Medium* medium;
        float start, length;
    };
    static bool alike(const Key& a, const Key& b);

    size_t index(int x, int y) const {
        return static_cast<size_t>(y) * static_cast<size_t>(m_size.x) + static_cast<size_t>(x);
    }
    size_t block_index(int x, int y) const {
        return static_cast<size_t>(y / kBlock) * static_cast<size_t>(m_blocks_x) +
               static_cast<size_t>(x / kBlock);
    }
    bool estimated(size_t i) const { return m_estimated[i] != 0; }

    Vec2i m_size{0};
    int m_blocks_x = 0;
    std::vector<uint8_t> m_choice;  // per block, the picked pixel: x % 2 + 2 (y % 2)
    std::vector<DeferredLeg> m_legs;
    std::vector<Key> m_keys;
    std::vector<Spectrum> m_estimates;
    std::vector<uint8_t> m_estimated;  // 1 where set_estimate() was called this pass
};

}  // namespace glint
