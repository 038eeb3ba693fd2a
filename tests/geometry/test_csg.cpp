// CSG: the interval algebra (touching, nested, infinite and empty intervals), ray-quadric
// roots of the nine named forms against closed forms (rays from inside, tangent rays, rays
// along an asymptote) with gradient normals, Monte Carlo volumes of CSG solids against
// closed forms, agreement of the ray intervals with point membership, and bounding-box
// shortcuts that change the work done but never the answer.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/geometry/csg/csg_node.h>
#include <glint/geometry/csg/interval.h>
#include <glint/geometry/csg/primitives.h>
#include <glint/math/warp.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace glint;

namespace {

using SolidPtr = std::shared_ptr<const Solid>;
using DVec3 = glm::dvec3;

constexpr float kInf = kInfinity;
constexpr double kPiD = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------
// Interval algebra. Every input interval is seen by a ray along +x, so its entry normal is
// -x and its exit normal +x. A correct algebra keeps that true of its results: where a
// subtracted solid's surface becomes an entry or exit of the result, its normal must flip.

const Vec3 kEntryNormal(-1.0f, 0.0f, 0.0f);
const Vec3 kExitNormal(1.0f, 0.0f, 0.0f);

Interval span(float t0, float t1, int leaf) {
    return {{t0, kEntryNormal, leaf}, {t1, kExitNormal, leaf}};
}

std::string show(const IntervalList& list) {
    std::string text = "{";
    for (const Interval& s : list) {
        text += fmt::format(" [{} (leaf {}, n.x {}), {} (leaf {}, n.x {})]", s.enter.t,
                            s.enter.leaf, s.enter.normal.x, s.exit.t, s.exit.leaf, s.exit.normal.x);
    }
    return text + " }";
}

// An expected interval: its two ends and the leaves they belong to.
struct Span {
    float t0;
    int leaf0;
    float t1;
    int leaf1;
};

void expect_list(const IntervalList& got, const std::vector<Span>& want) {
    ASSERT_EQ(got.size(), want.size()) << show(got);
    for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(got[i].enter.t, want[i].t0) << show(got);
        EXPECT_EQ(got[i].enter.leaf, want[i].leaf0) << show(got);
        EXPECT_TRUE(got[i].enter.normal == kEntryNormal) << "entry " << i << ": " << show(got);
        EXPECT_EQ(got[i].exit.t, want[i].t1) << show(got);
        EXPECT_EQ(got[i].exit.leaf, want[i].leaf1) << show(got);
        EXPECT_TRUE(got[i].exit.normal == kExitNormal) << "exit " << i << ": " << show(got);
    }
}

IntervalList unite(const IntervalList& a, const IntervalList& b) {
    IntervalList out;
    interval_union(a, b, out);
    return out;
}
IntervalList intersect(const IntervalList& a, const IntervalList& b) {
    IntervalList out;
    interval_intersection(a, b, out);
    return out;
}
IntervalList subtract(const IntervalList& a, const IntervalList& b) {
    IntervalList out;
    interval_difference(a, b, out);
    return out;
}

}  // namespace

TEST(IntervalAlgebra, UnionMergesTouchingAndOverlappingIntervals) {
    expect_list(unite({span(0, 1, 0)}, {span(1, 2, 1)}), {{0, 0, 2, 1}});
    expect_list(unite({span(1, 2, 1)}, {span(0, 1, 0)}), {{0, 0, 2, 1}});
    expect_list(unite({span(0, 2, 0)}, {span(1, 3, 1)}), {{0, 0, 3, 1}});
    expect_list(unite({span(0, 5, 0)}, {span(1, 2, 1)}), {{0, 0, 5, 0}});
    expect_list(unite({span(3, 4, 0)}, {span(0, 1, 1)}), {{0, 1, 1, 1}, {3, 0, 4, 0}});
    // A bridge joins two intervals into one.
    expect_list(unite({span(0, 1, 0), span(2, 3, 0)}, {span(1, 2, 1)}), {{0, 0, 3, 0}});
    expect_list(unite({span(0, 1, 0), span(4, 5, 0)}, {span(2, 3, 1), span(4.5f, 6, 1)}),
                {{0, 0, 1, 0}, {2, 1, 3, 1}, {4, 0, 6, 1}});
}

TEST(IntervalAlgebra, IntersectionOfTouchingIntervalsIsEmpty) {
    expect_list(intersect({span(0, 1, 0)}, {span(1, 2, 1)}), {});
    expect_list(intersect({span(0, 2, 0)}, {span(1, 3, 1)}), {{1, 1, 2, 0}});
    expect_list(intersect({span(0, 5, 0)}, {span(1, 2, 1)}), {{1, 1, 2, 1}});
    expect_list(intersect({span(0, 1, 0)}, {span(2, 3, 1)}), {});
    expect_list(intersect({span(0, 2, 0), span(3, 5, 0)}, {span(1, 4, 1)}),
                {{1, 1, 2, 0}, {3, 0, 4, 1}});
}

TEST(IntervalAlgebra, DifferenceFlipsTheSubtractedSurfaces) {
    // The cut face at t = 1 is the subtrahend's entry (normal -x), now the result's exit.
    expect_list(subtract({span(0, 2, 0)}, {span(1, 2, 1)}), {{0, 0, 1, 1}});
    expect_list(subtract({span(0, 2, 0)}, {span(0, 1, 1)}), {{1, 1, 2, 0}});
    expect_list(subtract({span(0, 2, 0)}, {span(0, 2, 1)}), {});
    expect_list(subtract({span(0, 2, 0)}, {span(-1, 3, 1)}), {});
    expect_list(subtract({span(0, 3, 0)}, {span(1, 2, 1)}), {{0, 0, 1, 1}, {2, 1, 3, 0}});
    // Touching removes nothing.
    expect_list(subtract({span(0, 1, 0)}, {span(1, 2, 1)}), {{0, 0, 1, 0}});
    expect_list(subtract({span(1, 2, 0)}, {span(0, 1, 1)}), {{1, 0, 2, 0}});
    // One subtrahend across two intervals.
    expect_list(subtract({span(0, 2, 0), span(3, 5, 0)}, {span(1, 4, 1)}),
                {{0, 0, 1, 1}, {4, 1, 5, 0}});
}

TEST(IntervalAlgebra, NestedDifferencesGiveThreeSpans) {
    const std::vector<Span> expected = {{0, 0, 2, 1}, {3, 1, 5, 2}, {6, 2, 10, 0}};
    // ([0, 10] - [2, 3]) - [5, 6], one operation at a time ...
    const IntervalList once = subtract({span(0, 10, 0)}, {span(2, 3, 1)});
    expect_list(subtract(once, {span(5, 6, 2)}), expected);
    // ... and both at once.
    const IntervalList both = subtract({span(0, 10, 0)}, {span(2, 3, 1), span(5, 6, 2)});
    expect_list(both, expected);
    // The cut faces are the subtrahends' surfaces turned around.
    ASSERT_EQ(both.size(), 3u);
    EXPECT_TRUE(both[0].exit.normal == -span(2, 3, 1).enter.normal);
    EXPECT_TRUE(both[1].enter.normal == -span(2, 3, 1).exit.normal);

    // A hole inside a hole is subtracted from nothing; added back, it is a third span.
    const IntervalList hollow = subtract({span(0, 10, 0)}, {span(2, 8, 1)});
    expect_list(subtract(hollow, {span(4, 6, 2)}), {{0, 0, 2, 1}, {8, 1, 10, 0}});
    expect_list(unite(hollow, {span(4, 6, 2)}), {{0, 0, 2, 1}, {4, 2, 6, 2}, {8, 1, 10, 0}});
    expect_list(intersect(hollow, {span(1, 9, 2)}), {{1, 2, 2, 1}, {8, 1, 9, 2}});
}

TEST(IntervalAlgebra, InfiniteEnds) {
    expect_list(unite({span(-kInf, 1, 0)}, {span(0, kInf, 1)}), {{-kInf, 0, kInf, 1}});
    expect_list(intersect({span(-kInf, kInf, 0)}, {span(1, 2, 1)}), {{1, 1, 2, 1}});
    expect_list(subtract({span(0, 10, 0)}, {span(-kInf, 3, 1)}), {{3, 1, 10, 0}});
    expect_list(subtract({span(-kInf, kInf, 0)}, {span(1, 2, 1)}),
                {{-kInf, 0, 1, 1}, {2, 1, kInf, 0}});
    // Two sheets of a hyperboloid inside a slab.
    expect_list(intersect({span(-kInf, -1, 0), span(1, kInf, 0)}, {span(-3, 3, 1)}),
                {{-3, 1, -1, 0}, {1, 0, 3, 1}});
    expect_list(subtract({span(-kInf, 0, 0)}, {span(-kInf, 0, 1)}), {});
    expect_list(subtract({span(-kInf, kInf, 0)}, {span(-kInf, kInf, 1)}), {});
}

TEST(IntervalAlgebra, EmptyInputs) {
    const IntervalList empty, one = {span(0, 1, 0)};
    expect_list(unite(empty, empty), {});
    expect_list(unite(empty, one), {{0, 0, 1, 0}});
    expect_list(unite(one, empty), {{0, 0, 1, 0}});
    expect_list(intersect(empty, one), {});
    expect_list(intersect(one, empty), {});
    expect_list(subtract(one, empty), {{0, 0, 1, 0}});
    expect_list(subtract(empty, one), {});
}

TEST(IntervalAlgebra, FirstCrossingAfter) {
    const IntervalList list = {span(-kInf, 1, 0), span(2, 3, 1)};
    ASSERT_NE(first_crossing_after(list, 0.0f), nullptr);
    EXPECT_EQ(first_crossing_after(list, 0.0f)->t, 1.0f);
    EXPECT_EQ(first_crossing_after(list, 1.5f)->t, 2.0f);
    EXPECT_EQ(first_crossing_after(list, 2.0f)->t, 3.0f);
    EXPECT_EQ(first_crossing_after(list, 3.0f), nullptr);
    EXPECT_EQ(first_crossing_after({}, 0.0f), nullptr);
}

// ---------------------------------------------------------------------------------------
// Quadrics against closed forms.

namespace {

IntervalList spans_of(const Solid& solid, const Vec3& origin, const Vec3& direction) {
    IntervalScratch scratch;
    IntervalList out;
    solid.intervals(Ray{origin, direction}, out, scratch);
    return out;
}

// The gradient of x^T Q x by central differences (exact for a quadratic, up to rounding).
DVec3 numerical_gradient(const QuadricSolid& q, const DVec3& p) {
    const double h = 1e-3;
    DVec3 g;
    for (int axis = 0; axis < 3; ++axis) {
        DVec3 step(0.0);
        step[axis] = h;
        g[axis] = (q.value(p + step) - q.value(p - step)) / (2.0 * h);
    }
    return g;
}

// A finite crossing lies on the surface, and its normal is the outward gradient: against
// the ray where it enters, along it where it leaves.
void expect_on_surface(const QuadricSolid& q, const Ray& ray, const Crossing& c, bool entering,
                       const std::string& what) {
    SCOPED_TRACE(what);
    const DVec3 p = DVec3(ray.origin) + static_cast<double>(c.t) * DVec3(ray.direction);
    const DVec3 gradient = numerical_gradient(q, p);
    // |f| is below the change of f over the rounding of t.
    const double tolerance =
        1e-5 * (1.0 + std::abs(c.t)) * glm::length(gradient) * glm::length(DVec3(ray.direction));
    EXPECT_LE(std::abs(q.value(p)), tolerance + 1e-9) << "t = " << c.t;
    ASSERT_TRUE(is_finite(c.normal));
    ASSERT_GT(glm::length(c.normal), 0.0f);
    const DVec3 n = glm::normalize(DVec3(c.normal));
    EXPECT_GT(glm::dot(n, glm::normalize(gradient)), 1.0 - 1e-6) << "t = " << c.t;
    const double facing = glm::dot(n, DVec3(ray.direction));
    if (entering)
        EXPECT_LT(facing, 0.0) << "t = " << c.t;
    else
        EXPECT_GT(facing, 0.0) << "t = " << c.t;
}

struct QuadricCase {
    const char* what;
    glm::dmat4 q;
    Vec3 origin;
    Vec3 direction;
    std::vector<std::pair<double, double>> expected;  // entry and exit t, +-inf allowed
};

void check_case(const QuadricCase& c) {
    SCOPED_TRACE(c.what);
    const QuadricSolid solid(c.q, c.what, 7);
    const Ray ray{c.origin, c.direction};
    const IntervalList got = spans_of(solid, c.origin, c.direction);
    ASSERT_EQ(got.size(), c.expected.size()) << show(got);
    for (size_t i = 0; i < got.size(); ++i) {
        const Crossing* ends[2] = {&got[i].enter, &got[i].exit};
        const double want[2] = {c.expected[i].first, c.expected[i].second};
        for (int e = 0; e < 2; ++e) {
            EXPECT_EQ(ends[e]->leaf, 7);
            ASSERT_FALSE(std::isnan(ends[e]->t)) << show(got);
            if (std::isinf(want[e])) {
                EXPECT_EQ(ends[e]->t, want[e]) << show(got);
                continue;
            }
            EXPECT_NEAR(ends[e]->t, want[e], 1e-5 * (1.0 + std::abs(want[e]))) << show(got);
            expect_on_surface(solid, ray, *ends[e], e == 0,
                              fmt::format("interval {} end {}", i, e));
        }
    }
}

}  // namespace

// One or more rays per form, roots worked out by hand from the form's equation (axis y,
// inside where x^T Q x <= 0). The comments give the equation along the ray.
TEST(Quadric, NineFormsMatchClosedForms) {
    namespace qf = quadric_forms;
    const double inf = std::numeric_limits<double>::infinity();
    const double r3 = std::sqrt(3.0), r2 = std::sqrt(2.0);
    const QuadricCase cases[] = {
        // x^2/4 + y^2 + z^2/9 <= 1 at y = 0.5: x^2 <= 3.
        {"ellipsoid", qf::ellipsoid(2, 1, 3), {-5, 0.5f, 0}, {1, 0, 0}, {{5 - r3, 5 + r3}}},
        // From the centre along z: z^2 <= 9; direction of length 2 halves t.
        {"ellipsoid from inside", qf::ellipsoid(2, 1, 3), {0, 0, 0}, {0, 0, 2}, {{-1.5, 1.5}}},
        // x^2 - y^2/4 + z^2 <= 1 at y = 2: x^2 <= 2.
        {"hyperboloid_one_sheet",
         qf::hyperboloid_one_sheet(1, 2, 1),
         {0, 2, 3},
         {0, 0, -1},
         {{3 - r2, 3 + r2}}},
        // Along the axis: -y^2/4 <= 1 everywhere.
        {"hyperboloid_one_sheet along its axis",
         qf::hyperboloid_one_sheet(1, 2, 1),
         {0, 0, 0},
         {0, 1, 0},
         {{-inf, inf}}},
        // Along the asymptote (1, 2, 0) from (2, 0, 0): (2 + t)^2 - t^2 - 1 = 3 + 4t <= 0.
        {"hyperboloid_one_sheet along an asymptote",
         qf::hyperboloid_one_sheet(1, 2, 1),
         {2, 0, 0},
         {1, 2, 0},
         {{-inf, -0.75}}},
        // x^2 - y^2 + z^2 <= -1: along the axis from the origin, |t| >= 1.
        {"hyperboloid_two_sheets along its axis",
         qf::hyperboloid_two_sheets(1, 1, 1),
         {0, 0, 0},
         {0, 1, 0},
         {{-inf, -1}, {1, inf}}},
        // From inside the upper sheet at y = 2: (2 + t)^2 >= 1, t <= -3 or t >= -1.
        {"hyperboloid_two_sheets from inside",
         qf::hyperboloid_two_sheets(1, 1, 1),
         {0, 2, 0},
         {0, 1, 0},
         {{-inf, -3}, {-1, inf}}},
        // Across the upper sheet at y = 2: x^2 <= 3.
        {"hyperboloid_two_sheets across",
         qf::hyperboloid_two_sheets(1, 1, 1),
         {4, 2, 0},
         {-1, 0, 0},
         {{4 - r3, 4 + r3}}},
        // x^2 - y^2/4 + z^2 <= 0 at y = 2: x^2 <= 1.
        {"elliptic_cone", qf::elliptic_cone(1, 2, 1), {-3, 2, 0}, {1, 0, 0}, {{2, 4}}},
        // Parallel to the axis at x = 0.5: y^2 >= 1, both nappes.
        {"elliptic_cone parallel to its axis",
         qf::elliptic_cone(1, 2, 1),
         {0.5f, 0, 0},
         {0, 1, 0},
         {{-inf, -1}, {1, inf}}},
        // Along a generator from (0, 1, 0): t^2 - (1 + 2t)^2/4 = -1/4 - t <= 0.
        {"elliptic_cone along a generator",
         qf::elliptic_cone(1, 2, 1),
         {0, 1, 0},
         {1, 2, 0},
         {{-0.25, inf}}},
        // Beside a generator, never inside: t^2 - t^2 + 1/4 > 0.
        {"elliptic_cone beside a generator",
         qf::elliptic_cone(1, 2, 1),
         {0, 0, 0.5f},
         {1, 2, 0},
         {}},
        // x^2 + z^2/4 <= y at y = 4: x^2 <= 4.
        {"elliptic_paraboloid", qf::elliptic_paraboloid(1, 2), {-3, 4, 0}, {1, 0, 0}, {{1, 5}}},
        // Up the axis direction at x = 1: 1 <= y.
        {"elliptic_paraboloid parallel to its axis",
         qf::elliptic_paraboloid(1, 2),
         {1, 0, 0},
         {0, 1, 0},
         {{1, inf}}},
        // Down from (0, 5, 0): 0 <= 5 - t.
        {"elliptic_paraboloid down its axis",
         qf::elliptic_paraboloid(1, 2),
         {0, 5, 0},
         {0, -1, 0},
         {{-inf, 5}}},
        // x^2 - z^2 <= y: at y = 1 along x, x^2 <= 1 ...
        {"hyperbolic_paraboloid along x",
         qf::hyperbolic_paraboloid(1, 1),
         {0, 1, 0},
         {1, 0, 0},
         {{-1, 1}}},
        // ... at y = -1 along z, z^2 >= 1 ...
        {"hyperbolic_paraboloid along z",
         qf::hyperbolic_paraboloid(1, 1),
         {0, -1, 0},
         {0, 0, 1},
         {{-inf, -1}, {1, inf}}},
        // ... up the y direction at x = 1 from y = -5, 1 <= t - 5 ...
        {"hyperbolic_paraboloid parallel to its axis",
         qf::hyperbolic_paraboloid(1, 1),
         {1, -5, 0},
         {0, 1, 0},
         {{6, inf}}},
        // ... and along the ruling (1, 0, 1) from (0, 0, 1): t^2 - (1 + t)^2 <= 0, t >= -1/2.
        {"hyperbolic_paraboloid along a ruling",
         qf::hyperbolic_paraboloid(1, 1),
         {0, 0, 1},
         {1, 0, 1},
         {{-0.5, inf}}},
        // x^2/4 + z^2 <= 1 at z = 0.5: x^2 <= 3.
        {"elliptic_cylinder",
         qf::elliptic_cylinder(2, 1),
         {5, 7, 0.5f},
         {-1, 0, 0},
         {{5 - r3, 5 + r3}}},
        {"elliptic_cylinder along its axis inside",
         qf::elliptic_cylinder(2, 1),
         {1, 0, 0},
         {0, 1, 0},
         {{-inf, inf}}},
        {"elliptic_cylinder along its axis outside",
         qf::elliptic_cylinder(2, 1),
         {3, 0, 0},
         {0, 1, 0},
         {}},
        // x^2 - z^2 <= 1: at z = 0 along x, |x| <= 1 ...
        {"hyperbolic_cylinder across",
         qf::hyperbolic_cylinder(1, 1),
         {-2, 0, 0},
         {1, 0, 0},
         {{1, 3}}},
        // ... along z at x = 0, everywhere ...
        {"hyperbolic_cylinder between the sheets",
         qf::hyperbolic_cylinder(1, 1),
         {0, 0, 0},
         {0, 0, 1},
         {{-inf, inf}}},
        // ... along z at x = 2, z^2 >= 3 ...
        {"hyperbolic_cylinder through both sheets",
         qf::hyperbolic_cylinder(1, 1),
         {2, 0, 0},
         {0, 0, 1},
         {{-inf, -r3}, {r3, inf}}},
        // ... and along the asymptote (1, 0, 1) from (1, 0, 0): 2t + 1 <= 1.
        {"hyperbolic_cylinder along an asymptote",
         qf::hyperbolic_cylinder(1, 1),
         {1, 0, 0},
         {1, 0, 1},
         {{-inf, 0}}},
        // x^2/4 <= y at y = 4: x^2 <= 16.
        {"parabolic_cylinder", qf::parabolic_cylinder(2), {-5, 4, 1}, {1, 0, 0}, {{1, 9}}},
        // Up the y direction at x = 2: 1 <= y.
        {"parabolic_cylinder parallel to its axis",
         qf::parabolic_cylinder(2),
         {2, 0, 0},
         {0, 1, 0},
         {{1, inf}}},
        // Along the ruling z at y = 2, x = 0: inside everywhere.
        {"parabolic_cylinder along a ruling",
         qf::parabolic_cylinder(2),
         {0, 2, 0},
         {0, 0, 1},
         {{-inf, inf}}},
    };
    for (const QuadricCase& c : cases) check_case(c);
}

// A general quadric matrix is the same surface as a named form moved by a transform:
// Q' = M^-T Q M^-1 equals the form seen through TransformedSolid.
TEST(Quadric, TransformedMatrixMatchesTransformedSolid) {
    const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), DVec3(0.5, -1.0, 2.0)), 0.7,
                                     glm::normalize(DVec3(1.0, 2.0, -0.5)));
    const glm::dmat4 form = quadric_forms::hyperboloid_one_sheet(0.8, 1.5, 1.2);
    const glm::dmat4 inverse = glm::inverse(m);
    const QuadricSolid moved(glm::transpose(inverse) * form * inverse, "quadric", 0);
    const TransformedSolid placed(std::make_shared<QuadricSolid>(form, "form", 0),
                                  Transform(Mat4(m)));
    Rng rng(5);
    int compared = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 o = Vec3(0.5f, -1.0f, 2.0f) + 3.0f * warp::square_to_uniform_sphere(Vec2(
                                                            rng.next_float(), rng.next_float()));
        const Vec3 d = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const IntervalList a = spans_of(moved, o, d), b = spans_of(placed, o, d);
        ASSERT_EQ(a.size(), b.size()) << show(a) << " vs " << show(b);
        for (size_t k = 0; k < a.size(); ++k) {
            for (const auto& [x, y] : {std::pair{a[k].enter, b[k].enter}, {a[k].exit, b[k].exit}}) {
                if (std::isinf(x.t)) {
                    EXPECT_EQ(x.t, y.t);
                    continue;
                }
                EXPECT_NEAR(x.t, y.t, 1e-3f * (1.0f + std::abs(x.t)));
                EXPECT_GT(glm::dot(glm::normalize(x.normal), glm::normalize(y.normal)), 0.9999f);
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 200);
}

// A ray tangent to an ellipsoid or a cylinder meets it in one double root or not at all;
// nudged inwards it gives two roots the closed form predicts, outwards none; never NaN.
// The ray starts far away, where a textbook quadratic formula loses the short chord.
TEST(Quadric, TangentAndNearlyTangentRays) {
    struct Tangent {
        const char* what;
        glm::dmat4 q;
        float half_width;  // semi-axis along the ray (x)
        float contact;     // the semi-axis across the ray: the tangent offset
        int offset_axis;   // y for the ellipsoid, z for the cylinder (its axis is y)
    };
    const Tangent tangents[] = {
        {"ellipsoid", quadric_forms::ellipsoid(2, 1, 3), 2.0f, 1.0f, 1},
        {"elliptic_cylinder", quadric_forms::elliptic_cylinder(2, 0.5), 2.0f, 0.5f, 2},
    };
    for (const Tangent& tangent : tangents) {
        SCOPED_TRACE(tangent.what);
        const QuadricSolid solid(tangent.q, tangent.what, 0);
        for (const float start : {-5.0f, -1000.0f}) {
            Vec3 o(start, 0.0f, 0.0f);
            o[tangent.offset_axis] = tangent.contact;
            const IntervalList touching = spans_of(solid, o, Vec3(1, 0, 0));
            for (const Interval& s : touching) {
                EXPECT_NEAR(s.enter.t, -start, 1e-3f * std::abs(start)) << show(touching);
                EXPECT_NEAR(s.exit.t, -start, 1e-3f * std::abs(start)) << show(touching);
            }
            EXPECT_LE(touching.size(), 1u) << show(touching);

            for (const double nudge : {1e-2, 1e-3, 1e-4}) {
                const double offset = tangent.contact * (1.0 - nudge);
                o[tangent.offset_axis] = static_cast<float>(offset);
                // The chord at that offset, from the float offset actually used.
                const double u = static_cast<double>(o[tangent.offset_axis]) / tangent.contact;
                const double half = tangent.half_width * std::sqrt(1.0 - u * u);
                const IntervalList inside = spans_of(solid, o, Vec3(1, 0, 0));
                ASSERT_EQ(inside.size(), 1u) << "nudge " << nudge << ": " << show(inside);
                const double t_tol = 2e-7 * std::abs(start) + 1e-6;
                EXPECT_NEAR(inside[0].enter.t, -start - half, t_tol) << nudge;
                EXPECT_NEAR(inside[0].exit.t, -start + half, t_tol) << nudge;
                EXPECT_TRUE(is_finite(inside[0].enter.normal) && is_finite(inside[0].exit.normal));
                EXPECT_LT(inside[0].enter.normal.x, 0.0f);
                EXPECT_GT(inside[0].exit.normal.x, 0.0f);

                o[tangent.offset_axis] = static_cast<float>(tangent.contact * (1.0 + nudge));
                EXPECT_TRUE(spans_of(solid, o, Vec3(1, 0, 0)).empty()) << nudge;
            }
        }
    }
}

// Close to an asymptotic direction the far root runs off to infinity while the near one
// must stay where the exactly asymptotic ray puts it (the a -> 0 limit of the quadratic).
TEST(Quadric, NearlyAsymptoticRaysApproachTheLimit) {
    const QuadricSolid cone(quadric_forms::elliptic_cone(1, 2, 1), "elliptic_cone", 0);
    const QuadricSolid paraboloid(quadric_forms::elliptic_paraboloid(1, 1), "paraboloid", 0);
    for (const float tilt : {1e-2f, 1e-4f, 1e-6f}) {
        SCOPED_TRACE(tilt);
        // Cone along a generator from (0, 1, 0): the entry tends to t = -1/4.
        for (const float sign : {-1.0f, 1.0f}) {
            const IntervalList spans = spans_of(cone, Vec3(0, 1, 0), Vec3(1, 2 + sign * tilt, 0));
            const Crossing* entry = first_crossing_after(spans, -1.0f);
            ASSERT_NE(entry, nullptr) << show(spans);
            EXPECT_NEAR(entry->t, -0.25f, 2.0f * tilt) << show(spans);
            EXPECT_LT(entry->normal.y * (2 + sign * tilt) + entry->normal.x, 0.0f);
            for (const Interval& s : spans)
                EXPECT_FALSE(std::isnan(s.enter.t) || std::isnan(s.exit.t));
        }
        // Paraboloid nearly along its axis at x = 1: the entry tends to y = 1.
        const IntervalList spans = spans_of(paraboloid, Vec3(1, 0, 0), Vec3(tilt, 1, 0));
        ASSERT_EQ(spans.size(), 1u) << show(spans);
        EXPECT_NEAR(spans[0].enter.t, 1.0f, 4.0f * tilt) << show(spans);
        EXPECT_GT(spans[0].exit.t, 0.5f / tilt) << show(spans);
    }
}

TEST(Quadric, EllipsoidBoundsFromAGeneralMatrix) {
    // An ellipsoid with semi-axes (a, b, c), rotated by R and moved to `center`: its extent
    // along world axis i is sqrt(sum_j (R_ij s_j)^2).
    const DVec3 semi(1.5, 0.5, 1.0), center(2.0, -1.0, 0.5);
    const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), center), 0.6,
                                     glm::normalize(DVec3(1.0, 1.0, 0.3)));
    const glm::dmat4 inverse = glm::inverse(m);
    const QuadricSolid solid(
        glm::transpose(inverse) * quadric_forms::ellipsoid(semi.x, semi.y, semi.z) * inverse,
        "quadric", 0);
    const Bounds3 b = solid.bounds();
    const glm::dmat3 r(m);
    for (int i = 0; i < 3; ++i) {
        double extent = 0.0;
        for (int j = 0; j < 3; ++j) extent += (r[j][i] * semi[j]) * (r[j][i] * semi[j]);
        extent = std::sqrt(extent);
        EXPECT_NEAR(b.min[i], center[i] - extent, 1e-5) << "axis " << i;
        EXPECT_NEAR(b.max[i], center[i] + extent, 1e-5) << "axis " << i;
    }
    // The other forms reach infinity.
    EXPECT_FALSE(QuadricSolid(quadric_forms::hyperboloid_two_sheets(1, 1, 1), "h", 0).is_bounded());
    EXPECT_FALSE(QuadricSolid(quadric_forms::elliptic_cylinder(1, 1), "c", 0).is_bounded());
}

// ---------------------------------------------------------------------------------------
// Solids for volume and consistency checks, each with its closed-form volume.

namespace {

SolidPtr sphere(const Vec3& c, float r, int part = 0) {
    return std::make_shared<SphereSolid>(c, r, part);
}
SolidPtr box(const Vec3& lo, const Vec3& hi, int part = 0) {
    return std::make_shared<BoxSolid>(lo, hi, part);
}
SolidPtr quadric(const glm::dmat4& q, int part = 0) {
    return std::make_shared<QuadricSolid>(q, "quadric", part);
}
SolidPtr node(CsgOperation op, std::vector<SolidPtr> children, bool shortcuts = true) {
    return std::make_shared<CsgNode>(op, std::move(children), shortcuts);
}
SolidPtr moved(SolidPtr child, const Transform& to_parent) {
    return std::make_shared<TransformedSolid>(std::move(child), to_parent);
}

// A closed cube [-h, h]^3 of twelve outward-wound triangles.
MeshData cube_mesh(float h) {
    MeshData mesh;
    for (int i = 0; i < 8; ++i)
        mesh.positions.push_back(Vec3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h));
    mesh.indices = {0, 2, 3, 0, 3, 1,   // -z
                    4, 5, 7, 4, 7, 6,   // +z
                    0, 1, 5, 0, 5, 4,   // -y
                    2, 6, 7, 2, 7, 3,   // +y
                    0, 4, 6, 0, 6, 2,   // -x
                    1, 3, 7, 1, 7, 5};  // +x
    return mesh;
}

struct NamedSolid {
    std::string name;
    SolidPtr solid;
    double volume;
};

// Lens of two spheres of radius r whose centres are d apart: pi (4r + d)(2r - d)^2 / 12.
double lens_volume(double r, double d) {
    return kPiD * (4.0 * r + d) * (2.0 * r - d) * (2.0 * r - d) / 12.0;
}
double ball_volume(double r) {
    return 4.0 / 3.0 * kPiD * r * r * r;
}

// A cylinder of radius 1 for |y| <= 1, the infinite quadric bounded by a box, minus a
// cone of radius 0.8 and height 1.5 standing on y = -0.75 (apex at y = 0.75), the double
// cone moved up by a transform and clipped by a box.
SolidPtr cylinder_minus_cone(bool shortcuts) {
    SolidPtr cylinder = node(
        CsgOperation::kIntersection,
        {quadric(quadric_forms::elliptic_cylinder(1, 1), 0), box(Vec3(-1), Vec3(1), 1)}, shortcuts);
    SolidPtr cone = node(CsgOperation::kIntersection,
                         {moved(quadric(quadric_forms::elliptic_cone(0.8, 1.5, 0.8), 2),
                                Transform::translate(Vec3(0, 0.75f, 0))),
                          box(Vec3(-1, -0.75f, -1), Vec3(1, 0.75f, 1), 3)},
                         shortcuts);
    return node(CsgOperation::kDifference, {cylinder, cone}, shortcuts);
}

std::vector<NamedSolid> volume_cases() {
    const float r = 1.0f, d = 1.0f;
    auto left = [&] { return sphere(Vec3(-0.5f * d, 0, 0), r, 0); };
    auto right = [&] { return sphere(Vec3(0.5f * d, 0, 0), r, 1); };
    // An ellipsoid from a general matrix: semi-axes (1.2, 0.6, 0.9), rotated and moved.
    const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), DVec3(0.3, 0.2, -0.4)), 0.9,
                                     glm::normalize(DVec3(0.2, 1.0, 0.7)));
    const glm::dmat4 inverse = glm::inverse(m);
    const glm::dmat4 ellipsoid =
        glm::transpose(inverse) * quadric_forms::ellipsoid(1.2, 0.6, 0.9) * inverse;
    return {
        {"lens", node(CsgOperation::kIntersection, {left(), right()}), lens_volume(r, d)},
        {"union of two spheres", node(CsgOperation::kUnion, {left(), right()}),
         2.0 * ball_volume(r) - lens_volume(r, d)},
        {"box minus a sphere inside",
         node(CsgOperation::kDifference, {box(Vec3(-1), Vec3(1)), sphere(Vec3(0), 0.8f, 1)}),
         8.0 - ball_volume(0.8)},
        {"box minus a sphere on its corner",
         node(CsgOperation::kDifference, {box(Vec3(-1), Vec3(1)), sphere(Vec3(1), 1.0f, 1)}),
         8.0 - ball_volume(1.0) / 8.0},
        {"cylinder minus a cone", cylinder_minus_cone(true),
         2.0 * kPiD - kPiD * 0.8 * 0.8 * 1.5 / 3.0},
        {"ellipsoid", quadric(ellipsoid), ball_volume(1.0) * 1.2 * 0.6 * 0.9},
        {"mesh cube minus a sphere",
         node(CsgOperation::kDifference,
              {std::make_shared<MeshSolid>(cube_mesh(1.0f), 0), sphere(Vec3(0), 0.9f, 1)}),
         8.0 - ball_volume(0.9)},
    };
}

double box_volume(const Bounds3& b) {
    const Vec3 e = b.extent();
    return static_cast<double>(e.x) * e.y * e.z;
}

}  // namespace

// Point membership sampled uniformly in the bounding box gives the volume; it must agree
// with the closed form within 1 %. The sampling error (about 0.2 % at worst here) is far
// below that, and the seed is fixed. A bounding box that cut off part of the solid would
// show up as missing volume.
TEST(CsgVolume, MonteCarloMatchesClosedForms) {
    const int n = 1'000'000;
    for (const NamedSolid& c : volume_cases()) {
        SCOPED_TRACE(c.name);
        ASSERT_TRUE(c.solid->is_bounded());
        const Bounds3 b = c.solid->bounds();
        Rng rng(17);
        int inside = 0;
        for (int i = 0; i < n; ++i) {
            const Vec3 u(rng.next_float(), rng.next_float(), rng.next_float());
            inside += c.solid->contains(b.min + u * b.extent());
        }
        const double volume = box_volume(b) * inside / n;
        EXPECT_NEAR(volume, c.volume, 0.01 * c.volume);
    }
}

// Along random lines through each solid, points inside a reported interval are inside the
// solid and points between intervals (or before the first, after the last) are outside.
// Points within `eps` of an interval end are not checked: rounding decides those.
TEST(CsgConsistency, IntervalsAgreeWithPointMembership) {
    const float eps = 1e-3f;
    for (const NamedSolid& c : volume_cases()) {
        SCOPED_TRACE(c.name);
        Bounds3 region = c.solid->bounds();
        const Vec3 margin = 0.5f * region.extent();
        region = {region.min - margin, region.max + margin};
        Rng rng(23);
        int wrong = 0, checked_inside = 0, checked_outside = 0;
        auto check = [&](const Ray& ray, float t0, float t1, bool expected) {
            if (t1 - t0 <= 2.0f * eps) return;
            for (int k = 0; k < 6; ++k) {
                const float t = t0 + eps + (t1 - t0 - 2.0f * eps) * rng.next_float();
                const Vec3 p = ray.at(t);
                if (c.solid->contains(p) != expected && wrong++ < 5) {
                    ADD_FAILURE() << fmt::format(
                        "point ({}, {}, {}) at t = {} on the ray from ({}, {}, {}) along ({}, {}, "
                        "{}) should be {}",
                        p.x, p.y, p.z, t, ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x,
                        ray.direction.y, ray.direction.z, expected ? "inside" : "outside");
                }
                (expected ? checked_inside : checked_outside)++;
            }
        };
        for (int i = 0; i < 10000; ++i) {
            const Vec3 u(rng.next_float(), rng.next_float(), rng.next_float());
            Ray ray{region.min + u * region.extent(),
                    warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()))};
            float t_lo, t_hi;
            ASSERT_TRUE(ray_box_range(ray, region, t_lo, t_hi));
            IntervalScratch scratch;
            IntervalList spans;
            c.solid->intervals(ray, spans, scratch);
            // Sorted and disjoint; checked over the part of the line inside `region`.
            float previous_exit = -kInf;
            for (const Interval& s : spans) {
                ASSERT_LE(s.enter.t, s.exit.t) << show(spans);
                ASSERT_GE(s.enter.t, previous_exit) << show(spans);
                check(ray, std::max(previous_exit, t_lo), std::min(s.enter.t, t_hi), false);
                check(ray, std::max(s.enter.t, t_lo), std::min(s.exit.t, t_hi), true);
                previous_exit = s.exit.t;
            }
            check(ray, std::max(previous_exit, t_lo), t_hi, false);
        }
        EXPECT_EQ(wrong, 0);
        EXPECT_GT(checked_inside, 5000);
        EXPECT_GT(checked_outside, 5000);
    }
}

// ---------------------------------------------------------------------------------------
// Shortcuts and nodes.

namespace {

// A tree like a CSG scene: intersections of infinite quadrics bounded by a sphere or box,
// differences, transforms, a union of it all; `shortcuts` on or off throughout.
SolidPtr mixed_tree(bool shortcuts) {
    namespace qf = quadric_forms;
    std::vector<SolidPtr> objects;
    int part = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Transform place = Transform::translate(Vec3(3.0f * i, 0.0f, 3.0f * j)) *
                                    Transform::rotate(20.0f * (i + j), Vec3(1, 0, 0));
            SolidPtr object;
            switch ((i + j) % 3) {
                case 0:  // a hyperboloid waist inside a sphere, with a cylinder drilled out
                    object = node(CsgOperation::kDifference,
                                  {node(CsgOperation::kIntersection,
                                        {quadric(qf::hyperboloid_one_sheet(0.5, 1, 0.5), part++),
                                         sphere(Vec3(0), 1.2f, part++)},
                                        shortcuts),
                                   quadric(qf::elliptic_cylinder(0.2, 0.2), part++)},
                                  shortcuts);
                    break;
                case 1:  // a paraboloid cup cut by a cone, in a box
                    object = node(CsgOperation::kIntersection,
                                  {quadric(qf::elliptic_paraboloid(0.5, 0.5), part++),
                                   moved(quadric(qf::elliptic_cone(1, 1, 1), part++),
                                         Transform::translate(Vec3(0, 2, 0))),
                                   box(Vec3(-1, -1, -1), Vec3(1, 1, 1), part++)},
                                  shortcuts);
                    break;
                default:  // a box minus two cylinders crossing, minus a sphere
                    object = node(CsgOperation::kDifference,
                                  {box(Vec3(-1), Vec3(1), part++),
                                   node(CsgOperation::kIntersection,
                                        {quadric(qf::elliptic_cylinder(0.5, 0.5), part++),
                                         box(Vec3(-2, -1.5f, -2), Vec3(2, 1.5f, 2), part++)},
                                        shortcuts),
                                   moved(quadric(qf::hyperbolic_cylinder(0.3, 0.6), part++),
                                         Transform::rotate(90.0f, Vec3(1, 0, 0))),
                                   sphere(Vec3(1), 0.6f, part++)},
                                  shortcuts);
                    break;
            }
            objects.push_back(moved(object, place));
        }
    }
    return node(CsgOperation::kUnion, std::move(objects), shortcuts);
}

}  // namespace

// The bounding boxes only decide what is evaluated, never the answer: the same tree with
// and without shortcuts reports the same crossings for every ray.
TEST(CsgNode, ShortcutsDoNotChangeIntervals) {
    const std::pair<SolidPtr, SolidPtr> trees[] = {
        {mixed_tree(true), mixed_tree(false)},
        {cylinder_minus_cone(true), cylinder_minus_cone(false)},
    };
    Bounds3 region;
    region.expand(Vec3(-2.0f, -2.0f, -2.0f));
    region.expand(Vec3(11.0f, 2.0f, 11.0f));
    Rng rng(31);
    int non_empty = 0;
    IntervalScratch scratch;
    IntervalList a, b;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 u(rng.next_float(), rng.next_float(), rng.next_float());
        const Ray ray{region.min + u * region.extent(),
                      warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()))};
        for (const auto& [on, off] : trees) {
            on->intervals(ray, a, scratch);
            off->intervals(ray, b, scratch);
            ASSERT_EQ(a.size(), b.size()) << "ray " << i << ": " << show(a) << " vs " << show(b);
            for (size_t k = 0; k < a.size(); ++k) {
                for (const auto& [x, y] :
                     {std::pair{a[k].enter, b[k].enter}, {a[k].exit, b[k].exit}}) {
                    ASSERT_EQ(x.t, y.t) << "ray " << i;
                    ASSERT_EQ(x.leaf, y.leaf) << "ray " << i;
                    ASSERT_TRUE(x.normal == y.normal) << "ray " << i;
                }
            }
            non_empty += !a.empty();
        }
    }
    EXPECT_GT(non_empty, 2000);
}

TEST(CsgNode, BoundsAndErrors) {
    EXPECT_THROW(CsgNode(CsgOperation::kUnion, {}, true), Error);
    const SolidPtr infinite = quadric(quadric_forms::elliptic_cylinder(1, 1));
    const SolidPtr finite = box(Vec3(-2, 0, -2), Vec3(2, 3, 2));
    // An intersection is bounded by its finite children; a difference by its first child.
    const SolidPtr clipped = node(CsgOperation::kIntersection, {infinite, finite});
    ASSERT_TRUE(clipped->is_bounded());
    EXPECT_EQ(clipped->bounds().min, Vec3(-2, 0, -2));
    EXPECT_EQ(clipped->bounds().max, Vec3(2, 3, 2));
    EXPECT_TRUE(node(CsgOperation::kDifference, {finite, infinite})->is_bounded());
    EXPECT_FALSE(node(CsgOperation::kDifference, {infinite, finite})->is_bounded());
    EXPECT_FALSE(node(CsgOperation::kUnion, {infinite, finite})->is_bounded());
    // A transform keeps a bounded solid bounded, and an unbounded one unbounded.
    EXPECT_TRUE(moved(clipped, Transform::rotate(30.0f, Vec3(1, 1, 0)))->is_bounded());
    EXPECT_FALSE(moved(infinite, Transform::translate(Vec3(1, 0, 0)))->is_bounded());
}

// A sphere squashed by a transform is the ellipsoid quadric: same t (the direction is not
// renormalised) and normals transformed to the ellipsoid's gradient.
TEST(CsgNode, TransformedSphereIsAnEllipsoid) {
    const TransformedSolid squashed(
        sphere(Vec3(0), 1.0f),
        Transform::translate(Vec3(1, 2, 3)) * Transform::scale(Vec3(2.0f, 0.5f, 1.5f)));
    const glm::dmat4 inverse = glm::inverse(glm::translate(glm::dmat4(1.0), DVec3(1, 2, 3)));
    const QuadricSolid ellipsoid(
        glm::transpose(inverse) * quadric_forms::ellipsoid(2.0, 0.5, 1.5) * inverse, "e", 0);
    Rng rng(41);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 o = Vec3(1, 2, 3) + 3.0f * warp::square_to_uniform_sphere(
                                                  Vec2(rng.next_float(), rng.next_float()));
        const Vec3 d = 0.5f * glm::normalize(Vec3(1, 2, 3) - o +
                                             warp::square_to_uniform_sphere(
                                                 Vec2(rng.next_float(), rng.next_float())));
        const IntervalList a = spans_of(squashed, o, d), b = spans_of(ellipsoid, o, d);
        ASSERT_EQ(a.size(), b.size()) << show(a) << " vs " << show(b);
        if (a.empty()) continue;
        ++hits;
        EXPECT_NEAR(a[0].enter.t, b[0].enter.t, 1e-4f * (1.0f + std::abs(b[0].enter.t)));
        EXPECT_NEAR(a[0].exit.t, b[0].exit.t, 1e-4f * (1.0f + std::abs(b[0].exit.t)));
        EXPECT_GT(glm::dot(glm::normalize(a[0].enter.normal), glm::normalize(b[0].enter.normal)),
                  0.9999f);
        EXPECT_GT(glm::dot(glm::normalize(a[0].exit.normal), glm::normalize(b[0].exit.normal)),
                  0.9999f);
    }
    EXPECT_GT(hits, 500);
}
