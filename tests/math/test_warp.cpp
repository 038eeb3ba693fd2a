// Warps against their densities (chi-square), and the frame and transform algebra that
// every BSDF and shape relies on.
#include <glint/core/rng.h>
#include <glint/math/frame.h>
#include <glint/math/transform.h>
#include <glint/math/warp.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>

#include <cmath>
#include <vector>

using namespace glint;

namespace {

constexpr int kSamples = 200000;

// Runs the chi-square test and checks, inside the sampler, that every direction is a unit
// vector. `tests_in_case` applies a Bonferroni correction to the 0.01 significance.
void expect_matches_pdf(const std::function<Vec3(const Vec2&)>& warp,
                        const std::function<double(const Vec3&)>& pdf, const char* label,
                        int tests_in_case, int cos_theta_bins = 20) {
    float worst_length_error = 0.0f;
    auto sample = [&](const Vec2& u, float) -> std::optional<Vec3> {
        const Vec3 w = warp(u);
        worst_length_error = std::max(worst_length_error, std::abs(glm::length(w) - 1.0f));
        return w;
    };
    const auto result = test::chi_square_directions(sample, pdf, kSamples, 7, cos_theta_bins, 40,
                                                    0.01 / tests_in_case);
    EXPECT_TRUE(result.passed) << label << ": " << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 1e-3) << label;
    EXPECT_LT(worst_length_error, 1e-5f) << label;
}

// Pearson's statistic of points that should be uniform over the unit square.
double uniform_square_p_value(const std::vector<Vec2>& points, int nx, int ny) {
    std::vector<double> counts(nx * ny, 0.0);
    for (const Vec2& p : points) {
        const int ix = std::clamp(static_cast<int>(p.x * nx), 0, nx - 1);
        const int iy = std::clamp(static_cast<int>(p.y * ny), 0, ny - 1);
        counts[iy * nx + ix] += 1.0;
    }
    const double expected = static_cast<double>(points.size()) / (nx * ny);
    double chi2 = 0.0;
    for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
    return test::chi_square_upper_tail(chi2, nx * ny - 1);
}

Vec3 random_unit_vector(Rng& rng) {
    return warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
}

void expect_vec_near(const Vec3& a, const Vec3& b, float tolerance, const char* what) {
    EXPECT_NEAR(a.x, b.x, tolerance) << what;
    EXPECT_NEAR(a.y, b.y, tolerance) << what;
    EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

}  // namespace

TEST(Warp, CosineHemisphereMatchesPdf) {
    expect_matches_pdf(warp::square_to_cosine_hemisphere, warp::cosine_hemisphere_pdf,
                       "cosine hemisphere", 1);
}

TEST(Warp, UniformHemisphereMatchesPdf) {
    expect_matches_pdf(warp::square_to_uniform_hemisphere, warp::uniform_hemisphere_pdf,
                       "uniform hemisphere", 1);
}

TEST(Warp, UniformSphereMatchesPdf) {
    expect_matches_pdf(
        warp::square_to_uniform_sphere, [](const Vec3&) { return warp::uniform_sphere_pdf(); },
        "uniform sphere", 1);
}

TEST(Warp, UniformConeMatchesPdf) {
    const float cones[] = {0.95f, 0.93f, 0.71f, 0.5f, 0.0f, -0.37f, -0.5f};
    for (float cos_max : cones) {
        const std::string label = "cone cos_theta_max=" + std::to_string(cos_max);
        expect_matches_pdf([&](const Vec2& u) { return warp::square_to_uniform_cone(u, cos_max); },
                           [&](const Vec3& w) { return warp::uniform_cone_pdf(w, cos_max); },
                           label.c_str(), 7);
    }
}

// Samples stay inside the cone even for u next to 1, where rounding could push them out.
TEST(Warp, UniformConeStaysInsideItsCone) {
    const float one_minus = std::nextafter(1.0f, 0.0f);
    for (float cos_max : {0.95f, 0.999f, 0.5f, 0.0f, -0.5f, -1.0f}) {
        for (float ux : {0.0f, 0.5f, one_minus}) {
            const Vec3 w = warp::square_to_uniform_cone(Vec2(ux, 0.3f), cos_max);
            EXPECT_GE(w.z, cos_max) << cos_max << " " << ux;
            EXPECT_GT(warp::uniform_cone_pdf(w, cos_max), 0.0f) << cos_max << " " << ux;
        }
    }
    // The full sphere as a cone has the uniform sphere's density.
    EXPECT_NEAR(warp::uniform_cone_pdf(Vec3(0, 0, -1), -1.0f), warp::uniform_sphere_pdf(), 1e-7f);
}

TEST(Warp, ConcentricDiskIsUniform) {
    // (r^2, phi / 2 pi) of a uniform disk point is uniform over the unit square.
    Rng rng(11);
    std::vector<Vec2> mapped;
    mapped.reserve(kSamples);
    float max_radius = 0.0f;
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 d =
            warp::square_to_uniform_disk_concentric(Vec2(rng.next_float(), rng.next_float()));
        const float r2 = d.x * d.x + d.y * d.y;
        max_radius = std::max(max_radius, std::sqrt(r2));
        float phi = std::atan2(d.y, d.x);
        if (phi < 0.0f) phi += 2.0f * kPi;
        mapped.emplace_back(r2, phi / (2.0f * kPi));
    }
    EXPECT_LE(max_radius, 1.0f + 1e-6f);
    EXPECT_GT(uniform_square_p_value(mapped, 20, 40), 0.01);
    // The centre and the corners of the square land where they should.
    const Vec2 centre = warp::square_to_uniform_disk_concentric(Vec2(0.5f));
    EXPECT_EQ(centre, Vec2(0.0f));
    EXPECT_NEAR(glm::length(warp::square_to_uniform_disk_concentric(Vec2(1.0f, 1.0f))), 1.0f,
                1e-6f);
}

// The mapping evaluates sin and cos by polynomials on [-pi/4, pi/4]; it must agree with
// Shirley and Chiu's formulas through libm to float precision everywhere on the square.
TEST(Warp, ConcentricDiskMatchesTheClosedForm) {
    float worst = 0.0f;
    for (int j = 0; j <= 200; ++j) {
        for (int i = 0; i <= 200; ++i) {
            const Vec2 u(i / 200.0f, j / 200.0f);
            const double ox = 2.0 * u.x - 1.0, oy = 2.0 * u.y - 1.0;
            if (ox == 0.0 && oy == 0.0) continue;
            const bool x_major = std::abs(ox) > std::abs(oy);
            const double r = x_major ? ox : oy;
            const double theta =
                x_major ? (kPi / 4.0) * (oy / ox) : kPi / 2.0 - (kPi / 4.0) * (ox / oy);
            const Vec2 d = warp::square_to_uniform_disk_concentric(u);
            worst = std::max(worst, std::abs(d.x - static_cast<float>(r * std::cos(theta))));
            worst = std::max(worst, std::abs(d.y - static_cast<float>(r * std::sin(theta))));
        }
    }
    EXPECT_LT(worst, 4e-7f);
}

TEST(Warp, TriangleIsUniform) {
    // The inverse of the square-root warp, (u0, u1) = ((1 - b0)^2, b1 / (1 - b0)), takes a
    // uniform triangle to a uniform square, so uniformity over the triangle becomes uniformity
    // over the square.
    Rng rng(12);
    std::vector<Vec2> mapped;
    mapped.reserve(kSamples);
    int outside = 0;
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 b = warp::square_to_uniform_triangle(Vec2(rng.next_float(), rng.next_float()));
        const double b1 = b.x, b2 = b.y, b0 = 1.0 - b1 - b2;
        if (b1 < 0.0 || b2 < 0.0 || b0 < -1e-7) ++outside;
        const double s = 1.0 - b0;
        mapped.emplace_back(static_cast<float>(s * s), s > 0.0 ? static_cast<float>(b1 / s) : 0.0f);
    }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(uniform_square_p_value(mapped, 30, 30), 0.01);
}

TEST(Frame, OrthonormalAndRoundTrips) {
    Rng rng(3);
    std::vector<Vec3> normals = {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(0, -1, 0),
                                 glm::normalize(Vec3(1e-4f, 0.0f, -1.0f))};
    for (int i = 0; i < 200; ++i) normals.push_back(random_unit_vector(rng));
    for (const Vec3& n : normals) {
        for (const Frame& f :
             {Frame::from_normal(n), Frame::from_normal_tangent(n, random_unit_vector(rng))}) {
            EXPECT_NEAR(glm::length(f.s()), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::length(f.t()), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(f.s(), f.t()), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(f.s(), f.n()), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(f.t(), f.n()), 0.0f, 1e-5f);
            // Right-handed, so that local directions keep their orientation in the world.
            expect_vec_near(glm::cross(f.s(), f.t()), f.n(), 1e-5f, "s x t = n");
            const Vec3 v = random_unit_vector(rng) * 3.0f;
            expect_vec_near(f.to_world(f.to_local(v)), v, 1e-5f, "world round trip");
            expect_vec_near(f.to_local(f.to_world(v)), v, 1e-5f, "local round trip");
            expect_vec_near(f.to_local(n), Vec3(0, 0, 1), 1e-5f, "normal is local z");
            EXPECT_NEAR(cos_theta(f.to_local(v)), glm::dot(v, n), 1e-5f);
        }
    }
    // The tangent frame keeps the tangent's direction in the plane.
    const Frame f = Frame::from_normal_tangent(Vec3(0, 0, 1), Vec3(2, 0, 1));
    expect_vec_near(f.s(), Vec3(1, 0, 0), 1e-6f, "tangent kept");
}

TEST(Transform, PointsVectorsNormals) {
    const Transform t = Transform::translate(Vec3(1, 2, 3));
    expect_vec_near(t.point(Vec3(1, 1, 1)), Vec3(2, 3, 4), 1e-6f, "translated point");
    expect_vec_near(t.vector(Vec3(1, 1, 1)), Vec3(1, 1, 1), 1e-6f, "vectors ignore translation");
    expect_vec_near(t.normal(Vec3(0, 0, 1)), Vec3(0, 0, 1), 1e-6f, "normals ignore translation");

    // A non-uniform scale: normals stay perpendicular to transformed tangents.
    const Transform s = Transform::scale(Vec3(2, 0.5f, 4));
    expect_vec_near(s.point(Vec3(1, 1, 1)), Vec3(2, 0.5f, 4), 1e-6f, "scaled point");
    Rng rng(5);
    const Transform m = Transform::translate(Vec3(-3, 1, 2)) *
                        Transform::rotate(37.0f, Vec3(1, 2, 3)) *
                        Transform::scale(Vec3(2, 0.5f, 4));
    for (int i = 0; i < 100; ++i) {
        const Vec3 n = random_unit_vector(rng);
        const Frame f = Frame::from_normal(n);
        const Vec3 tn = m.normal(n);
        EXPECT_NEAR(glm::dot(tn, m.vector(f.s())), 0.0f, 1e-4f);
        EXPECT_NEAR(glm::dot(tn, m.vector(f.t())), 0.0f, 1e-4f);
        // The transformed normal is on the same side as the transformed normal direction.
        EXPECT_GT(glm::dot(tn, m.vector(n)), 0.0f);
    }
    EXPECT_FALSE(m.swaps_handedness());
    EXPECT_TRUE(Transform::scale(Vec3(-1, 1, 1)).swaps_handedness());
    EXPECT_TRUE(Transform().is_identity());
}

TEST(Transform, InverseAndComposition) {
    Rng rng(6);
    const Transform a = Transform::translate(Vec3(4, -2, 0.5f)) *
                        Transform::rotate(-70.0f, Vec3(0, 1, 1)) *
                        Transform::scale(Vec3(3, 1, 0.25f));
    const Transform general(a.matrix());  // inverse computed from the matrix
    for (int i = 0; i < 100; ++i) {
        const Vec3 p = random_unit_vector(rng) * 5.0f;
        expect_vec_near(a.inverse().point(a.point(p)), p, 1e-4f, "inverse point");
        expect_vec_near(a.point(a.inverse().point(p)), p, 1e-4f, "point inverse");
        expect_vec_near(a.inverse().vector(a.vector(p)), p, 1e-4f, "inverse vector");
        expect_vec_near(general.inverse().point(p), a.inverse().point(p), 1e-4f,
                        "glm inverse agrees");
        // (A * B) applies B first.
        const Transform b = Transform::rotate(90.0f, Vec3(0, 0, 1));
        expect_vec_near((a * b).point(p), a.point(b.point(p)), 1e-4f, "composition order");
        expect_vec_near((a * b).inverse().point(p), b.inverse().point(a.inverse().point(p)), 1e-4f,
                        "inverse of a composition");
    }
}

TEST(Transform, RotateAboutAxis) {
    // Right-handed: +90 degrees about z takes x to y.
    const Transform rz = Transform::rotate(90.0f, Vec3(0, 0, 1));
    expect_vec_near(rz.vector(Vec3(1, 0, 0)), Vec3(0, 1, 0), 1e-6f, "x -> y");
    expect_vec_near(Transform::rotate(90.0f, Vec3(1, 0, 0)).vector(Vec3(0, 1, 0)), Vec3(0, 0, 1),
                    1e-6f, "y -> z");
    expect_vec_near(Transform::rotate(90.0f, Vec3(0, 1, 0)).vector(Vec3(0, 0, 1)), Vec3(1, 0, 0),
                    1e-6f, "z -> x");

    // Against Rodrigues' formula about an unnormalised axis.
    Rng rng(8);
    for (int i = 0; i < 50; ++i) {
        const Vec3 axis = random_unit_vector(rng);
        const float degrees = 360.0f * rng.next_float() - 180.0f;
        const Transform r = Transform::rotate(degrees, axis * 2.5f);
        const Vec3 v = random_unit_vector(rng) * 2.0f;
        const float a = glm::radians(degrees);
        const Vec3 expected = v * std::cos(a) + glm::cross(axis, v) * std::sin(a) +
                              axis * glm::dot(axis, v) * (1.0f - std::cos(a));
        expect_vec_near(r.vector(v), expected, 1e-5f, "Rodrigues");
        expect_vec_near(r.vector(axis), axis, 1e-5f, "axis fixed");
        EXPECT_NEAR(glm::length(r.vector(v)), glm::length(v), 1e-5f);
        expect_vec_near(r.inverse().vector(r.vector(v)), v, 1e-5f, "rotation inverse");
    }
}
