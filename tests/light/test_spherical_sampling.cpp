// Solid-angle sampling of triangles (Arvo) and rectangles (Urena et al.): chi-square of the
// sampled directions against the uniform density 1 / solid angle over the region, with the
// solid angle and the region computed here independently (Van Oosterom-Strackee's formula,
// ray casting), for ordinary, thin, large (the point close to the light) and nearly
// grazing (about 2 degrees above the light's plane) configurations.
#include <glint/math/spherical_rectangle.h>
#include <glint/math/spherical_triangle.h>

#include <gtest/gtest.h>
#include <support/cap_zoom.h>
#include <support/chi_square.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace glint;

namespace {

using DVec3 = glm::dvec3;
using Triangle = std::array<DVec3, 3>;

// Solid angle of triangle t seen from o (Van Oosterom and Strackee 1983).
double triangle_solid_angle(const DVec3& o, const Triangle& t) {
    const DVec3 a = glm::normalize(t[0] - o), b = glm::normalize(t[1] - o),
                c = glm::normalize(t[2] - o);
    const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denominator = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
    double omega = 2.0 * std::atan2(numerator, denominator);
    if (omega < 0.0) omega += 2.0 * M_PI;
    return omega;
}

// Whether the ray from o along d meets triangle t (edges moved out by `slack`).
bool ray_meets(const DVec3& o, const DVec3& d, const Triangle& t, double slack) {
    const DVec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
    const DVec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return false;
    const DVec3 s = o - t[0];
    const double u = glm::dot(s, p) / det;
    const DVec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    return u >= -slack && v >= -slack && u + v <= 1.0 + slack && glm::dot(e2, q) / det > 0.0;
}

// The cap around the region's directions, widened by half, for regions too small to spread
// over the chi-square's bins; nullopt for regions large enough to bin directly.
std::optional<test::CapZoom> zoom_onto(const DVec3& o, const std::vector<DVec3>& corners,
                                       double solid_angle) {
    if (solid_angle > 0.05) return std::nullopt;
    DVec3 axis(0.0);
    for (const DVec3& c : corners) axis += glm::normalize(c - o);
    axis = glm::normalize(axis);
    double cos_min = 1.0;
    for (const DVec3& c : corners)
        cos_min = std::min(cos_min, glm::dot(glm::normalize(c - o), axis));
    return test::CapZoom(Vec3(axis), 1.0 - 1.5 * (1.0 - cos_min));
}

// Chi-square of `sample` (unit directions) against 1 / `solid_angle` on the directions
// `inside` accepts, zoomed when the region is small.
template <typename Sample, typename Inside>
void expect_uniform_in_solid_angle(const Sample& sample, const Inside& inside, double solid_angle,
                                   std::optional<test::CapZoom> zoom, const std::string& label,
                                   int tests_in_case) {
    int outside_region = 0;
    auto draw = [&](const Vec2& u, float) -> std::optional<Vec3> {
        const Vec3 w = sample(u);
        if (!inside(DVec3(w), 1e-5)) ++outside_region;
        return zoom ? zoom->to_sphere(w) : std::optional<Vec3>(w);
    };
    auto density = [&](const Vec3& v) {
        if (zoom) {
            const Vec3 w = zoom->from_sphere(v);
            return inside(glm::normalize(DVec3(w)), 0.0) ? zoom->density_scale() / solid_angle
                                                         : 0.0;
        }
        return inside(glm::normalize(DVec3(v)), 0.0) ? 1.0 / solid_angle : 0.0;
    };
    const auto result =
        test::chi_square_directions(draw, density, 200000, 17, 20, 40, 0.01 / tests_in_case);
    EXPECT_TRUE(result.passed) << label << ": " << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 5e-3) << label << ": " << result.details;
    EXPECT_EQ(outside_region, 0) << label;
    if (zoom) {
        EXPECT_EQ(zoom->outside, 0) << label;
    }
}

struct TriangleCase {
    std::string name;
    Triangle triangle;
    DVec3 ref;
};

const TriangleCase kTriangleCases[] = {
    {"ordinary",
     {DVec3(-0.5, -0.4, 0), DVec3(0.9, -0.6, 0), DVec3(0.2, 0.8, 0)},
     DVec3(0.3, 0.2, 1.2)},
    {"oblique",
     {DVec3(-0.5, -0.4, 0), DVec3(0.9, -0.6, 0), DVec3(0.2, 0.8, 0)},
     DVec3(2.5, -1.0, 0.7)},
    {"thin", {DVec3(-1.0, 0.0, 0), DVec3(1.0, 0.0, 0), DVec3(0.1, 0.02, 0)}, DVec3(0.0, 0.3, 0.5)},
    {"large (close)", {DVec3(-3, -2, 0), DVec3(4, -3, 0), DVec3(0.5, 5, 0)}, DVec3(0.1, 0.2, 0.02)},
    {"nearly grazing",
     {DVec3(-0.5, -0.4, 0), DVec3(0.9, -0.6, 0), DVec3(0.2, 0.8, 0)},
     DVec3(3.0, 0.5, 0.12)},
    {"far",
     {DVec3(-0.5, -0.4, 0), DVec3(0.9, -0.6, 0), DVec3(0.2, 0.8, 0)},
     DVec3(8.0, -6.0, 20.0)},
};

}  // namespace

TEST(SphericalTriangle, SolidAngleMatchesClosedForm) {
    for (const TriangleCase& c : kTriangleCases) {
        const SphericalTriangle st(Vec3(c.ref), Vec3(c.triangle[0]), Vec3(c.triangle[1]),
                                   Vec3(c.triangle[2]));
        const double expected = triangle_solid_angle(c.ref, c.triangle);
        EXPECT_NEAR(st.solid_angle(), expected, 1e-5 * expected + 1e-9) << c.name;
    }
}

TEST(SphericalTriangleSlow, SamplesAreUniformInSolidAngle) {
    const int cases = static_cast<int>(std::size(kTriangleCases));
    for (const TriangleCase& c : kTriangleCases) {
        // The reference point in float, as the renderer holds it.
        const DVec3 ref = DVec3(Vec3(c.ref));
        const SphericalTriangle st(Vec3(ref), Vec3(c.triangle[0]), Vec3(c.triangle[1]),
                                   Vec3(c.triangle[2]));
        const double omega = triangle_solid_angle(ref, c.triangle);
        expect_uniform_in_solid_angle(
            [&](const Vec2& u) { return st.sample(u); },
            [&](const DVec3& d, double slack) { return ray_meets(ref, d, c.triangle, slack); },
            omega, zoom_onto(ref, {c.triangle[0], c.triangle[1], c.triangle[2]}, omega), c.name,
            cases);
    }
}

namespace {

struct RectangleCase {
    std::string name;
    DVec3 corner, edge_x, edge_y;
    DVec3 ref;
};

const RectangleCase kRectangleCases[] = {
    {"ordinary", DVec3(-0.5, -0.3, 0), DVec3(1.0, 0, 0), DVec3(0, 0.6, 0), DVec3(0.2, 0.1, 0.9)},
    {"rotated, from below", DVec3(0.2, -0.3, 0.1), DVec3(0.6, 0.0, 0.8), DVec3(0.0, 0.5, 0.0),
     DVec3(-0.5, 0.4, 0.6)},
    {"thin", DVec3(-1.0, -0.01, 0), DVec3(2.0, 0, 0), DVec3(0, 0.02, 0), DVec3(0.3, 0.0, 0.4)},
    {"large (close)", DVec3(-4, -3, 0), DVec3(8.0, 0, 0), DVec3(0, 6.0, 0), DVec3(0.5, -0.2, 0.03)},
    {"nearly grazing", DVec3(-0.5, -0.3, 0), DVec3(1.0, 0, 0), DVec3(0, 0.6, 0),
     DVec3(3.0, 0.2, 0.1)},
    {"far", DVec3(-0.5, -0.3, 0), DVec3(1.0, 0, 0), DVec3(0, 0.6, 0), DVec3(-9.0, 7.0, 25.0)},
};

}  // namespace

TEST(SphericalRectangleSlow, SamplesAreUniformInSolidAngleAndOnTheRectangle) {
    const int cases = static_cast<int>(std::size(kRectangleCases));
    for (const RectangleCase& c : kRectangleCases) {
        const DVec3 ref = DVec3(Vec3(c.ref));
        const SphericalRectangle sr(Vec3(ref), Vec3(c.corner), Vec3(c.edge_x), Vec3(c.edge_y));
        const Triangle lower{c.corner, c.corner + c.edge_x, c.corner + c.edge_x + c.edge_y};
        const Triangle upper{c.corner, c.corner + c.edge_x + c.edge_y, c.corner + c.edge_y};
        const double omega = triangle_solid_angle(ref, lower) + triangle_solid_angle(ref, upper);
        EXPECT_NEAR(sr.solid_angle(), omega, 1e-5 * omega + 1e-9) << c.name;
        const DVec3 normal = glm::normalize(glm::cross(c.edge_x, c.edge_y));
        int off_plane = 0;
        expect_uniform_in_solid_angle(
            [&](const Vec2& u) {
                const Vec3 p = sr.sample(u);
                const double scale = glm::length(c.edge_x) + glm::length(c.edge_y);
                if (std::abs(glm::dot(DVec3(p) - c.corner, normal)) > 1e-5 * scale) ++off_plane;
                return Vec3(glm::normalize(DVec3(p) - ref));
            },
            [&](const DVec3& d, double slack) {
                return ray_meets(ref, d, lower, slack) || ray_meets(ref, d, upper, slack);
            },
            omega,
            zoom_onto(ref,
                      {c.corner, c.corner + c.edge_x, c.corner + c.edge_y,
                       c.corner + c.edge_x + c.edge_y},
                      omega),
            c.name, cases);
        EXPECT_EQ(off_plane, 0) << c.name;
    }
}
