#include <glint/core/error.h>
#include <glint/core/parallel.h>
#include <glint/view/temporal_history.h>

#include <algorithm>

namespace glint {

TemporalHistory::TemporalHistory(int max_length) : m_max_length(max_length) {
    if (max_length < 1) throw Error("the temporal history's length must be at least 1 frame");
}

void TemporalHistory::reset() {
    m_colour.clear();
    m_moments.clear();
    m_length.clear();
}

float TemporalHistory::weight(float length, int frames) {
    return frames <= 1 ? length : std::max(0.0f, length - static_cast<float>(frames - 1));
}

Rgb TemporalHistory::blend(std::size_t i, const Rgb& frame_mean, int frames) const {
    const float w = empty() ? 0.0f : weight(m_length[i], frames);
    if (w <= 0.0f) return frame_mean;
    if (frames == 0) return m_colour[i];
    const float k = static_cast<float>(frames);
    return (m_colour[i] * w + frame_mean * k) / (w + k);
}

Vec2 TemporalHistory::blend_moments(std::size_t i, const Vec2& frame_moments, int frames) const {
    const float w = empty() ? 0.0f : weight(m_length[i], frames);
    if (w <= 0.0f) return frame_moments;
    if (frames == 0) return m_moments[i];
    const float k = static_cast<float>(frames);
    return (m_moments[i] * w + frame_moments * k) / (w + k);
}

float TemporalHistory::blended_length(std::size_t i, int frames) const {
    return std::min(static_cast<float>(m_max_length), blended_frames(i, frames));
}

float TemporalHistory::blended_frames(std::size_t i, int frames) const {
    const float w = empty() ? 0.0f : weight(m_length[i], frames);
    return w + static_cast<float>(frames);
}

void TemporalHistory::move(std::span<const HistoryTaps> taps, std::span<const Rgb> shown,
                           std::span<const Vec2> moments, std::span<const float> lengths) {
    m_colour.assign(taps.size(), Rgb(0.0f));
    m_moments.assign(taps.size(), Vec2(0.0f));
    m_length.assign(taps.size(), 0.0f);
    // The three fetches in one parallel loop over the pixels (fetch_history's sums, pixel by
    // pixel: the same bits for any threads).
    parallel_for_indices(taps.size(), [&](std::size_t i) {
        if (!taps[i].valid()) return;
        m_colour[i] = fetch_one(taps[i], shown);
        m_moments[i] = fetch_one(taps[i], moments);
        m_length[i] = fetch_one(taps[i], lengths);
    });
}

}  // namespace glint
