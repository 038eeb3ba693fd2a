// The real-time denoiser on an image with known noise: a piecewise-constant image with one
// vertical edge plus Gaussian noise. The filter must cut the error at least 4 times without
// moving or softening the edge (at least 90 % of its contrast kept).
#include <glint/core/error.h>
#include <glint/denoise/svgf.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace glint {
namespace {

constexpr int kWidth = 96, kHeight = 64, kEdge = 48;  // columns x < kEdge are the left side
constexpr float kNoise = 0.1f;

struct Scene {
    std::vector<Rgb> clean, noisy, albedo;
    std::vector<Vec3> normal;
    std::vector<float> depth, history;
    std::vector<Vec2> moments;
};

// Left and right values of the clean image, split into albedo times illumination; the
// noisy image is the mean of `frames` frames with noise kNoise * sqrt(frames) each (so the
// mean's noise is kNoise), with their accumulated moments. One frame: the filter estimates
// the variance spatially; more: from the moments.
Scene noisy_edge(Rgb albedo_left, Rgb albedo_right, float light_left, float light_right,
                 int frames = 1) {
    Scene s;
    std::mt19937 rng(11);
    std::normal_distribution<float> noise(0.0f, kNoise * std::sqrt(static_cast<float>(frames)));
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const bool left = x < kEdge;
            const Rgb albedo = left ? albedo_left : albedo_right;
            const Rgb clean = albedo * (left ? light_left : light_right);
            Rgb mean(0.0f);
            Vec2 moments(0.0f);
            for (int f = 0; f < frames; ++f) {
                const Rgb frame = clean + Rgb(noise(rng), noise(rng), noise(rng));
                mean += frame / static_cast<float>(frames);
                moments += svgf_moments(frame, albedo) / static_cast<float>(frames);
            }
            s.clean.push_back(clean);
            s.noisy.push_back(mean);
            s.albedo.push_back(albedo);
            s.normal.push_back(Vec3(0, 0, 1));
            s.depth.push_back(5.0f);
            s.history.push_back(static_cast<float>(frames));
            s.moments.push_back(moments);
        }
    }
    return s;
}

std::vector<Rgb> filter(const Scene& s) {
    SvgfInput in;
    in.width = kWidth;
    in.height = kHeight;
    in.colour = s.noisy;
    in.albedo = s.albedo;
    in.normal = s.normal;
    in.depth = s.depth;
    in.moments = s.moments;
    in.history_length = s.history;
    return svgf_filter(in);
}

double rmse(const std::vector<Rgb>& image, const std::vector<Rgb>& reference) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.size(); ++i)
        for (int c = 0; c < 3; ++c) sum += std::pow(image[i][c] - reference[i][c], 2.0);
    return std::sqrt(sum / (3.0 * image.size()));
}

double column_mean(const std::vector<Rgb>& image, int x) {
    double sum = 0.0;
    for (int y = 0; y < kHeight; ++y) sum += image[y * kWidth + x].luminance();
    return sum / kHeight;
}

void expect_denoised_with_sharp_edge(const Scene& s) {
    const std::vector<Rgb> filtered = filter(s);
    const double before = rmse(s.noisy, s.clean), after = rmse(filtered, s.clean);
    EXPECT_NEAR(before, kNoise, 0.01);
    EXPECT_LE(after * 4.0, before) << "error " << before << " -> " << after;
    // The edge stays between the same two columns and keeps its contrast.
    const double clean_step = column_mean(s.clean, kEdge) - column_mean(s.clean, kEdge - 1);
    const double step = column_mean(filtered, kEdge) - column_mean(filtered, kEdge - 1);
    EXPECT_GE(step / clean_step, 0.9) << "edge contrast";
    std::printf("rmse %.4f -> %.4f, edge contrast %.3f\n", before, after, step / clean_step);
    for (int x = 1; x < kWidth; ++x) {
        if (x == kEdge) continue;
        EXPECT_LT(std::abs(column_mean(filtered, x) - column_mean(filtered, x - 1)),
                  0.1 * std::abs(clean_step))
            << "a step between columns " << x - 1 << " and " << x;
    }
}

TEST(Svgf, EdgeInTheAlbedoIsKeptByDemodulation) {
    expect_denoised_with_sharp_edge(noisy_edge(Rgb(0.25f), Rgb(1.0f), 0.8f, 0.8f));
}

TEST(Svgf, EdgeInTheIlluminationIsKeptByTheLuminanceTest) {
    // An edge the albedo does not explain: only the luminance test keeps it, which needs the
    // per-frame variance from a temporal history.
    expect_denoised_with_sharp_edge(noisy_edge(Rgb(1.0f), Rgb(1.0f), 0.1f, 0.9f, 4));
}

TEST(Svgf, DepthEdgesStopTheFilter) {
    // Flat albedo and light, but the right half is another surface much further away: its
    // noise-free brighter value must not bleed into the left.
    Scene s = noisy_edge(Rgb(1.0f), Rgb(1.0f), 0.5f, 0.5f);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = kEdge; x < kWidth; ++x) {
            s.depth[y * kWidth + x] = 20.0f;
            s.clean[y * kWidth + x] = s.noisy[y * kWidth + x] = Rgb(0.52f);
            s.moments[y * kWidth + x] = svgf_moments(Rgb(0.52f), Rgb(1.0f));
        }
    }
    const std::vector<Rgb> filtered = filter(s);
    for (int y = 0; y < kHeight; ++y)
        for (int x = kEdge; x < kWidth; ++x) EXPECT_NEAR(filtered[y * kWidth + x].r, 0.52f, 1e-5f);
    EXPECT_NEAR(column_mean(filtered, kEdge - 1), 0.5, 0.01);
}

TEST(Svgf, EscapedPixelsPassThrough) {
    Scene s = noisy_edge(Rgb(1.0f), Rgb(1.0f), 0.2f, 0.8f);
    for (float& d : s.depth) d = 0.0f;
    const std::vector<Rgb> filtered = filter(s);
    for (std::size_t i = 0; i < filtered.size(); ++i) EXPECT_EQ(filtered[i], s.noisy[i]);
}

TEST(Svgf, SameBitsForOneAndTwoThreads) {
    const Scene s = noisy_edge(Rgb(0.5f), Rgb(1.0f), 0.3f, 0.7f, 2);
    std::vector<Rgb> one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = filter(s);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = filter(s);
    }
    for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "pixel " << i;
}

// The à-trous taps eight lanes at a time (AVX2) give the bits of four at a time (SSE2), and
// the interior's pixels through all their taps at once (blocked_taps) the bits of the
// tap-by-tap loop: on a frame of random colours, normals and depths with escaped pixels, a
// width that leaves scalar tails and interiors of several widths (holes 1 to 16), both
// kernels and a normal power other than 128 (its lane-by-lane pow).
TEST(Svgf, WideLanesGiveTheSameBits) {
    if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this processor has no AVX2";
    const int width = 101, height = 37;
    const std::size_t count = static_cast<std::size_t>(width) * height;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Rgb> colour(count), albedo(count);
    std::vector<Vec3> normal(count);
    std::vector<float> depth(count), history(count);
    std::vector<Vec2> moments(count);
    for (std::size_t i = 0; i < count; ++i) {
        colour[i] = Rgb(u(rng), u(rng), u(rng)) * 4.0f;
        albedo[i] = Rgb(u(rng), u(rng), u(rng));
        normal[i] = glm::normalize(Vec3(u(rng) - 0.5f, u(rng) - 0.5f, 2.0f));
        depth[i] = u(rng) < 0.05f ? 0.0f : 1.0f + u(rng);
        history[i] = std::floor(u(rng) * 8.0f);
        const float y = colour[i].luminance();
        moments[i] = Vec2(y, y * y * (1.0f + u(rng)));
    }
    SvgfInput in;
    in.width = width;
    in.height = height;
    in.colour = colour;
    in.albedo = albedo;
    in.normal = normal;
    in.depth = depth;
    in.moments = moments;
    in.history_length = history;
    for (const int radius : {1, 2}) {
        for (const float power : {128.0f, 20.0f}) {
            SvgfSettings settings;
            settings.kernel_radius = radius;
            settings.normal_power = power;
            const std::vector<Rgb> wide = svgf_filter(in, settings);
            settings.wide_lanes = false;
            const std::vector<Rgb> narrow = svgf_filter(in, settings);
            settings.blocked_taps = false;
            const std::vector<Rgb> tap_by_tap = svgf_filter(in, settings);
            settings.wide_lanes = true;
            const std::vector<Rgb> wide_tap_by_tap = svgf_filter(in, settings);
            for (std::size_t i = 0; i < count; ++i) {
                ASSERT_EQ(wide[i], narrow[i])
                    << "pixel " << i << ", radius " << radius << ", power " << power;
                ASSERT_EQ(wide[i], tap_by_tap[i])
                    << "pixel " << i << ", radius " << radius << ", power " << power;
                ASSERT_EQ(wide[i], wide_tap_by_tap[i])
                    << "pixel " << i << ", radius " << radius << ", power " << power;
            }
        }
    }
}

TEST(Svgf, SizesMustMatch) {
    Scene s = noisy_edge(Rgb(1.0f), Rgb(1.0f), 0.2f, 0.8f);
    s.depth.pop_back();
    EXPECT_THROW(filter(s), Error);
}

}  // namespace
}  // namespace glint
