// The transport layer's shared pieces: roulette's two rules, the start of a light path,
// photons that scatter through the same geometric-side check as every other walk, and
// visibility as transmittance through surfaces that only bound media.
#include <glint/core/rng.h>
#include <glint/integrator/photon/photon_tracer.h>
#include <glint/integrator/transport/light_path_start.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/roulette.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/material/material.h>
#include <glint/math/warp.h>

#include <glint/film/image.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cmath>
#include <string>
#include <utility>

using namespace glint;

// Below the depth where it applies, and for a throughput of 1 or more, throughput roulette
// draws nothing and keeps the path whole.
TEST(Roulette, ThroughputRuleDrawsOnlyWhereItApplies) {
    int draws = 0;
    auto draw = [&] {
        ++draws;
        return 0.0f;
    };
    float survival = 0.0f;
    EXPECT_TRUE(survives_throughput_roulette(kRouletteMinDepth - 1, 0.1f, draw, survival));
    EXPECT_EQ(survival, 1.0f);
    EXPECT_TRUE(survives_throughput_roulette(kRouletteMinDepth, 1.0f, draw, survival));
    EXPECT_TRUE(survives_throughput_roulette(kRouletteMinDepth, 7.0f, draw, survival));
    EXPECT_EQ(survival, 1.0f);
    EXPECT_EQ(draws, 0);
    // Where it applies: survival is the throughput, and a draw below 1 - throughput ends it.
    EXPECT_TRUE(survives_throughput_roulette(
        kRouletteMinDepth, 0.25f, [] { return 0.8f; }, survival));
    EXPECT_FLOAT_EQ(survival, 0.25f);
    EXPECT_FALSE(survives_throughput_roulette(
        kRouletteMinDepth, 0.25f, [] { return 0.7f; }, survival));
}

// Both rules keep the estimate unbiased: the mean over many draws of (survived / survival)
// is 1, within a few standard errors.
TEST(Roulette, BothRulesAreUnbiased) {
    for (const float kept : {0.05f, 0.3f, 0.9f}) {
        Rng rng(static_cast<uint64_t>(kept * 1000.0f) + 1u);
        const int n = 200000;
        double sum_throughput = 0.0, sum_power = 0.0;
        for (int i = 0; i < n; ++i) {
            float survival = 0.0f;
            if (survives_throughput_roulette(
                    kRouletteMinDepth, kept, [&] { return rng.next_float(); }, survival))
                sum_throughput += 1.0 / survival;
            if (survives_power_roulette(
                    kept, [&] { return rng.next_float(); }, survival))
                sum_power += 1.0 / survival;
        }
        // The weight 1/kept with probability kept: variance (1 - kept) / kept per draw.
        const double se = std::sqrt((1.0 - kept) / kept / n);
        EXPECT_NEAR(sum_throughput / n, 1.0, 5.0 * se) << "kept " << kept;
        EXPECT_NEAR(sum_power / n, 1.0, 5.0 * se) << "kept " << kept;
    }
    float survival = 1.0f;
    EXPECT_FALSE(survives_power_roulette(
        0.0f, [] { return 0.0f; }, survival));
}

namespace {

// Two area lights of different power (the second four times brighter and the same size).
const char* kTwoLights = R"(
    glint.quad{ vertices = { {-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1} },
                material = glint.emissive{ radiance = 1 } }
    glint.quad{ vertices = { {3, 2, -1}, {5, 2, -1}, {5, 2, 1}, {3, 2, 1} },
                material = glint.emissive{ radiance = 4 } }
    glint.quad{ vertices = { {-9, 0, 9}, {9, 0, 9}, {9, 0, -9}, {-9, 0, -9} },
                material = glint.diffuse{ reflectance = 0.5 } }
)";

}  // namespace

// A light path starts at the light the light sampler chooses, with the light's own
// emission sample, and carries power / pmf; the brighter light is chosen more often, in
// proportion to power.
TEST(LightPathStart, CarriesPowerOverPmfFromTheChosenLight) {
    const test::BuiltScene b = test::build_lua(kTwoLights, "light-path-start.lua");
    const Scene& scene = *b.scene;
    Rng rng(11);
    int bright = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        LightPathSamples u;
        u.u_light = rng.next_float();
        u.u_position = Vec2(rng.next_float(), rng.next_float());
        u.u_direction = Vec2(rng.next_float(), rng.next_float());
        u.u_select = rng.next_float();
        const std::optional<LightPathStart> start = start_light_path(scene, u);
        ASSERT_TRUE(start);
        const LightSampler::Choice choice = scene.light_sampler().sample(u.u_light);
        ASSERT_EQ(start->light, choice.light);
        EXPECT_EQ(start->pmf, choice.pmf);
        EXPECT_EQ(start->pmf, scene.light_sampler().pmf(*start->light));
        const std::optional<LightEmission> emission =
            choice.light->sample_le(u.u_position, u.u_direction, u.u_select);
        ASSERT_TRUE(emission);
        EXPECT_EQ(start->emission.ray.origin, emission->ray.origin);
        EXPECT_EQ(start->emission.pdf_pos, emission->pdf_pos);
        EXPECT_EQ(start->emission.pdf_dir, emission->pdf_dir);
        const Spectrum expected = emission->beta() / choice.pmf;
        EXPECT_FLOAT_EQ(start->beta.max_value(), expected.max_value());
        EXPECT_FLOAT_EQ(start->beta.luminance(), expected.luminance());
        if (start->emission.ray.origin.x > 2.0f) ++bright;
    }
    // Power in proportion 1 : 4 (equal areas): the bright light's share is 0.8.
    const double share = static_cast<double>(bright) / n;
    EXPECT_NEAR(share, 0.8, 5.0 * std::sqrt(0.8 * 0.2 / n));
}

// An emitter the caller supplies (a projection map) is asked instead of sample_le.
TEST(LightPathStart, UsesTheEmitterItIsGiven) {
    const test::BuiltScene b = test::build_lua(kTwoLights, "light-path-start.lua");
    int calls = 0;
    auto none = [&](const Light&, const Vec2&, const Vec2&, float) {
        ++calls;
        return std::optional<LightEmission>();
    };
    const LightPathSamples u{0.5f, Vec2(0.5f), Vec2(0.5f), 0.5f};
    EXPECT_FALSE(start_light_path(*b.scene, u, none));
    EXPECT_EQ(calls, 1);
}

namespace {

// A floor whose vertex normals lean far over (shading normal about 72 degrees from the
// geometric one), lit from above, with a second floor under it that only a ray through
// the first can reach. Diffuse scattering about the leaning shading normal picks many
// directions below the geometric surface.
const char* kLeaningNormals = R"(
    glint.point_light{ position = {0, 2, 0}, intensity = 10 }
    glint.mesh{ vertices = { {-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20} },
                indices = { 1, 3, 2, 1, 4, 3 },
                normals = { {0.95, 0.3, 0}, {0.95, 0.3, 0}, {0.95, 0.3, 0}, {0.95, 0.3, 0} },
                material = glint.diffuse{ reflectance = 0.9 } }
    glint.quad{ vertices = { {-4, -1, 4}, {4, -1, 4}, {4, -1, -4}, {-4, -1, -4} },
                material = glint.diffuse{ reflectance = 0.9 } }
)";

struct CountBelow {
    int above = 0, below = 0;
    void store(const PhotonHit& hit) { (hit.si->p.y < -0.5f ? below : above) += 1; }
};

}  // namespace

// A photon that would leave through the wrong side of a shading normal ends there, as a
// camera path does (sample_scattering's geometric-side check): none reaches the lower floor.
TEST(PhotonTracer, EndsAPhotonThatWouldLeaveThroughTheWrongSideOfItsShadingNormal) {
    const test::BuiltScene b = test::build_lua(kLeaningNormals, "leaning-normals.lua");
    const PhotonTracer tracer(*b.scene, 4);
    uint64_t rays = 0;
    const std::vector<CountBelow> sinks =
        tracer.trace(0, 20000, 5, rays, [] { return CountBelow{}; });
    int above = 0, below = 0;
    for (const CountBelow& sink : sinks) {
        above += sink.above;
        below += sink.below;
    }
    EXPECT_GT(above, 5000);  // the photons did reach the upper floor
    EXPECT_EQ(below, 0);
}

namespace {

// A point light above three sheets at heights 1, 2 and 3 between y = 0 and y = 4; `middle`
// is the material of the sheet at y = 2.
std::string sheets(const std::string& middle) {
    std::string code = R"(
        glint.point_light{ position = {0, 5, 0}, intensity = 1 }
    )";
    for (const auto& [y, material] : {std::pair<int, std::string>{1, "glint.interface{}"},
                                      {2, middle},
                                      {3, "glint.interface{}"}}) {
        const std::string h = std::to_string(y);
        code += "glint.quad{ vertices = { {-1, " + h + ", 1}, {1, " + h + ", 1}, {1, " + h +
                ", -1}, {-1, " + h + ", -1} }, material = " + material + " }\n";
    }
    return code;
}

}  // namespace

// Surfaces that only bound media let a shadow ray through whole: transmittance 1 through
// any number of them, 0 where an opaque surface stands among them.
TEST(Visibility, TransmittanceThroughInterfaceOnlySurfacesIsOne) {
    const test::BuiltScene open = test::build_lua(sheets("glint.interface{}"), "sheets.lua");
    ASSERT_TRUE(open.scene->has_interfaces());
    const Spectrum through = transmittance(*open.scene, Vec3(0.0f), Vec3(0.0f, 4.0f, 0.0f));
    EXPECT_EQ(through.max_value(), 1.0f);
    EXPECT_EQ(through.average(), 1.0f);
    // Towards a target short of the sheets, and from above them, alike.
    EXPECT_EQ(transmittance(*open.scene, Vec3(0.0f, 4.5f, 0.0f), Vec3(0.0f, 0.5f, 0.0f)).average(),
              1.0f);

    const test::BuiltScene blocked = test::build_lua(sheets("glint.diffuse{}"), "sheets.lua");
    EXPECT_TRUE(transmittance(*blocked.scene, Vec3(0.0f), Vec3(0.0f, 4.0f, 0.0f)).is_black());
    // Past the edge of the sheets nothing is in the way.
    EXPECT_EQ(
        transmittance(*blocked.scene, Vec3(3.0f, 0.0f, 0.0f), Vec3(3.0f, 4.0f, 0.0f)).average(),
        1.0f);
}

// A passed interface mesh whose vertex normals disagree with its winding: the normals say
// which side is outside, in what walks read of the crossing (Scene::passed_crossing) as in
// the whole interaction.
TEST(Visibility, PassedCrossingTakesTheSideOfTheNormals) {
    const test::BuiltScene built = test::build_lua(R"(
        local fog = glint.medium{ sigma_a = 0.1, sigma_s = 0.2 }
        glint.mesh{ vertices = { {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0} },
                    indices = { 1, 2, 3, 1, 3, 4 },
                    normals = { {0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1} },
                    material = glint.interface{ interior = fog } }
        glint.quad{ vertices = { {-9, -9, -20}, {9, -9, -20}, {9, 9, -20}, {-9, 9, -20} },
                    material = glint.diffuse{} }
    )",
                                                   "sheet.lua");
    const Ray ray{Vec3(0.2f, -0.3f, 10.0f), Vec3(0.0f, 0.0f, -1.0f), 0.0f, kInfinity};
    SurfaceInteraction si;
    PassedSurfaces passed;
    ASSERT_TRUE(built.scene->intersect_surface_passing(ray, si, passed));
    ASSERT_EQ(passed.count, 1);
    SurfaceInteraction crossing;
    built.scene->passed_surface(ray, passed.hits[0], crossing);
    const Scene::Crossing cheap = built.scene->passed_crossing(ray, passed.hits[0]);
    EXPECT_EQ(cheap.material, crossing.material);
    EXPECT_LT(crossing.ng.z, -0.99f) << "the winding's +z, turned to the normals' side";
    EXPECT_TRUE(cheap.along_normal) << "the ray goes along -z: along the normals' side";
}

namespace {

// A fog medium for the interface tests below, and a cube of side 2 `half` round the origin
// whose surface only bounds that fog.
const std::string kFog = "local fog = glint.medium{ sigma_a = 0.1, sigma_s = 0.2 }\n";
std::string fog_box(float half) {
    const std::string h = std::to_string(half);
    return "glint.box{ min = {-" + h + ", -" + h + ", -" + h + "}, max = {" + h + ", " + h + ", " +
           h + "}, material = glint.interface{ interior = fog } }\n";
}

}  // namespace

// One traversal goes past the interfaces Embree can skip: the shapes whose every part only
// bounds media. They come back in order along the ray, each once (the high-quality BVH may
// offer a triangle twice), and only those before the closest other hit; a sphere, which
// Embree cannot skip (user geometry), is the hit itself, as are interfaces stacked deeper
// than the record holds. Every other query still stops at them.
TEST(Visibility, OneTraversalPassesTheInterfaces) {
    const std::string wall =
        "glint.quad{ vertices = { {-9, -9, -20}, {9, -9, -20}, {9, 9, -20}, {-9, 9, -20} }, "
        "material = glint.diffuse{} }\n";
    const test::BuiltScene two =
        test::build_lua(kFog + fog_box(1) + fog_box(2) + wall, "boxes.lua");
    const Ray ray{Vec3(0.1f, 0.2f, 10.0f), Vec3(0.0f, 0.0f, -1.0f), 0.0f, kInfinity};
    SurfaceInteraction si;
    PassedSurfaces passed;
    ASSERT_TRUE(two.scene->intersect_surface_passing(ray, si, passed));
    EXPECT_FALSE(si.material->is_interface());
    EXPECT_NEAR(si.t, 30.0f, 1e-4f);
    ASSERT_EQ(passed.count, 4);
    const float expected_t[] = {8.0f, 9.0f, 11.0f, 12.0f};
    for (int i = 0; i < passed.count; ++i) {
        EXPECT_NEAR(passed.hits[i].t, expected_t[i], 1e-4f) << i;
        SurfaceInteraction crossing;
        two.scene->passed_surface(ray, passed.hits[i], crossing);
        EXPECT_TRUE(crossing.material->is_interface()) << i;
        EXPECT_NEAR(crossing.p.z, 10.0f - expected_t[i], 1e-4f) << i;
        // What walks read of a crossing, without the whole interaction: the same.
        const Scene::Crossing cheap = two.scene->passed_crossing(ray, passed.hits[i]);
        EXPECT_EQ(cheap.material, crossing.material) << i;
        EXPECT_EQ(cheap.along_normal, glm::dot(ray.direction, crossing.ng) > 0.0f) << i;
        EXPECT_EQ(cheap.along_normal, i >= 2) << i << ": in through two faces, out through two";
    }
    // Oblique rays through every face, both ways: the side read from the hit record is the
    // side of the interaction's normal.
    Rng rng(31);
    for (int k = 0; k < 200; ++k) {
        const Vec3 from =
            3.0f * warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 to =
            0.5f * warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Ray oblique{from, glm::normalize(to - from), 0.0f, kInfinity};
        PassedSurfaces through;
        SurfaceInteraction end;
        two.scene->intersect_surface_passing(oblique, end, through);
        for (int i = 0; i < through.count; ++i) {
            SurfaceInteraction crossing;
            two.scene->passed_surface(oblique, through.hits[i], crossing);
            EXPECT_EQ(two.scene->passed_crossing(oblique, through.hits[i]).along_normal,
                      glm::dot(oblique.direction, crossing.ng) > 0.0f)
                << k << ", " << i;
        }
    }
    // Every other query stops at the first interface.
    EXPECT_TRUE(two.scene->intersect_surface(ray, si));
    EXPECT_NEAR(si.t, 8.0f, 1e-4f);
    // Short of the wall, the same four and no hit.
    Ray shorter = ray;
    shorter.t_max = 11.5f;
    EXPECT_FALSE(two.scene->intersect_surface_passing(shorter, si, passed));
    EXPECT_EQ(passed.count, 3);

    // Through the diagonal edge of a box face's two triangles (and on through the opposite
    // face's): each face is crossed once.
    const Ray diagonal{Vec3(0.5f, 0.5f, 10.0f), Vec3(0.0f, 0.0f, -1.0f), 0.0f, kInfinity};
    ASSERT_TRUE(two.scene->intersect_surface_passing(diagonal, si, passed));
    EXPECT_EQ(passed.count, 4);
    const Ray corner{Vec3(-1.0f, -1.0f, 10.0f), Vec3(0.0f, 0.0f, -1.0f), 0.0f, kInfinity};
    ASSERT_TRUE(two.scene->intersect_surface_passing(corner, si, passed));
    EXPECT_EQ(passed.count % 2, 0) << "an inner box's corner: crossed twice or not at all";

    // A sphere interface is a hit; the box's face before it is passed.
    const test::BuiltScene sphere = test::build_lua(
        kFog + fog_box(2) +
            "glint.sphere{ radius = 1, material = glint.interface{ interior = fog } }\n",
        "sphere.lua");
    ASSERT_TRUE(sphere.scene->intersect_surface_passing(ray, si, passed));
    EXPECT_TRUE(si.material->is_interface());
    EXPECT_NEAR(si.t, 10.0f - std::sqrt(1.0f - 0.1f * 0.1f - 0.2f * 0.2f), 1e-4f);
    EXPECT_EQ(passed.count, 1);

    // Deeper than the record: the first interface is the hit, as for intersect_surface().
    std::string nested = kFog;
    for (int i = 1; i <= PassedSurfaces::kCapacity; ++i) nested += fog_box(0.5f * i);
    const test::BuiltScene deep = test::build_lua(nested + wall, "nested.lua");
    ASSERT_TRUE(deep.scene->intersect_surface_passing(ray, si, passed));
    EXPECT_EQ(passed.count, 0);
    EXPECT_NEAR(si.t, 10.0f - 0.5f * PassedSurfaces::kCapacity, 1e-4f);
}

// The packet form of the closest-hit walk past interfaces, which the preview's camera rays in
// media take: lane by lane, the same hit (surface, distance) and the same crossings in the
// same order as one ray at a time, for coherent and scattered packets, partly filled ones,
// interfaces stacked deeper than a lane's record (that lane traced again alone) and a
// sphere interface (user geometry: the hit, as for one ray).
TEST(Visibility, PacketsPassTheInterfacesAsOneRayDoes) {
    std::string deep = kFog;
    for (int i = 1; i <= PassedSurfaces::kCapacity + 1; ++i) deep += fog_box(0.4f * i);
    const std::string scenes[] = {
        kFog + fog_box(1) + fog_box(2) +
            "glint.quad{ vertices = { {0.5, -9, -5}, {9, -9, -5}, {9, 9, -5}, {0.5, 9, -5} }, "
            "material = glint.diffuse{} }\n",
        deep + "glint.sphere{ center = {0, 0, -6}, radius = 2, material = glint.diffuse{} }\n",
        kFog + fog_box(2) +
            "glint.sphere{ radius = 1, material = glint.interface{ interior = fog } }\n"};
    Rng rng(11);
    int compared = 0, passed_some = 0;
    for (const std::string& code : scenes) {
        const test::BuiltScene b = test::build_lua(code, "packets.lua");
        for (int packet = 0; packet < 60; ++packet) {
            const bool coherent = packet % 2 == 0;
            PerLane<Ray> rays;
            PerLane<const Ray*> ray_of{};
            PerLane<SurfaceInteraction> surfaces;
            PerLane<SurfaceInteraction*> si_of{};
            uint32_t active = 0;
            const Vec3 from(4.0f * rng.next_float() - 2.0f, 4.0f * rng.next_float() - 2.0f, 10.0f);
            for (int lane = 0; lane < kPacketWidth; ++lane) {
                if (packet % 5 == 4 && rng.next_float() < 0.5f) continue;  // a partial packet
                const Vec3 origin = coherent ? from
                                             : Vec3(4.0f * rng.next_float() - 2.0f,
                                                    4.0f * rng.next_float() - 2.0f, 10.0f);
                const Vec3 to(3.0f * rng.next_float() - 1.5f, 3.0f * rng.next_float() - 1.5f,
                              -8.0f);
                rays[lane] = Ray{origin, glm::normalize(to - origin), 0.0f, kInfinity};
                ray_of[lane] = &rays[lane];
                si_of[lane] = &surfaces[lane];
                active |= 1u << lane;
            }
            if (active == 0) continue;
            PerLane<PassedSurfaces> passed;
            const uint32_t hit =
                b.scene->intersect_surface_packet_passing(ray_of, active, si_of, passed, coherent);
            EXPECT_EQ(hit & ~active, 0u);
            for_each_lane(active, [&](int lane) {
                SurfaceInteraction si;
                PassedSurfaces alone;
                const bool alone_hit = b.scene->intersect_surface_passing(rays[lane], si, alone);
                ASSERT_EQ(((hit >> lane) & 1u) != 0, alone_hit) << packet << ", " << lane;
                if (alone_hit) {
                    EXPECT_EQ(surfaces[lane].t, si.t) << packet << ", " << lane;
                    EXPECT_EQ(surfaces[lane].p, si.p) << packet << ", " << lane;
                    EXPECT_EQ(surfaces[lane].material, si.material) << packet << ", " << lane;
                }
                ASSERT_EQ(passed[lane].count, alone.count) << packet << ", " << lane;
                for (int k = 0; k < alone.count; ++k) {
                    EXPECT_EQ(passed[lane].hits[k].t, alone.hits[k].t) << packet << ", " << lane;
                    EXPECT_EQ(passed[lane].hits[k].top_geometry, alone.hits[k].top_geometry);
                    EXPECT_EQ(passed[lane].hits[k].primitive, alone.hits[k].primitive);
                }
                passed_some += alone.count > 0;
                ++compared;
            });
        }
    }
    EXPECT_GT(compared, 1000);
    EXPECT_GT(passed_some, 500);
}

// The any-hit form for shadow rays: where every interface is a world triangle mesh, one
// occlusion traversal says whether an opaque surface blocks the segment and, when none does,
// hands back the same crossings in the same order as the closest-hit form; a sphere
// interface (user geometry, which Embree cannot skip) or an interface in a placed group
// makes the scene fall back to the closest-hit walk, which still gives the right
// transmittance through it.
TEST(Visibility, AnyHitTraversalPassesTheInterfacesAsTheClosestHitOneDoes) {
    const std::string plate =
        "glint.quad{ vertices = { {0.5, -9, -5}, {9, -9, -5}, {9, 9, -5}, {0.5, 9, -5} }, "
        "material = glint.diffuse{} }\n";
    const test::BuiltScene b = test::build_lua(kFog + fog_box(1) + fog_box(2) + plate, "boxes.lua");
    ASSERT_TRUE(b.scene->interfaces_skippable());
    Rng rng(7);
    int blocked_rays = 0, clear_rays = 0;
    for (int i = 0; i < 400; ++i) {
        // Segments from in front of the boxes to behind them, some through the plate.
        const Vec3 from(4.0f * rng.next_float() - 2.0f, 4.0f * rng.next_float() - 2.0f, 10.0f);
        const Vec3 to(8.0f * rng.next_float() - 4.0f, 8.0f * rng.next_float() - 4.0f, -8.0f);
        const Ray ray{from, to - from, 0.0f, kShadowRayEnd};
        PassedSurfaces any, closest;
        const std::optional<bool> blocked = b.scene->accel().occluded_passing(ray, any);
        ASSERT_TRUE(blocked.has_value());
        SurfaceInteraction si;
        const bool hit = b.scene->intersect_surface_passing(ray, si, closest);
        ASSERT_EQ(*blocked, hit) << i;
        if (hit) {
            ++blocked_rays;
            EXPECT_EQ(any.count, 0);
            continue;
        }
        ++clear_rays;
        ASSERT_EQ(any.count, closest.count) << i;
        for (int k = 0; k < any.count; ++k) {
            EXPECT_EQ(any.hits[k].t, closest.hits[k].t) << i << ", " << k;
            EXPECT_EQ(any.hits[k].top_geometry, closest.hits[k].top_geometry) << i << ", " << k;
        }
        // The transmittance through the boxes' fog, now found the any-hit way, is the one
        // the closest-hit walk's legs give.
        const Medium* outside = nullptr;
        Spectrum expected(1.0f);
        walk_legs(*b.scene, ray, closest, kShadowRayEnd, outside, [&](const Ray& leg, float t) {
            Rng unused;
            expected *= outside->transmittance(leg, t, unused);
            return true;
        });
        EXPECT_NEAR(transmittance_through_interfaces(*b.scene, {from, to - from}).average(),
                    expected.average(), 1e-6f)
            << i;
    }
    EXPECT_GT(blocked_rays, 40);
    EXPECT_GT(clear_rays, 40);

    // A sphere interface, or a box in a placed group: the closest-hit walk, which crosses the
    // sphere (fog of sigma_t 0.3 along its diameter 2 from outside).
    const test::BuiltScene sphere = test::build_lua(
        kFog + "glint.sphere{ radius = 1, material = glint.interface{ interior = fog } }\n",
        "sphere.lua");
    EXPECT_FALSE(sphere.scene->interfaces_skippable());
    EXPECT_NEAR(transmittance_through_interfaces(*sphere.scene,
                                                 {Vec3(0.0f, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -10.0f)})
                    .average(),
                std::exp(-0.3f * 2.0f), 1e-5f);
    const test::BuiltScene grouped =
        test::build_lua(kFog + "local g = glint.group()\n" +
                            "g:box{ min = {-1, -1, -1}, max = {1, 1, 1}, "
                            "material = glint.interface{ interior = fog } }\n" +
                            "glint.place(g)\n",
                        "grouped.lua");
    EXPECT_FALSE(grouped.scene->interfaces_skippable());
}

// Shadow rays as packets, which the preview's paths in media trace: lane by lane the same
// answer as one ray at a time. The any-hit traversal past interfaces gives the same blocked
// lanes and crossings as occluded_passing() (a lane whose crossings overflow its record is
// reported, as occluded_passing()'s nullopt), and transmittance_packet() the same bits as
// transmittance(), drawing the same from each lane's stream: lanes in vacuum and in a
// medium (homogeneous fog, and a cloud whose ratio tracking draws), coherent packets aimed
// at one point and scattered ones, partly filled ones; boxes with a plate, nested boxes that
// overflow the record with a sphere, a sphere interface (not skippable) and a scene without
// interfaces.
TEST(Visibility, ShadowPacketsGiveWhatOneShadowRayGives) {
    const std::string cloud =
        "local cloud = glint.medium{ type = 'cloud', min = {-2, -2, -2}, max = {2, 2, 2}, "
        "density = 2, albedo = 0.9, resolution = 12, seed = 3 }\n";
    std::string deep = kFog;
    for (int i = 1; i <= PassedSurfaces::kCapacity + 1; ++i) deep += fog_box(0.4f * i);
    const std::string plate =
        "glint.quad{ vertices = { {0.5, -9, -5}, {9, -9, -5}, {9, 9, -5}, {0.5, 9, -5} }, "
        "material = glint.diffuse{} }\n";
    const std::string scenes[] = {
        kFog + cloud + fog_box(1) + fog_box(2) + plate,
        cloud + deep +
            "glint.sphere{ center = {0, 0, -6}, radius = 2, material = glint.diffuse{} }\n",
        kFog + cloud + fog_box(2) +
            "glint.sphere{ radius = 1, material = glint.interface{ interior = fog } }\n",
        kFog + cloud + plate};
    Rng rng(5);
    int compared = 0, blocked_lanes = 0, crossed_lanes = 0, overflowed_lanes = 0;
    for (const std::string& code : scenes) {
        const test::BuiltScene b = test::build_lua(code, "shadow_packets.lua");
        const std::vector<std::unique_ptr<Medium>>& media = b.scene->media();
        for (int packet = 0; packet < 80; ++packet) {
            const bool coherent = packet % 2 == 0;
            PerLane<Scene::ShadowRay> shadows;
            PerLane<Vec3> origins, directions;
            PerLane<float> times{};
            PerLane<const Medium*> lane_media{};
            PerLane<Rng> packet_streams, alone_streams;
            PerLane<Rng*> streams{};
            uint32_t active = 0;
            const Vec3 target(3.0f * rng.next_float() - 1.5f, 3.0f * rng.next_float() - 1.5f,
                              -8.0f);
            for (int lane = 0; lane < kPacketWidth; ++lane) {
                if (packet % 5 == 4 && rng.next_float() < 0.5f) continue;  // a partial packet
                const Vec3 from(4.0f * rng.next_float() - 2.0f, 4.0f * rng.next_float() - 2.0f,
                                10.0f);
                const Vec3 to = coherent ? target
                                         : Vec3(8.0f * rng.next_float() - 4.0f,
                                                8.0f * rng.next_float() - 4.0f, -8.0f);
                shadows[lane] = {from, to - from, 0.0f};
                origins[lane] = from;
                directions[lane] = to - from;
                const int pick = static_cast<int>(3.0f * rng.next_float());
                lane_media[lane] =
                    pick < static_cast<int>(media.size()) ? media[pick].get() : nullptr;
                packet_streams[lane] = alone_streams[lane] = Rng(1000 + packet * 8 + lane);
                // Some lanes without a stream: the fixed one.
                streams[lane] = lane % 3 == 2 ? nullptr : &packet_streams[lane];
                active |= 1u << lane;
            }
            if (active == 0) continue;

            PerLane<PassedSurfaces> passed;
            uint32_t overflowed = 0;
            const uint32_t blocked = b.scene->accel().occluded_packet_passing(
                origins, directions, times, kShadowRayEnd, active, passed, overflowed, coherent);
            EXPECT_EQ(blocked & ~active, 0u);
            EXPECT_EQ(overflowed & ~active, 0u);
            EXPECT_EQ(blocked & overflowed, 0u);
            for_each_lane(active, [&](int lane) {
                PassedSurfaces alone;
                const Ray ray{origins[lane], directions[lane], 0.0f, kShadowRayEnd};
                const std::optional<bool> alone_blocked =
                    b.scene->accel().occluded_passing(ray, alone);
                ASSERT_EQ(((overflowed >> lane) & 1u) != 0, !alone_blocked.has_value())
                    << packet << ", " << lane << ", scene " << (&code - scenes);
                if (!alone_blocked) {
                    ++overflowed_lanes;
                    return;
                }
                ASSERT_EQ(((blocked >> lane) & 1u) != 0, *alone_blocked) << packet << ", " << lane;
                blocked_lanes += *alone_blocked;
                ASSERT_EQ(passed[lane].count, alone.count) << packet << ", " << lane;
                crossed_lanes += alone.count > 0;
                for (int k = 0; k < alone.count; ++k) {
                    EXPECT_EQ(passed[lane].hits[k].t, alone.hits[k].t) << packet << ", " << lane;
                    EXPECT_EQ(passed[lane].hits[k].top_geometry, alone.hits[k].top_geometry);
                }
            });

            PerLane<Spectrum> T;
            transmittance_packet(*b.scene, shadows, lane_media, streams, active, T);
            for_each_lane(active, [&](int lane) {
                Rng* stream = lane % 3 == 2 ? nullptr : &alone_streams[lane];
                const Spectrum expected =
                    transmittance(*b.scene, shadows[lane], lane_media[lane], stream);
                for (int c = 0; c < Spectrum::active_values(); ++c)
                    EXPECT_EQ(T[lane].value(c), expected.value(c)) << packet << ", " << lane;
                // The same draws: the streams are where the lone rays left theirs.
                EXPECT_EQ(packet_streams[lane].next_float(), alone_streams[lane].next_float());
                ++compared;
            });
        }
    }
    EXPECT_GT(compared, 1500);
    EXPECT_GT(blocked_lanes, 100);
    EXPECT_GT(crossed_lanes, 100);
    EXPECT_GT(overflowed_lanes, 20);
}

// Without interfaces, visibility is Embree's occlusion query: 0 or 1.
TEST(Visibility, WithoutInterfacesIsTheOcclusionQuery) {
    const test::BuiltScene b = test::build_lua(R"(
        glint.point_light{ position = {0, 5, 0}, intensity = 1 }
        glint.quad{ vertices = { {-1, 2, 1}, {1, 2, 1}, {1, 2, -1}, {-1, 2, -1} },
                    material = glint.diffuse{} }
    )",
                                               "sheet.lua");
    ASSERT_FALSE(b.scene->has_interfaces());
    for (const float x : {0.0f, 0.5f, 1.5f, 3.0f}) {
        const Vec3 from(x, 0.0f, 0.0f), to(x, 4.0f, 0.0f);
        const bool blocked = b.scene->accel().occluded(from, to - from, 0.0f, kShadowRayEnd);
        EXPECT_EQ(transmittance(*b.scene, from, to).average(), blocked ? 0.0f : 1.0f) << x;
    }
}

// A medium that only absorbs (an absorbing dielectric's inside) lets exp(-sigma_a d) through
// a segment of length d, per channel, and the dielectric names it as its inside.
TEST(Medium, AbsorbingMediumFollowsBeerLambert) {
    const AbsorbingMedium medium(Rgb(0.5f));
    const Ray ray{Vec3(0.0f), Vec3(0.0f, 2.0f, 0.0f), 0.0f, kInfinity};
    EXPECT_FLOAT_EQ(medium.transmittance(ray, 1.5f).average(), std::exp(-0.5f * 3.0f));
    const test::BuiltScene b = test::build_lua(R"(
        glint.sphere{ center = {0, 0, 0}, radius = 1,
                      material = glint.dielectric{ ior = 1.5, absorption = 0.5 } }
        glint.sphere{ center = {3, 0, 0}, radius = 1, material = glint.dielectric{ ior = 1.5 } }
    )",
                                               "glass.lua");
    SurfaceInteraction si;
    // From inside the absorbing sphere out through its back face: one unit of glass.
    ASSERT_TRUE(b.scene->intersect(Ray{Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), 0.0f, kInfinity}, si));
    EXPECT_FALSE(si.front_face);
    const MediumInterface absorbing = si.material->medium_interface();
    ASSERT_NE(absorbing.inside, nullptr);
    EXPECT_EQ(absorbing.outside, nullptr);
    EXPECT_FLOAT_EQ(segment_transmittance(Ray{Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f)}, si).average(),
                    std::exp(-0.5f));
    // Clear glass separates no media.
    ASSERT_TRUE(b.scene->intersect(
        Ray{Vec3(3.0f, 0.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f), 0.0f, kInfinity}, si));
    EXPECT_FALSE(si.material->medium_interface().is_transition());
}

namespace {

// A diffuse floor under a square light, seen from above; with `sheets`, interface-only
// sheets stand between the camera and the floor and between the light and the floor.
std::string floor_scene(const std::string& integrator, int seed, bool sheets) {
    std::string code = R"(
        glint.camera{ eye = {0, 3, 0.01}, look_at = {0, 0, 0}, fov = 50 }
        glint.render{ width = 16, height = 16, spp = 64, max_depth = 6, integrator = ')" +
                       integrator + "', seed = " + std::to_string(seed) + R"( }
        glint.quad{ vertices = { {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2} },
                    material = glint.diffuse{ reflectance = 0.6 } }
        glint.quad{ vertices = { {0.5, 2, -1}, {1.5, 2, -1}, {1.5, 2, 1}, {0.5, 2, 1} },
                    material = glint.emissive{ radiance = 4, two_sided = true } }
    )";
    if (sheets) {
        code += R"(
        glint.quad{ vertices = { {-3, 1, 3}, {3, 1, 3}, {3, 1, -3}, {-3, 1, -3} },
                    material = glint.interface{} }
        glint.quad{ vertices = { {-3, 2.5, 3}, {3, 2.5, 3}, {3, 2.5, -3}, {-3, 2.5, -3} },
                    material = glint.interface{} }
        )";
    }
    return code;
}

}  // namespace

// Walks and shadow rays cross interface-only surfaces unchanged: the image with them agrees
// with the image without them within the noise, for the path tracer (NEE, packets) and
// bdpt (its connections and the camera's).
TEST(Visibility, InterfaceSheetsLeaveTheImageUnchanged) {
    for (const char* integrator : {"path", "bdpt"}) {
        const Image a = test::render_lua(floor_scene(integrator, 1, false));
        const Image b = test::render_lua(floor_scene(integrator, 2, false));
        const Image with = test::render_lua(floor_scene(integrator, 3, true));
        for (int c = 0; c < 3; ++c) {
            const double se = test::standard_error_of_mean(a, b, c, 0, 0, 16, 16);
            const double mean = test::mean_channel(a, c, 0, 0, 16, 16);
            const double mean_with = test::mean_channel(with, c, 0, 0, 16, 16);
            ASSERT_GT(mean, 0.01) << integrator;
            // The difference of two independent means: sqrt(2) standard errors.
            EXPECT_NEAR(mean_with, mean, 4.0 * std::sqrt(2.0) * se) << integrator << " " << c;
        }
    }
}
