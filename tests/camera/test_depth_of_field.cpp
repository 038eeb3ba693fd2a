// The thin-lens camera: what is in the plane of focus stays sharp, and an edge out of focus
// is blurred by the circle of confusion the lens geometry predicts.
#include <glint/camera/camera.h>
#include <glint/film/image.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace glint;
using glint::test::mean_channel;
using glint::test::render_lua;

namespace {

constexpr int kWidth = 32, kHeight = 8;
constexpr float kNarrowFov = 10.0f;  // vertical, degrees

// A camera at the origin looking down -z at an emitter of radiance 1 that covers x < 0 of
// the plane z = -distance (nothing beyond x = 0, so black there): a vertical edge through the
// middle of the image, seen through a lens of radius `aperture` focused at `focus`.
Image render_edge(float distance, float aperture, float focus, int spp) {
    return render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 0}}, look_at = {{0, 0, -1}}, fov = {}, aperture = {},
                       focus_distance = {} }}
        glint.render{{ width = {}, height = {}, spp = {}, seed = 5 }}
        glint.quad{{ vertices = {{ {{-100, -100, {d}}}, {{0, -100, {d}}}, {{0, 100, {d}}}, {{-100, 100, {d}}} }},
                     material = glint.emissive{{ radiance = 1, two_sided = true }} }}
    )",
                                  kNarrowFov, aperture, focus, kWidth, kHeight, spp,
                                  fmt::arg("d", -distance)));
}

// P(t + X < 0) for X the horizontal offset of a point uniform on a disk of radius rho: the
// share of the disk left of the line x = -t.
double disk_share_left_of(double t, double rho) {
    const double s = std::clamp(-t / rho, -1.0, 1.0);  // the line, in disk radii
    return 0.5 + (s * std::sqrt(1.0 - s * s) + std::asin(s)) / M_PI;
}

}  // namespace

// With a lens, the plane of focus is as sharp as with a pinhole: every ray through the lens
// from a film point meets it at the same point, so the edge, which falls on a pixel border,
// leaves each column wholly lit or wholly dark.
TEST(ThinLens, PlaneOfFocusStaysSharp) {
    const Image image = render_edge(10.0f, 1.0f, 10.0f, 64);
    for (int x = 0; x < kWidth; ++x) {
        const double expected = x < kWidth / 2 ? 1.0 : 0.0;
        EXPECT_NEAR(mean_channel(image, 0, x, 0, x + 1, kHeight), expected, 1e-4) << "column " << x;
    }
}

// Out of focus, the lens point l moves the ray's hit on a plane at distance d by
// l (1 - d / f) (the ray runs from l to the focus point, whose offset from the pinhole ray
// grows with distance): a disk of radius rho = aperture |1 - d / f| in scene units, here
// 1 * |1 - 10/5| = 1, about 4.6 pixels. Each column's mean is the share of that disk, moved
// over the pixel, that lies left of the edge; the measured profile must match it within
// four standard errors of a column's mean (Bernoulli samples: at most 0.5 / sqrt(n)).
TEST(ThinLens, OutOfFocusEdgeIsBlurredByTheCircleOfConfusion) {
    const float distance = 10.0f, aperture = 1.0f, focus = 5.0f;
    const int spp = 1024;
    const Image image = render_edge(distance, aperture, focus, spp);
    const double rho = aperture * std::abs(1.0 - distance / focus);
    const double pixel = 2.0 * distance * std::tan(glm::radians(kNarrowFov / 2.0)) / kHeight;
    const double bound = 4.0 * 0.5 / std::sqrt(double(spp) * kHeight);
    int blurred = 0;
    for (int x = 0; x < kWidth; ++x) {
        // The pinhole hit of film column x + u is at (x + u - kWidth / 2) pixels from the edge.
        constexpr int kSub = 64;
        double expected = 0.0;
        for (int i = 0; i < kSub; ++i) {
            const double t = (x + (i + 0.5) / kSub - kWidth / 2.0) * pixel;
            expected += disk_share_left_of(t, rho) / kSub;
        }
        const double measured = mean_channel(image, 0, x, 0, x + 1, kHeight);
        EXPECT_NEAR(measured, expected, bound) << "column " << x;
        blurred += expected > 0.02 && expected < 0.98;
    }
    // The blur spans about 2 rho = 9 pixels, so the profile is tested where it is gradual.
    EXPECT_GE(blurred, 8);
}
