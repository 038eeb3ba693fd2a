#pragma once
// Chi-square goodness of fit of points in a rectangle (positions on a light, on a lens)
// against their density per unit area, through chi_square_directions: the rectangle
// [lo, hi] maps linearly onto (cos theta, phi) in [-1, 1] x [0, 2 pi), which preserves area
// up to the constant 4 pi / area, so the direction test's equal-area bins become a grid on
// the rectangle and densities scale by area / (4 pi).
#include <support/chi_square.h>

#include <algorithm>
#include <cmath>

namespace glint::test {

using PointSampler = std::function<std::optional<Vec2>(const Vec2& u, float u_extra)>;
using PointPdf = std::function<double(const Vec2& p)>;

inline ChiSquareResult chi_square_points(const PointSampler& sample, const PointPdf& pdf,
                                         const Vec2& lo, const Vec2& hi, int sample_count,
                                         uint64_t seed, double significance = 0.01) {
    const double wx = static_cast<double>(hi.x) - lo.x, wy = static_cast<double>(hi.y) - lo.y;
    const double area = wx * wy;
    auto to_sphere = [&](const Vec2& p) {
        // Points outside the rectangle are clamped onto its edge, where the pdf is zero
        // when the rectangle is chosen larger than the support: the test then fails.
        const double s = std::clamp((p.x - lo.x) / wx, 0.0, 1.0);
        const double t = std::clamp((p.y - lo.y) / wy, 0.0, 0x1.fffffffffffffp-1);
        const double z = -1.0 + 2.0 * s, phi = 2.0 * M_PI * t;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return Vec3(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                    static_cast<float>(z));
    };
    auto from_sphere = [&](const Vec3& w) {
        double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
        if (phi < 0.0) phi += 2.0 * M_PI;
        const double s = 0.5 * (std::clamp(static_cast<double>(w.z), -1.0, 1.0) + 1.0);
        return Vec2(static_cast<float>(lo.x + s * wx),
                    static_cast<float>(lo.y + phi / (2.0 * M_PI) * wy));
    };
    return chi_square_directions(
        [&](const Vec2& u, float u_extra) -> std::optional<Vec3> {
            const std::optional<Vec2> p = sample(u, u_extra);
            if (!p) return std::nullopt;
            return to_sphere(*p);
        },
        [&](const Vec3& w) { return pdf(from_sphere(w)) * area / (4.0 * M_PI); }, sample_count,
        seed, 20, 20, significance);
}

}  // namespace glint::test
