#pragma once
// The viewer's temporal accumulation: what the frames before the last camera move left,
// reprojected into the current view (reprojection.h), blended with the frames since.
//
// Per pixel the history holds a colour H, the luminance moments M (mean of Y and of Y^2 per
// frame, for the real-time denoiser's variance) and a length n: how many frames H stands for.
// With F the plain mean of the k frames rendered since the move, the pixel shows
//     (w H + k F) / (w + k),   w = n for k <= 1, then max(0, n - (k - 1)).
// While the camera keeps moving (k = 1 per view) this is an exponential moving average with
// weight 1 / (n + 1) on the new frame and a per-pixel length n that grows by one per frame up
// to max_length and restarts at 0 where reprojection rejects the history. Once the camera
// stops, the history's weight falls by one per frame, so after n + 1 frames the pixel is F
// exactly: the plain average of the still frames, what the integrator alone gives.
#include <glint/core/rgb.h>
#include <glint/math/vector.h>
#include <glint/view/reprojection.h>

#include <span>
#include <vector>

namespace glint {

class TemporalHistory {
public:
    /// Throws glint::Error unless max_length >= 1.
    explicit TemporalHistory(int max_length = 32);

    /// Forgets the history (a light, material or integrator change).
    void reset();
    bool empty() const { return m_length.empty(); }
    int max_length() const { return m_max_length; }

    /// The weight of a history of `length` frames once `frames` frames since the move are
    /// blended with it.
    static float weight(float length, int frames);

    /// Pixel i blended with the mean `frame_mean` of `frames` frames (0: the history alone).
    /// Exactly frame_mean where the history's weight is 0 (always, when empty()).
    Rgb blend(std::size_t i, const Rgb& frame_mean, int frames) const;
    Vec2 blend_moments(std::size_t i, const Vec2& frame_moments, int frames) const;
    /// How many frames pixel i stands for after blending: w + frames, at most max_length
    /// (the frames since the move alone, when empty()).
    float blended_length(std::size_t i, int frames) const;
    /// The same without the cap: how many frames the blended colour averages (it grows past
    /// max_length while the camera stays still).
    float blended_frames(std::size_t i, int frames) const;

    /// The camera moved: the blended image of the old view (`shown`, `moments`, `lengths`:
    /// blend(), blend_moments() and blended_length() of every old pixel) becomes the
    /// history of the new one through `taps` (one per new pixel; reproject()). Pixels
    /// without kept taps get length 0: their history is rejected.
    void move(std::span<const HistoryTaps> taps, std::span<const Rgb> shown,
              std::span<const Vec2> moments, std::span<const float> lengths);

    /// The history's length at pixel i (0 when empty()).
    float length(std::size_t i) const { return empty() ? 0.0f : m_length[i]; }

private:
    int m_max_length;
    std::vector<Rgb> m_colour;
    std::vector<Vec2> m_moments;
    std::vector<float> m_length;
};

}  // namespace glint
