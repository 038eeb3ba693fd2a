#pragma once
// Reprojection of an earlier frame into the current view (3D image warping by depth): each
// pixel's visible point, from the current camera and the geometry buffer, is projected by the
// previous camera onto the previous film; the four previous pixels around that position are
// the bilinear taps of its history. A tap is kept only when the previous frame saw the same
// surface there: its depth matches the point's distance from the previous camera, its normal
// agrees and it shows the same object. Pixels without a kept tap are disoccluded (or left
// the frame): their history is rejected.
#include <glint/view/geometry_buffer.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace glint {

class Camera;

struct ReprojectionTolerances {
    /// A tap's depth may differ from the expected one by this fraction of it.
    float relative_depth = 0.03f;
    /// A tap's normal must make at most this cosine's angle with the pixel's.
    float min_normal_cosine = 0.9f;
    /// Taps with a smaller bilinear weight are left out: a position on a pixel centre
    /// then uses that pixel alone, whatever the rounding.
    float min_weight = 1e-3f;
};

/// Where one pixel's history lies in the previous frame.
struct HistoryTaps {
    static constexpr int32_t kNone = -1;
    /// Previous-frame pixel indices (y * width + x), kNone where a tap was rejected.
    std::array<int32_t, 4> index{kNone, kNone, kNone, kNone};
    /// Bilinear weights of the kept taps, summing to 1 (all 0 when none is kept).
    std::array<float, 4> weight{};
    bool valid() const { return index[0] != kNone; }
};

/// For every pixel of `current` (seen by `current_camera`), the kept taps of its history in
/// `previous` (seen by `previous_camera`); both cameras made for their buffers' resolutions.
/// Kept taps come first in HistoryTaps::index. Escaped rays reproject by direction (a point
/// far along the ray) and keep only taps that escaped too. Runs in parallel (TBB).
std::vector<HistoryTaps> reproject(const GeometryBuffer& current, const Camera& current_camera,
                                   const GeometryBuffer& previous, const Camera& previous_camera,
                                   const ReprojectionTolerances& tolerances = {});

/// `history` (one value per previous pixel) fetched through one pixel's valid `taps`: the
/// weighted sum of the kept taps.
template <typename T>
T fetch_one(const HistoryTaps& taps, std::span<const T> history) {
    T sum = history[taps.index[0]] * taps.weight[0];
    for (int k = 1; k < 4 && taps.index[k] != HistoryTaps::kNone; ++k)
        sum += history[taps.index[k]] * taps.weight[k];
    return sum;
}

/// `history` fetched through every pixel's `taps` (fetch_one), or `fallback` for a pixel
/// without history.
template <typename T>
std::vector<T> fetch_history(std::span<const HistoryTaps> taps, std::span<const T> history,
                             const T& fallback) {
    std::vector<T> result(taps.size(), fallback);
    for (std::size_t i = 0; i < taps.size(); ++i)
        if (taps[i].valid()) result[i] = fetch_one(taps[i], history);
    return result;
}

}  // namespace glint
