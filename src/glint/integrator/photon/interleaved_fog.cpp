#include <glint/core/rng.h>
#include <glint/integrator/photon/interleaved_fog.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

// Two distances within 5 % of the smaller (both infinite: alike). The tolerance lets a
// floor seen at a grazing angle share its estimates while a silhouette, where the leg's
// length jumps by far more, does not. (An infinite and a finite one differ by infinity.)
bool close(float a, float b) {
    return a == b || std::abs(a - b) <= 0.05f * std::min(a, b);
}

}  // namespace

void InterleavedFog::reset(Vec2i size, int pass) {
    m_size = size;
    const size_t count = static_cast<size_t>(size.x) * static_cast<size_t>(size.y);
    m_legs.resize(count);
    m_keys.resize(count);
    m_estimates.resize(count);
    m_estimated.assign(count, 0);
    m_blocks_x = (size.x + kBlock - 1) / kBlock;
    const int blocks_y = (size.y + kBlock - 1) / kBlock;
    m_choice.resize(static_cast<size_t>(m_blocks_x) * static_cast<size_t>(blocks_y));
    for (int by = 0; by < blocks_y; ++by) {
        for (int bx = 0; bx < m_blocks_x; ++bx) {
            const uint64_t block = (static_cast<uint64_t>(static_cast<uint32_t>(bx)) << 32) |
                                   static_cast<uint32_t>(by);
            m_choice[static_cast<size_t>(by) * static_cast<size_t>(m_blocks_x) +
                     static_cast<size_t>(bx)] =
                static_cast<uint8_t>(hash_combine(mix_bits(block), static_cast<uint64_t>(pass)) %
                                     (kBlock * kBlock));
        }
    }
}

bool InterleavedFog::alike(const Key& a, const Key& b) {
    return a.medium == b.medium && a.medium != nullptr && close(a.start, b.start) &&
           close(a.length, b.length);
}

bool InterleavedFog::estimates(int x, int y) const {
    const Key& own = m_keys[index(x, y)];
    if (!own.medium) return false;
    if (picked(x, y)) return true;
    // The 3 x 3 neighbourhood overlaps at most 2 x 2 blocks: their picked pixels are the
    // only candidates (asking picked() of all nine neighbours cost a third of this).
    const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, m_size.x - 1);
    const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, m_size.y - 1);
    for (int by = y0 / kBlock; by <= y1 / kBlock; ++by) {
        for (int bx = x0 / kBlock; bx <= x1 / kBlock; ++bx) {
            const int choice = m_choice[static_cast<size_t>(by) * static_cast<size_t>(m_blocks_x) +
                                        static_cast<size_t>(bx)];
            const int px = bx * kBlock + choice % kBlock, py = by * kBlock + choice / kBlock;
            // Outside the window (a block the film's edge cuts) or the neighbourhood.
            if (px < x0 || px > x1 || py < y0 || py > y1) continue;
            if (alike(own, m_keys[index(px, py)])) return false;
        }
    }
    return true;
}

void InterleavedFog::set_estimate(int x, int y, const Spectrum& value) {
    const size_t i = index(x, y);
    m_estimates[i] = value;
    m_estimated[i] = 1;
}

Spectrum InterleavedFog::reconstruct(int x, int y) const {
    const Key& own = m_keys[index(x, y)];
    if (!own.medium) return Spectrum(0.0f);
    Spectrum sum(0.0f);
    int count = 0;
    for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, m_size.y - 1); ++ny) {
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, m_size.x - 1); ++nx) {
            const size_t i = index(nx, ny);
            if (!estimated(i) || !alike(own, m_keys[i])) continue;
            sum += m_estimates[i];
            ++count;
        }
    }
    // estimates() guarantees at least one: the pixel itself or a picked neighbour like it.
    return count > 0 ? sum / static_cast<float>(count) : Spectrum(0.0f);
}

}  // namespace glint
