// Emission sampling for light paths and photons: every light's sample_le against its
// pdf_le, by chi-square of the direction and (where it is not a delta) the position; that
// pdf_le reproduces the densities sample_le reports; and that the photons' mean power
// (LightEmission::beta) is the light's power.
#include <glint/core/rng.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/sphere.h>
#include <glint/integrator/photon/projection_map.h>
#include <glint/light/area_light.h>
#include <glint/light/environment_light.h>
#include <glint/light/point_light.h>
#include <glint/math/frame.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>
#include <support/chi_square_plane.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace glint;

namespace {

constexpr int kEmissionSamples = 100000;

// One sample_le call from the three numbers of a chi-square sample, the remaining two
// dimensions from `rng` (fixed seed): `position_first` says whether the chi-square's
// numbers pick the position or the direction.
std::optional<LightEmission> draw(const Light& light, const Vec2& u, float u_extra, Rng& rng,
                                  bool position_first) {
    const Vec2 other(rng.next_float(), rng.next_float());
    return position_first ? light.sample_le(u, other, u_extra) : light.sample_le(other, u, u_extra);
}

// sample_le's densities against pdf_le of its own ray, and the mean of beta() against
// power() (relative `power_tolerance`; 0 where every photon carries the same power).
void expect_consistent(const Light& light, const std::string& label, double power_tolerance) {
    Rng rng(7);
    int mismatches = 0, drawn = 0;
    Spectrum sum(0.0f);
    std::vector<double> total(3, 0.0);
    for (int i = 0; i < kEmissionSamples; ++i) {
        const Vec2 a(rng.next_float(), rng.next_float()), b(rng.next_float(), rng.next_float());
        const std::optional<LightEmission> e = light.sample_le(a, b, rng.next_float());
        if (!e) continue;
        ++drawn;
        const EmissionPdf pdf = light.pdf_le(e->ray, e->n);
        if (std::abs(pdf.pos - e->pdf_pos) > 1e-5f * e->pdf_pos ||
            std::abs(pdf.dir - e->pdf_dir) > 1e-4f * e->pdf_dir || !(e->pdf_dir > 0.0f) ||
            std::abs(glm::length(e->ray.direction) - 1.0f) > 1e-5f) {
            ++mismatches;
        }
        const Spectrum beta = e->beta();
        for (int c = 0; c < 3; ++c) total[c] += to_rgb(beta)[c];
    }
    EXPECT_EQ(mismatches, 0) << label;
    EXPECT_GT(drawn, 0) << label;
    const Spectrum power = light.power();
    for (int c = 0; c < 3; ++c) {
        const double mean = total[c] / kEmissionSamples;
        EXPECT_NEAR(mean, to_rgb(power)[c], std::max(power_tolerance, 1e-5) * to_rgb(power)[c])
            << label << " channel " << c;
    }
}

// Chi-square of directions `to_test` (a sampled emission mapped to a unit vector) against
// `density` (of that unit vector).
void expect_directions(const Light& light,
                       const std::function<std::optional<Vec3>(const LightEmission&)>& to_test,
                       const std::function<double(const Vec3&)>& density, const std::string& label,
                       int cos_theta_bins = 20) {
    Rng rng(11);
    const auto result = test::chi_square_directions(
        [&](const Vec2& u, float u_extra) -> std::optional<Vec3> {
            const std::optional<LightEmission> e = draw(light, u, u_extra, rng, false);
            if (!e) return std::nullopt;
            return to_test(*e);
        },
        density, kEmissionSamples, 3, cos_theta_bins, 40, 0.001);
    EXPECT_TRUE(result.passed) << label << ": " << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 3e-3) << label << ": " << result.details;
}

// Chi-square of origins mapped to a plane by `to_plane`, inside [lo, hi], against `density`.
void expect_positions(const Light& light,
                      const std::function<std::optional<Vec2>(const LightEmission&)>& to_plane,
                      const std::function<double(const Vec2&)>& density, const Vec2& lo,
                      const Vec2& hi, const std::string& label) {
    Rng rng(13);
    const auto result = test::chi_square_points(
        [&](const Vec2& u, float u_extra) -> std::optional<Vec2> {
            const std::optional<LightEmission> e = draw(light, u, u_extra, rng, true);
            if (!e) return std::nullopt;
            return to_plane(*e);
        },
        density, lo, hi, kEmissionSamples, 5, 0.001);
    EXPECT_TRUE(result.passed) << label << ": " << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 3e-3) << label << ": " << result.details;
}

// Directions of a surface light in the frame of the surface's front normal at the origin;
// their density is pdf_le's at any point, since the lobe is the same everywhere.
void expect_surface_directions(const AreaLight& light,
                               const std::function<Vec3(const Vec3&)>& front_normal, const Vec3& p0,
                               const std::string& label) {
    const Vec3 n0 = front_normal(p0);
    const Frame f0 = Frame::from_normal(n0);
    expect_directions(
        light,
        [&](const LightEmission& e) -> std::optional<Vec3> {
            return Frame::from_normal(front_normal(e.ray.origin)).to_local(e.ray.direction);
        },
        [&](const Vec3& v) {
            return light.pdf_le(Ray{p0, f0.to_world(v)}, n0).dir;
        },
        label);
}

bool inside_convex(const std::vector<Vec2>& polygon, const Vec2& p) {
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0.0f) return false;
    }
    return true;
}

// The disc of radius r centred on `centre`, perpendicular to `axis`, in the coordinates of
// Frame::from_normal(axis), and the density 1 / (pi r^2) on it.
std::optional<Vec2> on_disc(const Vec3& origin, const Vec3& centre, const Vec3& axis) {
    const Frame f = Frame::from_normal(axis);
    const Vec3 q = origin - centre;
    if (std::abs(glm::dot(q, axis)) > 1e-4f * (1.0f + glm::length(q))) return std::nullopt;
    return Vec2(glm::dot(q, f.s()), glm::dot(q, f.t()));
}

double disc_density(const Vec2& p, float radius, float pdf_pos) {
    return glm::dot(p, p) <= radius * radius ? pdf_pos : 0.0;
}

}  // namespace

TEST(LightEmission, QuadAreaLightOneAndTwoSided) {
    // A convex quad that is not a parallelogram, so a triangle chosen by anything but its
    // area shows in the positions.
    const std::vector<Vec2> corners = {{-0.5f, -0.4f}, {0.9f, -0.6f}, {0.6f, 0.8f}, {-0.7f, 0.3f}};
    const TriangleMesh mesh("quad", make_quad_mesh(Vec3(corners[0], 0), Vec3(corners[1], 0),
                                                   Vec3(corners[2], 0), Vec3(corners[3], 0)));
    const Vec3 front = mesh.make_sampler(Transform())->sample_area(Vec2(0.5f), 0.5f).n;
    for (const bool two_sided : {false, true}) {
        const AreaLight light(mesh.make_sampler(Transform()),
                              uplift(Rgb(2.0f, 1.0f, 0.5f), RgbRole::unbounded), two_sided);
        const std::string label = two_sided ? "two-sided quad" : "one-sided quad";
        expect_consistent(light, label, 1e-4);
        expect_surface_directions(
            light, [&](const Vec3&) { return front; }, Vec3(0.0f), label);
        expect_positions(
            light, [](const LightEmission& e) -> std::optional<Vec2> { return Vec2(e.ray.origin); },
            [&](const Vec2& p) {
                return inside_convex(corners, p)
                           ? light.pdf_le(Ray{Vec3(p, 0.0f), front}, front).pos
                           : 0.0;
            },
            Vec2(-0.8f, -0.7f), Vec2(1.0f, 0.9f), label);
    }
}

TEST(LightEmission, SphereAreaLightOneAndTwoSided) {
    const Vec3 centre(0.5f, -1.0f, 2.0f);
    const float radius = 0.7f;
    auto front = [&](const Vec3& p) { return glm::normalize(p - centre); };
    for (const bool two_sided : {false, true}) {
        const AreaLight light(std::make_unique<SphereSampler>(centre, radius),
                              uplift(Rgb(1.0f, 3.0f, 2.0f), RgbRole::unbounded), two_sided);
        const std::string label = two_sided ? "two-sided sphere" : "one-sided sphere";
        expect_consistent(light, label, 1e-4);
        expect_surface_directions(light, front, centre + Vec3(0.0f, radius, 0.0f), label);
        // Positions as directions from the centre: the area density times r^2.
        expect_directions(
            light,
            [&](const LightEmission& e) -> std::optional<Vec3> { return front(e.ray.origin); },
            [&](const Vec3& w) {
                return light.pdf_le(Ray{centre + radius * w, w}, w).pos * radius * radius;
            },
            label + " positions");
    }
}

TEST(LightEmission, PointLightIsUniformFromItsPosition) {
    const Vec3 position(1.0f, 2.0f, -3.0f);
    const PointLight light(position, uplift(Rgb(3.0f, 2.0f, 1.0f), RgbRole::unbounded));
    expect_consistent(light, "point", 1e-4);
    expect_directions(
        light, [](const LightEmission& e) -> std::optional<Vec3> { return e.ray.direction; },
        [&](const Vec3& w) {
            return light.pdf_le(Ray{position, w}, Vec3(0.0f)).dir;
        },
        "point");
    const auto e = light.sample_le(Vec2(0.3f), Vec2(0.6f), 0.2f);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->ray.origin, position);
    EXPECT_EQ(e->pdf_pos, 1.0f);
    EXPECT_EQ(e->n, Vec3(0.0f));
}

TEST(LightEmission, SpotLightIsUniformInItsCone) {
    const Vec3 position(0.0f, 1.0f, 0.0f), target(0.3f, -1.0f, 0.4f);
    const SpotLight light(position, target - position,
                          uplift(Rgb(5.0f, 4.0f, 3.0f), RgbRole::unbounded), 50.0f, 30.0f);
    const Frame frame = Frame::from_normal(glm::normalize(target - position));
    // The falloff makes photons' powers differ; the tolerance is several standard errors.
    expect_consistent(light, "spot", 0.01);
    expect_directions(
        light,
        [&](const LightEmission& e) -> std::optional<Vec3> {
            return frame.to_local(e.ray.direction);
        },
        [&](const Vec3& v) {
            return light.pdf_le(Ray{position, frame.to_world(v)}, Vec3(0.0f)).dir;
        },
        "spot", 40);
    EXPECT_EQ(light.pdf_le(Ray{position, -frame.n()}, Vec3(0.0f)).dir, 0.0f);
}

TEST(LightEmission, DirectionalLightEntersThroughADiscCoveringTheScene) {
    const Vec3 direction = glm::normalize(Vec3(0.3f, -1.0f, 0.2f));
    DirectionalLight light(direction, uplift(Rgb(1.0f, 0.5f, 0.25f), RgbRole::unbounded));
    const Vec3 centre(1.0f, 0.0f, -2.0f);
    const float radius = 3.0f;
    light.preprocess(centre, radius);
    expect_consistent(light, "directional", 1e-4);
    const Vec3 disc_centre = centre - radius * direction;
    expect_positions(
        light,
        [&](const LightEmission& e) { return on_disc(e.ray.origin, disc_centre, direction); },
        [&](const Vec2& p) {
            return disc_density(p, radius,
                                light.pdf_le(Ray{disc_centre, direction}, Vec3(0.0f)).pos);
        },
        Vec2(-1.1f * radius), Vec2(1.1f * radius), "directional");
    Rng rng(3);
    for (int i = 0; i < 100; ++i) {
        const auto e = light.sample_le(Vec2(rng.next_float(), rng.next_float()),
                                       Vec2(rng.next_float(), rng.next_float()), rng.next_float());
        ASSERT_TRUE(e);
        EXPECT_EQ(e->ray.direction, direction);
        EXPECT_EQ(e->pdf_dir, 1.0f);
    }
}

TEST(LightEmission, EnvironmentLightDirectionsAndDisc) {
    // A small sky, brighter towards the zenith and varying in azimuth, with a bright spot.
    constexpr int kWidth = 16, kHeight = 8;
    std::vector<Spectrum> pixels;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const float a = 1.0f + 0.5f * std::cos(2.0f * kPi * (x + 0.5f) / kWidth);
            Spectrum p =
                uplift(Rgb(1.0f - 0.1f * y, 0.8f, 0.2f + 0.1f * y), RgbRole::unbounded) * a;
            if (x == 5 && y == 2) p = uplift(Rgb(30.0f, 25.0f, 20.0f), RgbRole::unbounded);
            pixels.push_back(p);
        }
    }
    const Mat3 tilt = Mat3(Transform::rotate(30.0f, Vec3(1.0f, 0.0f, 0.0f)).matrix());
    EnvironmentLight light(std::move(pixels), kWidth, kHeight, tilt);
    const Vec3 centre(0.0f, 1.0f, 0.5f);
    const float radius = 2.0f;
    light.preprocess(centre, radius);
    // Powers vary with the map's bilinear lookup against a per-pixel density.
    expect_consistent(light, "environment", 0.01);
    expect_directions(
        light, [](const LightEmission& e) -> std::optional<Vec3> { return -e.ray.direction; },
        [&](const Vec3& w) {
            return light.pdf_le(Ray{centre, -w}, Vec3(0.0f)).dir;
        },
        "environment");
    // The disc faces the sampled direction, tangent to the scene's sphere on the sky's side.
    expect_positions(
        light,
        [&](const LightEmission& e) {
            const Vec3 to_sky = -e.ray.direction;
            return on_disc(e.ray.origin, centre + radius * to_sky, to_sky);
        },
        [&](const Vec2& p) {
            return disc_density(p, radius,
                                light.pdf_le(Ray{centre, Vec3(0, 0, 1)}, Vec3(0.0f)).pos);
        },
        Vec2(-1.1f * radius), Vec2(1.1f * radius), "environment");
}

// Projection maps serve the lights whose photons start at one point or on a surface,
// found through sample_le alone.
TEST(LightEmission, ProjectionMapsSupportPointAndSurfaceLightsOnly) {
    const TriangleMesh mesh(
        "quad", make_quad_mesh(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)));
    EXPECT_TRUE(ProjectionMap::supports(PointLight(Vec3(1.0f), Spectrum(1.0f))));
    EXPECT_TRUE(ProjectionMap::supports(
        SpotLight(Vec3(0.0f), Vec3(0, -1, 0), Spectrum(1.0f), 30.0f, 20.0f)));
    EXPECT_TRUE(
        ProjectionMap::supports(AreaLight(mesh.make_sampler(Transform()), Spectrum(1.0f), false)));
    EXPECT_TRUE(
        ProjectionMap::supports(AreaLight(mesh.make_sampler(Transform()), Spectrum(1.0f), true)));
    DirectionalLight sun(Vec3(0, -1, 0), Spectrum(1.0f));
    sun.preprocess(Vec3(0.0f), 2.0f);
    EXPECT_FALSE(ProjectionMap::supports(sun));
    // A scene of one point: the disc the sun enters through is a point too.
    sun.preprocess(Vec3(0.0f), 0.0f);
    EXPECT_FALSE(ProjectionMap::supports(sun));
    EnvironmentLight sky(std::vector<Spectrum>(8, Spectrum(1.0f)), 4, 2, Mat3(1.0f));
    sky.preprocess(Vec3(0.0f), 1.0f);
    EXPECT_FALSE(ProjectionMap::supports(sky));
}
