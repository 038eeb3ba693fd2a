// Shapes and the accelerator: sphere intervals against closed forms (also far away and
// scaled into ellipsoids), mesh validation, box winding, Embree queries with instancing, and
// rays leaving a surface that must not hit it again at any scene scale.
#include <glint/core/error.h>
#include <glint/core/interaction.h>
#include <glint/core/rng.h>
#include <glint/geometry/accel.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/sphere.h>
#include <glint/math/warp.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace glint;

namespace {

using DVec3 = glm::dvec3;

// Entry and exit parameters of the ray o + t d with the axis-aligned ellipsoid of centre
// `c` and semi-axes `r`, in double from the float inputs; false on a miss.
bool ellipsoid_interval(const Vec3& o, const Vec3& d, const DVec3& c, const DVec3& r, double& t0,
                        double& t1) {
    const DVec3 oo = (DVec3(o) - c) / r, dd = DVec3(d) / r;
    const double a = glm::dot(dd, dd), b = glm::dot(oo, dd), cc = glm::dot(oo, oo) - 1.0;
    const double disc = b * b - a * cc;
    if (disc < 0.0) return false;
    t0 = (-b - std::sqrt(disc)) / a;
    t1 = (-b + std::sqrt(disc)) / a;
    return true;
}

Vec3 random_direction(Rng& rng) {
    return warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
}

// A direction in the hemisphere around `n`, at least about 6 degrees from its plane.
Vec3 random_direction_around(Rng& rng, const Vec3& n) {
    const Vec3 local = warp::square_to_uniform_cone(Vec2(rng.next_float(), rng.next_float()), 0.1f);
    return glm::normalize(Frame::from_normal(n).to_world(local));
}

}  // namespace

TEST(Sphere, IntervalMatchesClosedForm) {
    const Vec3 center(1.0f, -2.0f, 0.5f);
    const float radius = 1.5f;
    const Sphere sphere(center, radius);
    Rng rng(1);
    int hits = 0, misses = 0;
    for (int i = 0; i < 2000; ++i) {
        // Origins outside and inside, directions of any length, aimed near the sphere.
        const float distance = i % 4 == 0 ? 0.7f * radius * rng.next_float()
                                          : radius * (1.2f + 5.0f * rng.next_float());
        const Vec3 o = center + distance * random_direction(rng);
        const Vec3 target = center + 2.0f * radius * rng.next_float() * random_direction(rng);
        const Vec3 d = (target - o) * (0.2f + 3.0f * rng.next_float());
        double e0 = 0.0, e1 = 0.0;
        const bool expected = ellipsoid_interval(o, d, DVec3(center), DVec3(radius), e0, e1);
        float t0, t1;
        const bool hit = sphere.intersect_interval(o, d, t0, t1);
        // Rays grazing the silhouette within rounding may go either way.
        const double grazing = std::abs(e1 - e0) * glm::length(d) / radius;
        if (expected && grazing < 1e-3) continue;
        ASSERT_EQ(hit, expected) << i;
        if (!hit) {
            ++misses;
            continue;
        }
        ++hits;
        const double scale = std::max(1.0, std::abs(e1));
        EXPECT_NEAR(t0, e0, 1e-5 * scale) << i;
        EXPECT_NEAR(t1, e1, 1e-5 * scale) << i;
        if (distance < radius) {
            EXPECT_LT(t0, 0.0f);  // inside: entered behind the origin
        }
    }
    EXPECT_GT(hits, 500);
    EXPECT_GT(misses, 200);
}

// A ray from 1e4 radii away: b^2 - ac cancels catastrophically in float there (an error of
// about 6 in a discriminant of at most 1), so hits and misses near the silhouette test the
// closest-approach form; t is then good to a few float steps at 1e4 (1e-3 each).
TEST(Sphere, FarAwayRayIsPrecise) {
    const Vec3 center(0.3f, -0.2f, 0.1f);
    const Sphere sphere(center, 1.0f);
    Rng rng(2);
    for (int i = 0; i < 500; ++i) {
        const Vec3 o = center + 1e4f * random_direction(rng);
        const Vec3 to_center = glm::normalize(center - o);
        const Vec3 side = glm::normalize(glm::cross(to_center, random_direction(rng)));
        const float offset = 1.1f * rng.next_float();  // closest approach, in radii
        const Vec3 d = glm::normalize(center + offset * side - o);
        double e0 = 0.0, e1 = 0.0;
        const bool expected = ellipsoid_interval(o, d, DVec3(center), DVec3(1.0), e0, e1);
        float t0, t1;
        const bool hit = sphere.intersect_interval(o, d, t0, t1);
        if (std::abs(offset - 1.0f) > 1e-3f) {
            ASSERT_EQ(hit, expected) << "offset " << offset;
        }
        if (!hit || !expected) continue;
        EXPECT_NEAR(t0, e0, 5e-3) << "offset " << offset;
        EXPECT_NEAR(t1, e1, 5e-3) << "offset " << offset;
    }
}

TEST(Sphere, ScaledSphereIsAnEllipsoid) {
    // A unit-radius sphere at (1, 2, 3), scaled by (2, 1, 0.5) in its parent: centre
    // (2, 2, 1.5) and semi-axes (2, 1, 0.5) times the radius.
    const float radius = 1.2f;
    const Sphere ellipsoid(Vec3(1, 2, 3), radius, Transform::scale(Vec3(2.0f, 1.0f, 0.5f)));
    const DVec3 c(2.0, 2.0, 1.5), axes = DVec3(2.0, 1.0, 0.5) * double(radius);
    Rng rng(3);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 o = Vec3(c) + 6.0f * random_direction(rng);
        const Vec3 target =
            Vec3(c) +
            Vec3(axes) * (2.0f * Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 1.0f);
        const Vec3 d = glm::normalize(target - o);
        double e0 = 0.0, e1 = 0.0;
        const bool expected = ellipsoid_interval(o, d, c, axes, e0, e1);
        float t0, t1;
        const bool hit = ellipsoid.intersect_interval(o, d, t0, t1);
        if (expected && (e1 - e0) < 1e-3) continue;  // grazing
        ASSERT_EQ(hit, expected) << i;
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(t0, e0, 1e-5 * std::abs(e1));
        EXPECT_NEAR(t1, e1, 1e-5 * std::abs(e1));
    }
    EXPECT_GT(hits, 300);
    const Bounds3 b = ellipsoid.bounds();
    EXPECT_NEAR(b.min.x, c.x - axes.x, 1e-5);
    EXPECT_NEAR(b.max.z, c.z + axes.z, 1e-5);
}

TEST(TriangleMesh, DropsDegenerateTriangles) {
    MeshData data;
    data.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(3, 0, 0)};
    data.indices = {0, 1, 2,   // good
                    0, 1, 3,   // collinear: zero area
                    2, 2, 4,   // repeated vertex
                    4, 3, 2};  // good
    const TriangleMesh mesh("m", data);
    EXPECT_EQ(mesh.triangle_count(), 2u);
    const std::vector<uint32_t> kept = {0, 1, 2, 4, 3, 2};
    EXPECT_EQ(mesh.data().indices, kept);
}

TEST(TriangleMesh, RejectsInvalidData) {
    MeshData good;
    good.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    good.indices = {0, 1, 2};
    EXPECT_NO_THROW(TriangleMesh("good", good));

    MeshData out_of_range = good;
    out_of_range.indices = {0, 1, 3};
    EXPECT_THROW(TriangleMesh("m", out_of_range), Error);

    const float nan = std::numeric_limits<float>::quiet_NaN();
    MeshData nan_vertex = good;
    nan_vertex.positions[1] = Vec3(1, nan, 0);
    EXPECT_THROW(TriangleMesh("m", nan_vertex), Error);

    MeshData infinite_vertex = good;
    infinite_vertex.positions[2] = Vec3(0, kInfinity, 0);
    EXPECT_THROW(TriangleMesh("m", infinite_vertex), Error);

    MeshData ragged = good;
    ragged.indices = {0, 1, 2, 0};
    EXPECT_THROW(TriangleMesh("m", ragged), Error);

    MeshData wrong_normals = good;
    wrong_normals.normals = {Vec3(0, 0, 1)};
    EXPECT_THROW(TriangleMesh("m", wrong_normals), Error);

    // A mesh with nothing left to emit from cannot be an area light.
    MeshData flat = good;
    flat.positions[2] = Vec3(2, 0, 0);
    const TriangleMesh empty("flat", flat);
    EXPECT_EQ(empty.triangle_count(), 0u);
    EXPECT_THROW(empty.make_sampler(Transform()), Error);
}

TEST(TriangleMesh, BoxNormalsPointOutward) {
    const Vec3 lo(-1.0f, 0.5f, 2.0f), hi(3.0f, 1.0f, 2.25f);
    const MeshData box = make_box_mesh(lo, hi);
    ASSERT_EQ(box.indices.size(), 36u);
    const Vec3 centre = 0.5f * (lo + hi);
    double area = 0.0;
    int faces_per_direction[6] = {0, 0, 0, 0, 0, 0};
    for (size_t i = 0; i < box.indices.size(); i += 3) {
        const Vec3 a = box.positions[box.indices[i]], b = box.positions[box.indices[i + 1]],
                   c = box.positions[box.indices[i + 2]];
        const Vec3 n = glm::cross(b - a, c - a);
        area += 0.5 * glm::length(n);
        // The face centre is where the triangle's plane meets its axis through the centre.
        const Vec3 unit = glm::normalize(n);
        const int axis = std::abs(unit.x) > 0.5f ? 0 : (std::abs(unit.y) > 0.5f ? 1 : 2);
        EXPECT_NEAR(std::abs(unit[axis]), 1.0f, 1e-6f) << "axis-aligned face";
        Vec3 face_centre = centre;
        face_centre[axis] = a[axis];
        EXPECT_GT(glm::dot(n, face_centre - centre), 0.0f) << "triangle " << i / 3;
        EXPECT_GT(glm::dot(n, (a + b + c) / 3.0f - centre), 0.0f) << "triangle " << i / 3;
        ++faces_per_direction[2 * axis + (unit[axis] > 0.0f ? 1 : 0)];
    }
    for (int count : faces_per_direction) EXPECT_EQ(count, 2);
    const Vec3 e = hi - lo;
    EXPECT_NEAR(area, 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x), 1e-5);

    // Mirroring keeps the winding outward.
    MeshData mirrored = box;
    transform_mesh(mirrored, Transform::scale(Vec3(-1.0f, 1.0f, 1.0f)));
    const Vec3 mirrored_centre(-centre.x, centre.y, centre.z);
    for (size_t i = 0; i < mirrored.indices.size(); i += 3) {
        const Vec3 a = mirrored.positions[mirrored.indices[i]];
        const Vec3 b = mirrored.positions[mirrored.indices[i + 1]];
        const Vec3 c = mirrored.positions[mirrored.indices[i + 2]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - mirrored_centre), 0.0f);
    }
}

TEST(Accel, MeshSphereAndInstance) {
    Accel accel;
    // A unit box at x in [2, 3], a sphere of radius 0.5 at the origin, and a prototype
    // holding a sphere of radius 0.25, placed at (0, 0, 10).
    const TriangleMesh box("box", make_box_mesh(Vec3(2, -0.5f, -0.5f), Vec3(3, 0.5f, 0.5f)));
    const Sphere sphere(Vec3(0.0f), 0.5f);
    const Sphere small(Vec3(0.0f), 0.25f);
    const unsigned box_id = accel.add_shape(-1, box);
    const unsigned sphere_id = accel.add_shape(-1, sphere);
    const int prototype = accel.add_prototype();
    const unsigned small_id = accel.add_shape(prototype, small);
    const unsigned instance_id =
        accel.add_instance(prototype, Transform::translate(Vec3(0, 0, 10)));
    accel.commit();

    struct Case {
        Ray ray;
        bool hit;
        float t;
        unsigned top;
        bool instanced;
    };
    const Case cases[] = {
        {{Vec3(-5, 0, 0), Vec3(1, 0, 0)}, true, 4.5f, sphere_id, false},    // sphere first
        {{Vec3(1, 0.1f, 0.2f), Vec3(1, 0, 0)}, true, 1.0f, box_id, false},  // box face
        {{Vec3(2.5f, 3, 0), Vec3(0, -2, 0)}, true, 1.25f, box_id, false},   // unnormalised
        {{Vec3(0, 0, 0), Vec3(0, 0, 1)}, true, 0.5f, sphere_id, false},     // from inside
        {{Vec3(0, 0, 2), Vec3(0, 0, 1)}, true, 7.75f, instance_id, false},  // the instance
        {{Vec3(0, 0.2f, 20), Vec3(0, 0, -1)}, true, 10.0f - std::sqrt(0.0225f), instance_id, true},
        {{Vec3(0, 2, 0), Vec3(1, 0, 0)}, false, 0.0f, 0, false},               // miss
        {{Vec3(-5, 0, 0), Vec3(-1, 0, 0)}, false, 0.0f, 0, false},             // behind
        {{Vec3(-5, 0, 0), Vec3(1, 0, 0), 0.0f, 4.0f}, false, 0.0f, 0, false},  // t_max short
        {{Vec3(0, 0, 0), Vec3(1, 0, 0), 1.0f, kInfinity}, true, 2.0f, box_id, false},  // t_min
    };
    for (size_t i = 0; i < std::size(cases); ++i) {
        const Case& c = cases[i];
        const auto hit = accel.intersect(c.ray);
        EXPECT_EQ(accel.occluded(c.ray), c.hit) << "case " << i;
        ASSERT_EQ(hit.has_value(), c.hit) << "case " << i;
        if (!hit) continue;
        EXPECT_NEAR(hit->t, c.t, 1e-5f * std::max(1.0f, c.t)) << "case " << i;
        EXPECT_EQ(hit->top_geometry, c.top) << "case " << i;
        if (c.top == instance_id) {
            EXPECT_TRUE(hit->instanced()) << "case " << i;
            EXPECT_EQ(hit->local_geometry, small_id) << "case " << i;
        } else {
            EXPECT_FALSE(hit->instanced()) << "case " << i;
        }
        // Occlusion stops at t_max: just short of the hit it sees nothing (the geometry
        // behind is further away in every case here).
        Ray shorter = c.ray;
        shorter.t_max = 0.999f * hit->t;
        EXPECT_FALSE(accel.occluded(shorter)) << "case " << i;
    }
    // The instance's hit, rebuilt in the prototype's space, lies on the small sphere.
    const Ray down{Vec3(0.1f, 0, 20), Vec3(0, 0, -1)};
    const auto hit = accel.intersect(down);
    ASSERT_TRUE(hit.has_value());
    const Ray local{down.origin - Vec3(0, 0, 10), down.direction};
    SurfaceInteraction si;
    small.fill_interaction(local, *hit, si);
    EXPECT_NEAR(glm::length(si.p), 0.25f, 1e-6f);
    EXPECT_GT(si.ng.z, 0.9f);
}

// Packets give each active lane what a lone ray gets, bit for bit (Embree's packet and
// single-ray kernels compute the same intersections), for triangles, user geometry and
// instances, with any set of lanes; inactive lanes' records stay as they were.
TEST(Accel, PacketsMatchSingleRaysLaneByLane) {
    Accel accel;
    const TriangleMesh box("box", make_box_mesh(Vec3(2, -0.5f, -0.5f), Vec3(3, 0.5f, 0.5f)));
    const Sphere sphere(Vec3(0.0f), 0.5f);
    const Sphere small(Vec3(0.0f), 0.25f);
    accel.add_shape(-1, box);
    accel.add_shape(-1, sphere);
    const int prototype = accel.add_prototype();
    accel.add_shape(prototype, small);
    accel.add_instance(prototype, Transform::translate(Vec3(1, 1, 0)));
    accel.commit();

    Rng rng(7);
    HitRecord untouched;
    untouched.t = -123.0f;
    int hits = 0, blocked = 0;
    for (int round = 0; round < 300; ++round) {
        // Random lanes, at least one; rays from around the shapes towards them.
        const uint32_t active = 1u + rng.next_u32() % 255u;
        PerLane<Ray> rays;
        PerLane<const Ray*> pointers{};
        PerLane<Vec3> origins, directions;
        for (int lane = 0; lane < kPacketWidth; ++lane) {
            const Vec3 origin = Vec3(-1.5f, -1.5f, -1.5f) +
                                5.0f * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
            const Vec3 target = Vec3(-0.5f, -0.5f, -0.5f) +
                                2.0f * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
            rays[lane] = Ray{origin, target - origin, 0.0f, kInfinity};
            pointers[lane] = &rays[lane];
            origins[lane] = origin;
            directions[lane] = target - origin;
        }
        PerLane<HitRecord> packet_hits;
        packet_hits.fill(untouched);
        const uint32_t hit_lanes =
            accel.intersect_packet(pointers, active, packet_hits, round % 2 == 0);
        const uint32_t blocked_lanes = accel.occluded_packet(origins, directions, PerLane<float>{},
                                                             1.0f, active, round % 2 == 1);
        for (int lane = 0; lane < kPacketWidth; ++lane) {
            const bool is_active = (active >> lane) & 1u;
            const HitRecord& got = packet_hits[lane];
            HitRecord expected;
            const bool expect_hit = is_active && accel.intersect(rays[lane], expected);
            ASSERT_EQ(((hit_lanes >> lane) & 1u) != 0, expect_hit) << "round " << round;
            const bool expect_blocked =
                is_active && accel.occluded(origins[lane], directions[lane], 0.0f, 1.0f);
            ASSERT_EQ(((blocked_lanes >> lane) & 1u) != 0, expect_blocked) << "round " << round;
            hits += expect_hit;
            blocked += expect_blocked;
            if (!expect_hit) {
                EXPECT_EQ(got.t, untouched.t) << "round " << round << ", lane " << lane;
                continue;
            }
            EXPECT_EQ(got.t, expected.t);
            EXPECT_EQ(got.top_geometry, expected.top_geometry);
            EXPECT_EQ(got.local_geometry, expected.local_geometry);
            EXPECT_EQ(got.primitive, expected.primitive);
            EXPECT_EQ(got.barycentric, expected.barycentric);
            EXPECT_EQ(got.normal, expected.normal);
        }
    }
    // The rays aim at the shapes, so most hit; some miss, and some segments are clear.
    EXPECT_GT(hits, 300);
    EXPECT_GT(blocked, 100);
}

// A ray Embree would refuse (NaN, infinite or huge origin or direction, NaN t) is answered
// as a miss, or as an unblocked segment, and counted, single or in a packet, instead of
// reaching Embree, whose assertions would abort the program.
TEST(Accel, RaysEmbreeRefusesAreDroppedAndCounted) {
    Accel accel;
    const Sphere sphere(Vec3(0.0f), 0.5f);
    accel.add_shape(-1, sphere);
    accel.commit();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Ray good{Vec3(-5, 0, 0), Vec3(1, 0, 0)};
    const Ray bad_rays[] = {
        {Vec3(-5, nan, 0), Vec3(1, 0, 0)},
        {Vec3(-5, 0, 0), Vec3(1, 0, nan)},
        {Vec3(-5, 0, 0), Vec3(kInfinity, 0, 0)},
        {Vec3(-1e19f, 0, 0), Vec3(1, 0, 0)},
        {Vec3(-5, 0, 0), Vec3(1, 0, 0), nan, kInfinity},
        {Vec3(-5, 0, 0), Vec3(1, 0, 0), 0.0f, nan},
    };
    EXPECT_TRUE(Accel::embree_accepts(good.origin, good.direction, good.t_min, good.t_max));
    uint64_t expected = 0;
    for (const Ray& bad : bad_rays) {
        EXPECT_FALSE(Accel::embree_accepts(bad.origin, bad.direction, bad.t_min, bad.t_max));
        HitRecord hit;
        EXPECT_FALSE(accel.intersect(bad, hit));
        EXPECT_FALSE(accel.occluded(bad));
        expected += 2;
        EXPECT_EQ(accel.dropped_rays(), expected);
    }
    EXPECT_TRUE(accel.intersect(good).has_value());
    EXPECT_TRUE(accel.occluded(good));
    EXPECT_EQ(accel.dropped_rays(), expected);

    // Packets: lanes 1 and 4 hold NaN rays; the others still hit.
    PerLane<Ray> rays;
    PerLane<const Ray*> pointers{};
    PerLane<Vec3> origins, directions;
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        rays[lane] = lane == 1 || lane == 4 ? bad_rays[lane % 2] : good;
        pointers[lane] = &rays[lane];
        origins[lane] = rays[lane].origin;
        directions[lane] = 10.0f * rays[lane].direction;
    }
    PerLane<HitRecord> hits;
    EXPECT_EQ(accel.intersect_packet(pointers, 0xffu, hits, true), 0xedu);
    EXPECT_EQ(accel.dropped_rays(), expected + 2);
    EXPECT_EQ(accel.occluded_packet(origins, directions, PerLane<float>{}, 1.0f, 0xffu, false),
              0xedu);
    EXPECT_EQ(accel.dropped_rays(), expected + 4);
    // A packet of bad lanes only, and a lone bad lane (which goes the single-ray way).
    EXPECT_EQ(accel.intersect_packet(pointers, 0x12u, hits, false), 0u);
    EXPECT_EQ(accel.occluded_packet(origins, directions, PerLane<float>{}, 1.0f, 0x02u, false), 0u);
    EXPECT_EQ(accel.dropped_rays(), expected + 7);
}

// Rays leaving a surface from the offset origin never hit it again, at scales 1e-3, 1 and
// 1e4 (each shape placed away from the origin in proportion): reflected rays must see
// nothing, rays entering a sphere must reach its far side.
class SelfIntersection : public ::testing::TestWithParam<float> {};

TEST_P(SelfIntersection, Triangle) {
    const float scale = GetParam();
    const Vec3 a = scale * Vec3(3.0f, -1.0f, 2.0f), b = scale * Vec3(5.0f, 0.5f, 1.0f),
               c = scale * Vec3(2.5f, 1.5f, 3.5f);
    MeshData data;
    data.positions = {a, b, c};
    data.indices = {0, 1, 2};
    const TriangleMesh triangle("triangle", data);
    Accel accel;
    accel.add_shape(-1, triangle);
    accel.commit();
    const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
    Rng rng(5);
    int found = 0, rehit = 0;
    for (int i = 0; i < 2000; ++i) {
        // Hit a random point of the triangle from either side, as a path would.
        const Vec2 bary =
            warp::square_to_uniform_triangle(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 target = (1.0f - bary.x - bary.y) * a + bary.x * b + bary.y * c;
        const Vec3 side = i % 2 ? n : -n;
        const Ray ray{target + 2.0f * scale * random_direction_around(rng, side), Vec3(0.0f)};
        const Ray aimed{ray.origin, target - ray.origin};
        const auto hit = accel.intersect(aimed);
        if (!hit) continue;  // the triangle's edge, missed within rounding
        ++found;
        SurfaceInteraction si;
        triangle.fill_interaction(aimed, *hit, si);
        // Leave towards the viewer's side (reflection) and through (transmission).
        for (const Vec3& leave : {side, -side}) {
            const Vec3 dir = random_direction_around(rng, leave);
            if (accel.intersect(spawn_ray(si, dir))) ++rehit;
            if (accel.occluded(spawn_ray(si, dir))) ++rehit;
        }
    }
    EXPECT_GT(found, 1900);
    EXPECT_EQ(rehit, 0) << "scale " << scale;
}

TEST_P(SelfIntersection, Sphere) {
    const float scale = GetParam();
    const Vec3 center = scale * Vec3(-2.0f, 4.0f, 1.0f);
    const float radius = scale;
    const Sphere sphere(center, radius);
    Accel accel;
    accel.add_shape(-1, sphere);
    accel.commit();
    Rng rng(6);
    int reflected_rehit = 0, wrong_exit = 0;
    double worst_exit_error = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 target_n = random_direction(rng);
        const Vec3 o = center + 3.0f * radius * random_direction_around(rng, target_n);
        const Ray ray{o, center + radius * target_n - o};
        const auto hit = accel.intersect(ray);
        ASSERT_TRUE(hit.has_value());
        SurfaceInteraction si;
        sphere.fill_interaction(ray, *hit, si);
        const Vec3 out = random_direction_around(rng, si.ng);
        if (accel.intersect(spawn_ray(si, out)) || accel.occluded(spawn_ray(si, out)))
            ++reflected_rehit;
        // Into the sphere: the offset origin is inside, and the next hit is the far side,
        // where the exact interval from that origin puts it (a chord of about 2 r cos).
        const Vec3 in = random_direction_around(rng, -si.ng);
        const Ray inward = spawn_ray(si, in);
        const auto exit = accel.intersect(inward);
        double e0 = 0.0, e1 = 0.0;
        ellipsoid_interval(inward.origin, in, DVec3(center), DVec3(radius), e0, e1);
        const float chord = 2.0f * radius * glm::dot(in, -si.ng);
        if (!exit || !(e0 < 0.0) || !(exit->t > 0.5f * chord)) {
            ++wrong_exit;
            continue;
        }
        const double error = std::abs(exit->t - e1) / chord;
        worst_exit_error = std::max(worst_exit_error, error);
        if (error > 1e-4) ++wrong_exit;
    }
    EXPECT_EQ(reflected_rehit, 0) << "scale " << scale;
    EXPECT_EQ(wrong_exit, 0) << "scale " << scale << ", worst relative error " << worst_exit_error;
}

INSTANTIATE_TEST_SUITE_P(Scales, SelfIntersection, ::testing::Values(1e-3f, 1.0f, 1e4f),
                         [](const ::testing::TestParamInfo<float>& info) {
                             return info.index == 0 ? std::string("Milli")
                                                    : (info.index == 1 ? "Unit" : "TenThousand");
                         });

// offset_ray_origin against the rule it implements (Wächter & Binder), written out axis by
// axis: a few ulps along the normal, on the side the ray leaves by, or a fixed small step
// near the origin, where ulps vanish. Random points of all magnitudes and signs, and the
// edge cases: zero of either sign, the near-origin threshold, normals along the axes.
TEST(SpawnRay, OffsetOriginFollowsThePerAxisRule) {
    auto expected = [](const Vec3& p, const Vec3& ng, const Vec3& direction) {
        const Vec3 n = glm::dot(ng, direction) < 0.0f ? -ng : ng;
        Vec3 result;
        for (int i = 0; i < 3; ++i) {
            if (std::abs(p[i]) < 1.0f / 32.0f) {
                result[i] = p[i] + n[i] / 65536.0f;
                continue;
            }
            const int offset = static_cast<int>(256.0f * n[i]);
            const int32_t bits = std::bit_cast<int32_t>(p[i]);
            result[i] = std::bit_cast<float>(bits + (p[i] < 0.0f ? -offset : offset));
        }
        return result;
    };
    auto same_bits = [](const Vec3& a, const Vec3& b) {
        for (int i = 0; i < 3; ++i) {
            if (std::bit_cast<uint32_t>(a[i]) != std::bit_cast<uint32_t>(b[i])) return false;
        }
        return true;
    };
    Rng rng(99);
    std::vector<Vec3> points = {Vec3(0.0f), Vec3(-0.0f), Vec3(1.0f / 32.0f, -1.0f / 32.0f, 0.03f),
                                Vec3(-1e30f, 1e-30f, 5.0f)};
    for (int i = 0; i < 20000; ++i) {
        const float magnitude = std::pow(10.0f, 8.0f * rng.next_float() - 4.0f);
        const Vec3 u(rng.next_float(), rng.next_float(), rng.next_float());
        points.push_back(magnitude * (2.0f * u - Vec3(1.0f)));
    }
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 ng =
            i % 5 == 0 ? Vec3(0, 0, 1)
                       : warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 direction =
            warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 got = offset_ray_origin(points[i], ng, direction);
        ASSERT_TRUE(same_bits(got, expected(points[i], ng, direction)))
            << "p = (" << points[i].x << ", " << points[i].y << ", " << points[i].z << ")";
    }
}
