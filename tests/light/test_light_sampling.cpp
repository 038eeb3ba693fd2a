// Light sampling: the solid-angle densities of quad and sphere emitters against their
// samples (chi-square, densities computed here by ray casting, independently of the
// samplers), point and spot light closed forms, one-sided emission and light selection.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/mesh_sampler.h>
#include <glint/geometry/sphere.h>
#include <glint/light/area_light.h>
#include <glint/light/light_sampler.h>
#include <glint/light/point_light.h>

#include <gtest/gtest.h>
#include <support/cap_zoom.h>
#include <support/chi_square.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace glint;
using test::CapZoom;

namespace {

using DVec3 = glm::dvec3;

constexpr int kSamples = 200000;

// Ray parameter of the hit of (o, d) with triangle (a, b, c), Moller-Trumbore in double;
// negative on a miss. The edges move out by `slack` (barycentric units).
double ray_triangle(const DVec3& o, const DVec3& d, const DVec3& a, const DVec3& b, const DVec3& c,
                    double slack) {
    const DVec3 e1 = b - a, e2 = c - a;
    const DVec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return -1.0;
    const DVec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    if (u < -slack || u > 1.0 + slack) return -1.0;
    const DVec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < -slack || u + v > 1.0 + slack) return -1.0;
    return glm::dot(e2, q) / det;
}

// Solid angle of triangle t seen from o (Van Oosterom and Strackee 1983).
double solid_angle_of(const DVec3& o, const std::array<DVec3, 3>& t) {
    const DVec3 a = glm::normalize(t[0] - o), b = glm::normalize(t[1] - o),
                c = glm::normalize(t[2] - o);
    const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denominator = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
    return 2.0 * std::atan2(numerator, denominator);
}

// MeshSampler's rule: the estimate area |cos| / dist^2 from the part's centre reaches the
// lower limit, and the exact solid angle stays under the upper one.
bool solid_angle_sampled(const DVec3& o, const std::vector<std::array<DVec3, 3>>& parts,
                         double omega) {
    DVec3 centre(0.0);
    double area = 0.0;
    for (const auto& t : parts) {
        const double a = 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
        centre += a * (t[0] + t[1] + t[2]) / 3.0;
        area += a;
    }
    centre /= area;
    const DVec3 n =
        glm::normalize(glm::cross(parts[0][1] - parts[0][0], parts[0][2] - parts[0][0]));
    const DVec3 d = o - centre;
    const double estimate = area * std::abs(glm::dot(n, d)) / std::pow(glm::length(d), 3.0);
    return estimate >= MeshSampler::kMinSphericalSolidAngle &&
           omega <= MeshSampler::kMaxSphericalSolidAngle;
}

// The solid-angle density, seen from `ref`, with which a mesh emitter of at most
// MeshSampler::kSolidAngleTriangles triangles is sampled: a rectangle uniformly in its whole
// solid angle; other triangles each chosen by area, then uniform in their solid angle; and
// where a solid angle is outside the thresholds, uniform by area (dist^2 / (area |cos|)).
struct TriangleEmitter {
    std::vector<std::array<DVec3, 3>> triangles;
    bool rectangle = false;

    double area() const {
        double sum = 0.0;
        for (const auto& t : triangles) sum += triangle_area(t);
        return sum;
    }
    static double triangle_area(const std::array<DVec3, 3>& t) {
        return 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
    }
    double pdf(const Vec3& ref, const Vec3& w, double slack) const {
        const DVec3 o(ref), d = glm::normalize(DVec3(w));
        double whole = 0.0;
        for (const auto& t : triangles) whole += solid_angle_of(o, t);
        // On an edge two triangles share, either triangle's density is right.
        int hits = 0;
        for (const auto& t : triangles) hits += ray_triangle(o, d, t[0], t[1], t[2], slack) > 0.0;
        if (hits > 1 && slack > 0.0) return std::nan("");
        for (const auto& t : triangles) {
            const double hit = ray_triangle(o, d, t[0], t[1], t[2], slack);
            if (hit <= 0.0) continue;
            if (rectangle && solid_angle_sampled(o, triangles, whole)) return 1.0 / whole;
            const double omega = solid_angle_of(o, t);
            if (!rectangle && solid_angle_sampled(o, {t}, omega))
                return triangle_area(t) / area() / omega;
            const DVec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
            return hit * hit / (area() * std::abs(glm::dot(n, d)));
        }
        return 0.0;
    }
};

// A reference solid-angle density of direction `w`, with the light's edges moved out by
// `slack` (see ray_triangle and sphere_pdf).
using ReferencePdf = std::function<double(const Vec3& w, double slack)>;

// Chi-square of the directions from `ref` towards the points `sampler` draws, against
// `pdf`; also checks that each sample's own pdf, and the sampler's pdf() for its point,
// agree with `pdf`. Sampled points on the light's edge, rounded to float, may fall just
// outside it, so that check gives the edges some slack; the chi-square does not. With
// `zoom`, the chi-square runs on the zoomed cap.
void expect_matches(const ShapeSampler& sampler, const Vec3& ref, const ReferencePdf& pdf,
                    const std::string& label, int tests_in_case, CapZoom* zoom = nullptr) {
    int inconsistent = 0;
    double worst = 0.0;
    auto sample = [&](const Vec2& u, float u_select) -> std::optional<Vec3> {
        const ShapeSample s = sampler.sample(ref, u, u_select);
        const Vec3 w = glm::normalize(s.p - ref);
        const double expected = pdf(w, 1e-6);
        if (std::isnan(expected)) return zoom ? zoom->to_sphere(w) : w;  // on a shared edge
        const double error =
            std::max(std::abs(s.pdf - expected), std::abs(sampler.pdf(ref, s.p, s.n) - expected));
        worst = std::max(worst, error / expected);
        if (!(error <= 1e-3 * expected) || std::abs(glm::length(s.n) - 1.0f) > 1e-5f) {
            ++inconsistent;
        }
        return zoom ? zoom->to_sphere(w) : w;
    };
    std::function<double(const Vec3&)> density = [&](const Vec3& w) { return pdf(w, 0.0); };
    if (zoom) {
        density = [&](const Vec3& v) {
            return pdf(zoom->from_sphere(v), 0.0) * zoom->density_scale();
        };
    }
    const auto result =
        test::chi_square_directions(sample, density, kSamples, 31, 20, 40, 0.01 / tests_in_case);
    EXPECT_TRUE(result.passed) << label << ": " << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 2e-3) << label << ": " << result.details;
    EXPECT_EQ(inconsistent, 0) << label << ": worst relative pdf error " << worst;
    if (zoom) {
        EXPECT_EQ(zoom->outside, 0) << label;
    }
}

TriangleEmitter world_triangles(const MeshData& mesh, const Transform& to_world) {
    TriangleEmitter emitter;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        emitter.triangles.push_back({DVec3(to_world.point(mesh.positions[mesh.indices[i]])),
                                     DVec3(to_world.point(mesh.positions[mesh.indices[i + 1]])),
                                     DVec3(to_world.point(mesh.positions[mesh.indices[i + 2]]))});
    }
    return emitter;
}

// Solid-angle density of uniform sampling of the cone a sphere subtends from `ref`
// outside it, or of uniform area sampling from inside; by ray casting. The silhouette
// moves out by about `slack` times the distance (float directions are good to 1e-7).
double sphere_pdf(const DVec3& center, double radius, const Vec3& ref, const Vec3& w,
                  double slack) {
    const DVec3 o(ref), d = glm::normalize(DVec3(w));
    const DVec3 oc = o - center;
    const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - radius * radius;
    const double disc = b * b - c;
    if (disc < -2.0 * slack * radius * glm::length(oc)) return 0.0;
    if (c > 0.0) {
        if (b > 0.0) return 0.0;  // the sphere is behind
        const double sin2_max = radius * radius / glm::dot(oc, oc);
        const double one_minus_cos_max = sin2_max / (1.0 + std::sqrt(1.0 - sin2_max));
        return 1.0 / (2.0 * M_PI * one_minus_cos_max);
    }
    const double t = -b + std::sqrt(std::max(0.0, disc));  // inside: the one hit in front
    const DVec3 n = glm::normalize(oc + t * d);
    return t * t / (4.0 * M_PI * radius * radius * std::abs(glm::dot(n, d)));
}

}  // namespace

TEST(QuadEmitterSlow, SamplingMatchesSolidAngleDensity) {
    struct Case {
        std::string name;
        MeshData mesh;
        Transform to_world;
    };
    // A square, a convex quad that is not a parallelogram, and that quad placed by a
    // rotation, non-uniform scale and translation.
    const Transform placed = Transform::translate(Vec3(1, 2, -1)) *
                             Transform::rotate(40.0f, Vec3(1, 1, 0)) *
                             Transform::scale(Vec3(1.5f, 0.7f, 1.0f));
    const MeshData irregular = make_quad_mesh(Vec3(-0.5f, -0.4f, 0), Vec3(0.9f, -0.6f, 0),
                                              Vec3(0.6f, 0.8f, 0), Vec3(-0.7f, 0.3f, 0));
    const Case cases[] = {
        {"square",
         make_quad_mesh(Vec3(-0.5f, -0.5f, 0), Vec3(0.5f, -0.5f, 0), Vec3(0.5f, 0.5f, 0),
                        Vec3(-0.5f, 0.5f, 0)),
         Transform()},
        {"irregular", irregular, Transform()},
        {"placed", irregular, placed},
    };
    // Reference points in the quad's own space: above, oblique and low, behind.
    const Vec3 refs[] = {Vec3(0.1f, 0.2f, 0.8f), Vec3(1.5f, -1.0f, 0.3f), Vec3(0.2f, 0.1f, -0.6f)};
    for (const Case& c : cases) {
        const TriangleMesh mesh(c.name, c.mesh);
        // The mesh is in local space; its sampler places it in the world.
        const auto sampler = mesh.make_sampler(c.to_world);
        TriangleEmitter emitter = world_triangles(mesh.data(), c.to_world);
        emitter.rectangle = c.name == "square";
        EXPECT_NEAR(sampler->area(), emitter.area(), 1e-5 * emitter.area()) << c.name;
        for (const Vec3& local_ref : refs) {
            const Vec3 ref = c.to_world.point(local_ref);
            expect_matches(
                *sampler, ref,
                [&](const Vec3& w, double slack) { return emitter.pdf(ref, w, slack); },
                c.name + " from " + std::to_string(local_ref.x) + "," + std::to_string(local_ref.z),
                9);
        }
    }
}

namespace {

// One piece of an emitting mesh (a triangle) as a sampler of its own: what next-event
// estimation samples once the light tree has chosen that triangle.
class PieceSampler final : public ShapeSampler {
public:
    PieceSampler(const ShapeSampler& whole, uint32_t piece) : m_whole(whole), m_piece(piece) {}
    ShapeSample sample(const Vec3& ref, const Vec2& u, float u_select) const override {
        return m_whole.sample_piece(ref, u, u_select, m_piece);
    }
    float pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const override {
        return m_whole.pdf_piece(ref, p, n, m_piece);
    }
    float area() const override { return m_whole.piece_area(m_piece); }
    ShapeSample sample_area(const Vec2& u, float u_select) const override {
        return m_whole.sample_area(u, u_select);
    }
    Bounds3 bounds() const override { return m_whole.piece_bounds(m_piece); }

private:
    const ShapeSampler& m_whole;
    uint32_t m_piece;
};

}  // namespace

// Every triangle of an emitting mesh is a piece the light tree chooses on its own (a
// rectangle stays whole); a piece is sampled in its own solid angle, or by area where the
// thresholds say so, with the density given the piece. Checked on a quad's two triangles and
// on a box (12 triangles, more than the whole mesh samples in solid angle) near and far.
TEST(MeshEmitterPiecesSlow, EachTriangleMatchesItsDensity) {
    const TriangleMesh square("square", make_quad_mesh(Vec3(-0.5f, -0.5f, 0), Vec3(0.5f, -0.5f, 0),
                                                       Vec3(0.5f, 0.5f, 0), Vec3(-0.5f, 0.5f, 0)));
    EXPECT_EQ(square.make_sampler(Transform())->piece_count(), 1u);
    const TriangleMesh quad("irregular", make_quad_mesh(Vec3(-0.5f, -0.4f, 0), Vec3(0.9f, -0.6f, 0),
                                                        Vec3(0.6f, 0.8f, 0), Vec3(-0.7f, 0.3f, 0)));
    const TriangleMesh box("box", make_box_mesh(Vec3(-0.5f), Vec3(0.5f)));
    struct Case {
        const TriangleMesh* mesh;
        uint32_t piece;
        Vec3 ref;
    };
    const Case cases[] = {{&quad, 0, Vec3(0.1f, 0.2f, 0.8f)},
                          {&quad, 1, Vec3(-0.8f, 0.9f, 0.6f)},
                          {&box, 4, Vec3(0.2f, 0.1f, 0.9f)},
                          {&box, 7, Vec3(2.0f, 6.0f, 9.0f)}};
    for (const Case& c : cases) {
        const auto whole = c.mesh->make_sampler(Transform());
        ASSERT_EQ(whole->piece_count(), c.mesh->triangle_count());
        const TriangleEmitter all = world_triangles(c.mesh->data(), Transform());
        TriangleEmitter one;
        one.triangles = {all.triangles[c.piece]};
        const PieceSampler piece(*whole, c.piece);
        EXPECT_NEAR(piece.area(), one.area(), 1e-5 * one.area());
        expect_matches(
            piece, c.ref, [&](const Vec3& w, double slack) { return one.pdf(c.ref, w, slack); },
            c.mesh->name() + " piece " + std::to_string(c.piece),
            static_cast<int>(std::size(cases)));
    }
}

TEST(QuadEmitterSlow, FarAwayQuadOnAZoomedCap) {
    const TriangleMesh mesh("irregular", make_quad_mesh(Vec3(-0.5f, -0.4f, 0), Vec3(0.9f, -0.6f, 0),
                                                        Vec3(0.6f, 0.8f, 0), Vec3(-0.7f, 0.3f, 0)));
    const auto sampler = mesh.make_sampler(Transform());
    const TriangleEmitter emitter = world_triangles(mesh.data(), Transform());
    const Vec3 ref(3.0f, -2.0f, 12.0f);
    // A cap around the direction to the centre wide enough for every corner.
    const Vec3 axis = glm::normalize(Vec3(0.1f, 0.0f, 0.0f) - ref);
    double cos_min = 1.0;
    for (const auto& t : emitter.triangles) {
        for (const DVec3& p : t)
            cos_min = std::min(cos_min, glm::dot(glm::normalize(p - DVec3(ref)), DVec3(axis)));
    }
    CapZoom zoom(axis, 1.0 - 1.5 * (1.0 - cos_min));
    expect_matches(
        *sampler, ref, [&](const Vec3& w, double slack) { return emitter.pdf(ref, w, slack); },
        "far quad", 1, &zoom);
}

TEST(SphereEmitter, SamplingMatchesSolidAngleDensity) {
    const Vec3 center(0.5f, -1.0f, 2.0f);
    const float radius = 0.8f;
    const SphereSampler sampler(center, radius);
    struct Case {
        std::string name;
        Vec3 ref;
        bool zoomed;
    };
    const Case cases[] = {
        {"near", center + Vec3(0.6f, 0.9f, -0.3f), false},              // 1.36 radii
        {"grazing", center + radius * Vec3(0.0f, 0.0f, 1.02f), false},  // just outside
        {"far", center + Vec3(6.0f, -9.0f, 8.0f), true},                // 17 radii
        {"very far", center + Vec3(-60.0f, 20.0f, 0.0f), true},         // 79 radii
        {"sun", center + Vec3(100.0f, 100.0f, -100.0f), true},          // 216 radii
        {"distant", center + Vec3(0.0f, 800.0f, 0.0f), true},           // 1000 radii
        {"inside", center + Vec3(0.2f, -0.3f, 0.1f), false},
        {"at the centre", center, false},
    };
    for (const Case& c : cases) {
        auto pdf = [&](const Vec3& w, double slack) {
            return sphere_pdf(DVec3(center), radius, c.ref, w, slack);
        };
        if (!c.zoomed) {
            expect_matches(sampler, c.ref, pdf, c.name, 8);
            continue;
        }
        const Vec3 axis = glm::normalize(center - c.ref);
        const double sin2_max =
            double(radius) * radius / glm::dot(DVec3(center - c.ref), DVec3(center - c.ref));
        CapZoom zoom(axis, 1.0 - 1.3 * sin2_max / (1.0 + std::sqrt(1.0 - sin2_max)));
        expect_matches(sampler, c.ref, pdf, c.name, 8, &zoom);
    }
}

// Points land on the sphere; from outside only on the part facing the reference point, with
// the direction towards them.
TEST(SphereEmitter, SamplesLieOnTheVisibleSurface) {
    const Vec3 center(1.0f, 2.0f, 3.0f);
    const float radius = 2.0f;
    const SphereSampler sampler(center, radius);
    Rng rng(2);
    for (const Vec3& ref :
         {center + Vec3(0, 0, 2.5f), center + Vec3(30, -10, 0), center + Vec3(0.5f, 0, 0)}) {
        const bool outside = glm::length(ref - center) > radius;
        for (int i = 0; i < 2000; ++i) {
            const ShapeSample s =
                sampler.sample(ref, Vec2(rng.next_float(), rng.next_float()), rng.next_float());
            EXPECT_NEAR(glm::length(s.p - center), radius, 1e-5f * radius);
            EXPECT_NEAR(glm::dot(s.n, glm::normalize(s.p - center)), 1.0f, 1e-5f);
            if (outside) {
                EXPECT_GE(glm::dot(s.n, ref - s.p), -1e-4f * radius);
                // The direction the sampler hands the light is the one towards the point.
                EXPECT_NEAR(glm::dot(s.direction, glm::normalize(s.p - ref)), 1.0f, 1e-6f);
                EXPECT_NEAR(glm::length(s.direction), 1.0f, 1e-6f);
            }
        }
    }
    EXPECT_NEAR(sampler.area(), 4.0f * kPi * radius * radius, 1e-4f);
    // Placing a sphere shape: a uniform scale scales the radius, a non-uniform one is refused.
    const Sphere sphere(Vec3(0.0f), 1.5f);
    EXPECT_NEAR(sphere.make_sampler(Transform::scale(Vec3(2.0f)))->area(), 4.0f * kPi * 9.0f,
                1e-3f);
    EXPECT_THROW(sphere.make_sampler(Transform::scale(Vec3(1, 2, 1))), Error);
}

TEST(PointLight, IrradianceFallsOffAsInverseSquare) {
    const Spectrum intensity = uplift(Rgb(3.0f, 2.0f, 1.0f), RgbRole::unbounded);
    const PointLight light(Vec3(1, 2, 3), intensity);
    for (const Vec3& ref : {Vec3(1, 2, 0), Vec3(-4, 0, 1), Vec3(100, 2, 3)}) {
        const auto s = light.sample_li(ref, Vec2(0.5f), 0.5f);
        ASSERT_TRUE(s.has_value());
        const Vec3 d = Vec3(1, 2, 3) - ref;
        const float r2 = glm::dot(d, d);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(to_rgb(s->L)[c], to_rgb(intensity)[c] / r2,
                        1e-6f * to_rgb(intensity)[c] / r2);
        EXPECT_NEAR(glm::length(s->wi - glm::normalize(d)), 0.0f, 1e-6f);
        EXPECT_TRUE(s->is_delta);
        EXPECT_EQ(s->pdf, 1.0f);
        EXPECT_EQ(s->p, Vec3(1, 2, 3));
    }
    EXPECT_NEAR(to_rgb(light.power()).r, 4.0f * kPi * 3.0f, 1e-5f);
    EXPECT_FALSE(light.sample_li(Vec3(1, 2, 3), Vec2(0.5f), 0.5f).has_value());  // at the light
}

TEST(SpotLight, FalloffProfile) {
    const float cone = 30.0f, start = 20.0f;
    const Vec3 position(0, 0, 5), axis = glm::normalize(Vec3(0.3f, -0.2f, -1.0f));
    const SpotLight light(position, axis * 3.0f, Spectrum(10.0f), cone, start);
    const Frame frame = Frame::from_normal(axis);
    float previous = 2.0f;
    double power = 0.0;  // the intensity integrated over solid angle, by the midpoint rule
    constexpr int kSteps = 4000;
    for (int i = 0; i < kSteps; ++i) {
        const float degrees = (i + 0.5f) * 40.0f / kSteps;
        const Vec3 w = frame.to_world(
            Vec3(std::sin(glm::radians(degrees)), 0.0f, std::cos(glm::radians(degrees))));
        const float f = light.falloff(w);
        if (degrees < start) {
            EXPECT_EQ(f, 1.0f) << degrees;
        } else if (degrees > cone) {
            EXPECT_EQ(f, 0.0f) << degrees;
        }
        EXPECT_LE(f, previous) << degrees;  // monotone
        previous = f;
        const double theta0 = glm::radians(i * 40.0 / kSteps),
                     theta1 = glm::radians((i + 1) * 40.0 / kSteps);
        power += 10.0 * f * 2.0 * M_PI * (std::cos(theta0) - std::cos(theta1));

        // What a surface point in that direction receives.
        const Vec3 ref = position + 4.0f * w;
        const auto s = light.sample_li(ref, Vec2(0.5f), 0.5f);
        if (f > 0.0f) {
            ASSERT_TRUE(s.has_value()) << degrees;
            EXPECT_NEAR(to_rgb(s->L).r, 10.0f * f / 16.0f, 1e-5f) << degrees;
        } else {
            EXPECT_FALSE(s.has_value()) << degrees;
        }
    }
    // Around the axis, azimuth makes no difference.
    for (float phi : {0.0f, 1.0f, 2.5f, 4.0f}) {
        const float t = glm::radians(25.0f);
        const Vec3 w = frame.to_world(
            Vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)));
        EXPECT_NEAR(light.falloff(w),
                    light.falloff(frame.to_world(Vec3(std::sin(t), 0.0f, std::cos(t)))), 1e-5f);
    }
    EXPECT_NEAR(to_rgb(light.power()).r, power, 1e-3 * power);
}

TEST(AreaLight, OneSidedEmitsOnlyFromTheFront) {
    // Counter-clockwise seen from +z, so the front faces +z.
    const MeshData quad =
        make_quad_mesh(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0));
    const TriangleMesh mesh("quad", quad);
    const Spectrum radiance = uplift(Rgb(2.0f, 1.0f, 0.5f), RgbRole::unbounded);
    const AreaLight one_sided(mesh.make_sampler(Transform()), radiance, false);
    const AreaLight two_sided(mesh.make_sampler(Transform()), radiance, true);
    Rng rng(17);
    int front = 0, back = 0, two_front = 0, two_back = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec2 u(rng.next_float(), rng.next_float());
        const float u_select = rng.next_float();
        const Vec3 above(0.3f, -0.2f, 1.5f), below(0.3f, -0.2f, -1.5f);
        if (auto s = one_sided.sample_li(above, u, u_select)) {
            ++front;
            EXPECT_TRUE(s->L == radiance);
            SurfaceInteraction on_light;
            on_light.p = s->p;
            on_light.ng = Vec3(0, 0, 1);
            EXPECT_NEAR(one_sided.pdf_li(above, on_light), s->pdf, 1e-4f * s->pdf);
            EXPECT_FALSE(s->is_delta);
        }
        // Behind, also just behind the plane at a grazing angle.
        const Vec3 grazing(6.0f, 1.0f, -0.05f);
        if (one_sided.sample_li(below, u, u_select)) ++back;
        if (one_sided.sample_li(grazing, u, u_select)) ++back;
        if (two_sided.sample_li(above, u, u_select)) ++two_front;
        if (two_sided.sample_li(below, u, u_select)) ++two_back;
        if (two_sided.sample_li(grazing, u, u_select)) ++two_back;
    }
    EXPECT_EQ(front, 1000);
    EXPECT_EQ(back, 0);
    EXPECT_EQ(two_front, 1000);
    EXPECT_EQ(two_back, 2000);

    SurfaceInteraction si;
    si.p = Vec3(0.1f, 0.2f, 0.0f);
    si.ng = Vec3(0, 0, 1);
    EXPECT_TRUE(one_sided.le(si, glm::normalize(Vec3(0.2f, 0.1f, 1.0f))) == radiance);
    EXPECT_TRUE(one_sided.le(si, glm::normalize(Vec3(0.2f, 0.1f, -1.0f))).is_black());
    EXPECT_TRUE(one_sided.le(si, glm::normalize(Vec3(1.0f, 0.0f, -0.01f))).is_black());
    EXPECT_TRUE(one_sided.le(si, glm::normalize(Vec3(1.0f, 0.0f, 0.01f))) == radiance);
    EXPECT_TRUE(two_sided.le(si, glm::normalize(Vec3(0.2f, 0.1f, -1.0f))) == radiance);
    // Power: radiance times pi times area, per emitting side.
    EXPECT_NEAR(to_rgb(one_sided.power()).r, 2.0f * kPi * 4.0f, 1e-4f);
    EXPECT_NEAR(to_rgb(two_sided.power()).r, 2.0f * 2.0f * kPi * 4.0f, 1e-4f);
}

TEST(LightSampler, ChoosesInProportionToPower) {
    std::vector<std::unique_ptr<Light>> lights;
    lights.push_back(std::make_unique<PointLight>(Vec3(0.0f), Spectrum(0.0f)));  // black
    lights.push_back(std::make_unique<PointLight>(Vec3(0.0f), Spectrum(1.0f)));
    lights.push_back(std::make_unique<PointLight>(
        Vec3(0.0f), uplift(Rgb(3.0f, 0.5f, 2.0f), RgbRole::unbounded)));
    const TriangleMesh mesh(
        "quad", make_quad_mesh(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0)));
    lights.push_back(
        std::make_unique<AreaLight>(mesh.make_sampler(Transform()), Spectrum(1.5f), false));
    lights.push_back(std::make_unique<PointLight>(Vec3(0.0f), Spectrum(0.0f)));  // black, last
    const LightSampler sampler(lights);

    std::vector<double> expected(lights.size());
    double total = 0.0;
    for (size_t i = 0; i < lights.size(); ++i) {
        expected[i] = lights[i]->power().luminance();
        total += expected[i];
    }
    double pmf_sum = 0.0;
    for (size_t i = 0; i < lights.size(); ++i) {
        expected[i] /= total;
        EXPECT_EQ(lights[i]->index(), static_cast<int>(i));
        EXPECT_NEAR(sampler.pmf(*lights[i]), expected[i], 1e-6);
        pmf_sum += sampler.pmf(*lights[i]);
    }
    EXPECT_NEAR(pmf_sum, 1.0, 1e-6);

    Rng rng(23);
    constexpr int kDraws = 200000;
    std::vector<double> counts(lights.size(), 0.0);
    for (int i = 0; i < kDraws; ++i) {
        const auto choice = sampler.sample(rng.next_float());
        ASSERT_NE(choice.light, nullptr);
        EXPECT_EQ(choice.pmf, sampler.pmf(*choice.light));
        counts[choice.light->index()] += 1.0;
    }
    EXPECT_EQ(counts[0], 0.0);
    EXPECT_EQ(counts[4], 0.0);
    double chi2 = 0.0;
    for (size_t i = 1; i < 4; ++i)
        chi2 += sqr(counts[i] - kDraws * expected[i]) / (kDraws * expected[i]);
    EXPECT_GT(test::chi_square_upper_tail(chi2, 2), 0.01) << "chi2 = " << chi2;
    // The ends of [0, 1) never pick a black light.
    EXPECT_NE(sampler.sample(0.0f).light, lights[0].get());
    EXPECT_NE(sampler.sample(std::nextafter(1.0f, 0.0f)).light, lights[4].get());

    // With only black lights the choice falls back to uniform.
    std::vector<std::unique_ptr<Light>> dark;
    dark.push_back(std::make_unique<PointLight>(Vec3(0.0f), Spectrum(0.0f)));
    dark.push_back(std::make_unique<PointLight>(Vec3(1.0f), Spectrum(0.0f)));
    const LightSampler uniform(dark);
    EXPECT_NEAR(uniform.pmf(*dark[0]), 0.5f, 1e-6f);
    EXPECT_EQ(uniform.sample(0.75f).light, dark[1].get());
}

// docs/scene-language.md (spot_light): full intensity inside `falloff_start`, fading
// "smoothly (smoothstep in the cosine) to zero at `cone_angle`". The irradiance it gives a
// plane below it, E = I s(x) cos(theta) / r^2 with s(x) = x^2 (3 - 2x) and
// x = (cos(theta) - cos(cone)) / (cos(start) - cos(cone)), is computed here from that
// sentence alone and compared with the light's samples along a line across the plane.
TEST(SpotLight, IrradianceOnAPlaneFollowsTheDocumentedFalloff) {
    const float cone = 40.0f, start = 15.0f, height = 2.0f, intensity = 7.0f;
    const SpotLight light(Vec3(0.0f, 0.0f, height), Vec3(0.0f, 0.0f, -1.0f), Spectrum(intensity),
                          cone, start);
    const double cos_cone = std::cos(glm::radians(double(cone)));
    const double cos_start = std::cos(glm::radians(double(start)));
    int in_band = 0;
    for (int i = 0; i <= 400; ++i) {
        const Vec3 p(static_cast<float>(i) * 0.005f, 0.3f * static_cast<float>(i) * 0.005f, 0.0f);
        const DVec3 to_light = DVec3(0.0, 0.0, height) - DVec3(p);
        const double r2 = glm::dot(to_light, to_light);
        const double cos_theta = height / std::sqrt(r2);  // at the light and at the plane
        double s = 0.0;
        if (cos_theta >= cos_start) {
            s = 1.0;
        } else if (cos_theta > cos_cone) {
            const double x = (cos_theta - cos_cone) / (cos_start - cos_cone);
            s = x * x * (3.0 - 2.0 * x);
            ++in_band;
        }
        const double expected = intensity * s * cos_theta / r2;
        const auto sample = light.sample_li(p, Vec2(0.5f), 0.5f);
        const double measured = sample ? to_rgb(sample->L).r * sample->wi.z : 0.0;
        EXPECT_NEAR(measured, expected, 1e-4 * intensity / (height * height) + 1e-5 * expected)
            << "at " << glm::length(Vec2(p)) << " from the axis";
    }
    EXPECT_GT(in_band, 100);  // most of the points are in the falloff band
}

namespace {

// Chi-square test of the directions photons leave a light with, against `pdf`, using only
// the emitted ray (LightEmission's other fields are changing); also checks where the rays
// start with `origin_ok`.
void expect_emission_directions(const Light& light, const std::function<double(const Vec3&)>& pdf,
                                const std::function<bool(const Vec3&)>& origin_ok,
                                const std::string& label, int cos_theta_bins = 20) {
    int bad_origins = 0, unit = 0, count = 0;
    auto sample = [&](const Vec2& u, float u_extra) -> std::optional<Vec3> {
        // The position sample from the extra number (a planar light's directions do not
        // depend on it).
        const Vec2 u_position(u_extra, std::fmod(u_extra * 7.31f + 0.17f, 1.0f));
        const auto emission = light.sample_le(u_position, u, u_extra);
        if (!emission) return std::nullopt;
        ++count;
        bad_origins += !origin_ok(emission->ray.origin);
        unit += std::abs(glm::length(emission->ray.direction) - 1.0f) < 1e-5f;
        return emission->ray.direction;
    };
    const auto result =
        test::chi_square_directions(sample, pdf, kSamples, 41, cos_theta_bins, 40, 0.01 / 5);
    EXPECT_TRUE(result.passed) << label << ": " << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 2e-3) << label << ": " << result.details;
    EXPECT_EQ(bad_origins, 0) << label;
    EXPECT_EQ(unit, count) << label << ": directions not of unit length";
}

}  // namespace

// Photons leave a point light uniformly over the sphere, a spot light uniformly over its
// cone (the falloff goes into their power), and an area light with the cosine distribution
// about its emitting side's normal (half on each side when two-sided).
TEST(LightEmission, DirectionsFollowTheEmissionDistribution) {
    const Vec3 position(0.5f, -1.0f, 2.0f);
    auto at_position = [&](const Vec3& o) { return glm::length(o - position) < 1e-6f; };

    const PointLight point(position, Spectrum(2.0f));
    expect_emission_directions(
        point, [](const Vec3&) { return 1.0 / (4.0 * M_PI); }, at_position, "point light");

    // A cone of 50 degrees about +z: cos(theta) in [0.64, 1], a sixth of the sphere's
    // cos(theta) range, hence the finer bins.
    const float cone = 50.0f;
    const double cos_cone = std::cos(glm::radians(double(cone)));
    const SpotLight spot(position, Vec3(0.0f, 0.0f, 1.0f), Spectrum(3.0f), cone, 20.0f);
    expect_emission_directions(
        spot,
        [&](const Vec3& w) { return w.z > cos_cone ? 1.0 / (2.0 * M_PI * (1.0 - cos_cone)) : 0.0; },
        at_position, "spot light", 120);

    // A 2 x 1 quad in the plane z = 1, counter-clockwise seen from +z: its front faces +z.
    const TriangleMesh mesh(
        "quad", make_quad_mesh(Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(-1, 1, 1)));
    auto on_quad = [](const Vec3& o) {
        return std::abs(o.z - 1.0f) < 1e-3f && o.x >= -1.001f && o.x <= 1.001f && o.y >= -0.001f &&
               o.y <= 1.001f;
    };
    const AreaLight one_sided(mesh.make_sampler(Transform()), Spectrum(1.0f), false);
    expect_emission_directions(
        one_sided, [](const Vec3& w) { return w.z > 0.0f ? w.z / M_PI : 0.0; }, on_quad,
        "one-sided area light");
    const AreaLight two_sided(mesh.make_sampler(Transform()), Spectrum(1.0f), true);
    expect_emission_directions(
        two_sided, [](const Vec3& w) { return 0.5 * std::abs(w.z) / M_PI; }, on_quad,
        "two-sided area light");
}

// An area light's photons start uniformly over its surface: counts in a 4 x 4 grid of
// equal cells of the quad, chi-square against equal expectations.
TEST(LightEmission, AreaLightOriginsAreUniformOverTheSurface) {
    const TriangleMesh mesh(
        "quad", make_quad_mesh(Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(-1, 1, 1)));
    const AreaLight light(mesh.make_sampler(Transform()), Spectrum(1.0f), false);
    Rng rng(43);
    constexpr int kDraws = 160000;
    std::array<double, 16> counts{};
    for (int i = 0; i < kDraws; ++i) {
        const Vec2 u1(rng.next_float(), rng.next_float()), u2(rng.next_float(), rng.next_float());
        const auto emission = light.sample_le(u1, u2, rng.next_float());
        ASSERT_TRUE(emission.has_value());
        const Vec3 o = emission->ray.origin;
        const int cx = std::clamp(static_cast<int>((o.x + 1.0f) * 2.0f), 0, 3);
        const int cy = std::clamp(static_cast<int>(o.y * 4.0f), 0, 3);
        counts[cy * 4 + cx] += 1.0;
    }
    double chi2 = 0.0;
    for (double c : counts) chi2 += (c - kDraws / 16.0) * (c - kDraws / 16.0) / (kDraws / 16.0);
    EXPECT_GT(test::chi_square_upper_tail(chi2, 15), 0.01) << "chi2 = " << chi2;
}
