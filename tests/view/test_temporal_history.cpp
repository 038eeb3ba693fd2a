// The temporal accumulation's blend: an exponential moving average while the camera moves,
// reset where reprojection rejects the history, and, once the camera stops, exactly the plain
// average of the still frames after the history's length in frames.
#include <glint/core/error.h>
#include <glint/view/temporal_history.h>

#include <gtest/gtest.h>

#include <random>

namespace glint {
namespace {

constexpr int kPixels = 6;

// Every pixel keeps its own history, except those in `rejected`.
std::vector<HistoryTaps> identity_taps(const std::vector<int>& rejected = {}) {
    std::vector<HistoryTaps> taps(kPixels);
    for (int i = 0; i < kPixels; ++i) {
        if (std::find(rejected.begin(), rejected.end(), i) != rejected.end()) continue;
        taps[i].index[0] = i;
        taps[i].weight[0] = 1.0f;
    }
    return taps;
}

// The blended image of `history` after `frames` frames of mean `mean`, and the camera moves.
void move(TemporalHistory& history, const std::vector<Rgb>& mean, int frames,
          const std::vector<HistoryTaps>& taps) {
    std::vector<Rgb> shown(kPixels);
    std::vector<Vec2> moments(kPixels);
    std::vector<float> lengths(kPixels);
    for (int i = 0; i < kPixels; ++i) {
        shown[i] = history.blend(i, mean[i], frames);
        moments[i] = history.blend_moments(i, Vec2(mean[i].r, mean[i].r * mean[i].r), frames);
        lengths[i] = history.blended_length(i, frames);
    }
    history.move(taps, shown, moments, lengths);
}

TEST(TemporalHistory, MovingCameraIsAnExponentialAverageWithGrowingLength) {
    TemporalHistory history(4);
    EXPECT_TRUE(history.empty());
    const std::vector<Rgb> first(kPixels, Rgb(1.0f));
    EXPECT_EQ(history.blend(0, first[0], 1), first[0]);  // nothing to blend with yet
    move(history, first, 1, identity_taps());
    EXPECT_FLOAT_EQ(history.length(0), 1.0f);
    // One frame per view: weight 1 / (n + 1) on the new frame, n growing up to the maximum.
    float expected = 1.0f;
    for (int frame = 2; frame <= 8; ++frame) {
        const float n = history.length(0);
        EXPECT_FLOAT_EQ(n, static_cast<float>(std::min(frame - 1, 4)));
        const Rgb value(static_cast<float>(frame));
        expected = (n * expected + value.r) / (n + 1.0f);
        EXPECT_FLOAT_EQ(history.blend(0, value, 1).r, expected);
        move(history, std::vector<Rgb>(kPixels, value), 1, identity_taps());
    }
}

TEST(TemporalHistory, RejectedPixelsStartAgain) {
    TemporalHistory history(8);
    for (int frame = 0; frame < 5; ++frame)
        move(history, std::vector<Rgb>(kPixels, Rgb(3.0f)), 1, identity_taps());
    move(history, std::vector<Rgb>(kPixels, Rgb(3.0f)), 1, identity_taps({2}));
    EXPECT_EQ(history.length(2), 0.0f);
    EXPECT_EQ(history.blend(2, Rgb(5.0f), 1), Rgb(5.0f));
    EXPECT_GT(history.length(1), 5.0f);
    EXPECT_NE(history.blend(1, Rgb(5.0f), 1), Rgb(5.0f));
}

TEST(TemporalHistory, AfterAStopTheImageBecomesThePlainAverageOfTheStillFrames) {
    const int max_length = 16;
    TemporalHistory history(max_length);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 4.0f);
    auto noisy = [&] {
        std::vector<Rgb> frame(kPixels);
        for (Rgb& c : frame) c = Rgb(u(rng), u(rng), u(rng));
        return frame;
    };
    // A long move, then the camera stops.
    for (int frame = 0; frame < 40; ++frame) move(history, noisy(), 1, identity_taps());
    std::vector<double> sum(3 * kPixels, 0.0);
    for (int k = 1; k <= max_length + 3; ++k) {
        const std::vector<Rgb> frame = noisy();
        for (int i = 0; i < kPixels; ++i)
            for (int c = 0; c < 3; ++c) sum[3 * i + c] += frame[i][c];
        for (int i = 0; i < kPixels; ++i) {
            Rgb mean;
            for (int c = 0; c < 3; ++c) mean[c] = static_cast<float>(sum[3 * i + c] / k);
            const Rgb shown = history.blend(i, mean, k);
            if (k > max_length) {
                EXPECT_EQ(shown, mean) << "pixel " << i << " after " << k << " still frames";
            } else {
                EXPECT_NE(shown, mean) << "the history still counts after " << k << " frames";
            }
            EXPECT_EQ(history.blended_length(i, k), static_cast<float>(max_length));
        }
    }
}

TEST(TemporalHistory, LengthMustBePositive) {
    EXPECT_THROW(TemporalHistory(0), Error);
}

}  // namespace
}  // namespace glint
