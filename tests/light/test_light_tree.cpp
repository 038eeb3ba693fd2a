// The light tree: its choice of light against its stated pmf (chi-square) at several
// receiving points, pmfs over all lights summing to 1, a pmf of zero only for lights that
// really cannot light the point, the same tree for any thread count, degenerate inputs, and
// the cone bounds it is built on.
#include <glint/core/rng.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/sphere.h>
#include <glint/light/area_light.h>
#include <glint/light/light_sampler.h>
#include <glint/light/point_light.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>
#include <tbb/global_control.h>

#include <bit>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace glint;

namespace {

Vec3 random_unit(Rng& rng) {
    const float z = 1.0f - 2.0f * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * rng.next_float();
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A small square quad light at `center` facing `normal`.
std::unique_ptr<Light> quad_light(const Vec3& center, const Vec3& normal, float size,
                                  float radiance, bool two_sided) {
    const Frame frame = Frame::from_normal(normal);
    const Vec3 s = 0.5f * size * frame.s(), t = 0.5f * size * frame.t();
    const TriangleMesh mesh(
        "quad", make_quad_mesh(center - s - t, center + s - t, center + s + t, center - s + t));
    return std::make_unique<AreaLight>(mesh.make_sampler(Transform()), Spectrum(radiance),
                                       two_sided);
}

// An emitting box: a mesh light of 12 pieces (its triangles) facing six ways.
std::unique_ptr<Light> box_light(const Vec3& center, float size, float radiance) {
    const Vec3 half(0.5f * size);
    const TriangleMesh mesh("box", make_box_mesh(center - half, center + half));
    return std::make_unique<AreaLight>(mesh.make_sampler(Transform()), Spectrum(radiance), false);
}

// A mixed scene of lights: quads facing every way (one- and two-sided), spheres, point and
// spot lights, a dark quad, emitting boxes (lights of 12 pieces each) and a directional
// light (no bounds: chosen beside the tree).
std::vector<std::unique_ptr<Light>> mixed_lights(int quads) {
    Rng rng(7);
    std::vector<std::unique_ptr<Light>> lights;
    for (int i = 0; i < quads; ++i) {
        const Vec3 c(8.0f * rng.next_float() - 4.0f, 8.0f * rng.next_float() - 4.0f,
                     8.0f * rng.next_float() - 4.0f);
        lights.push_back(quad_light(c, random_unit(rng), 0.1f + 0.5f * rng.next_float(),
                                    0.5f + 4.0f * rng.next_float(), i % 5 == 0));
    }
    lights.push_back(std::make_unique<AreaLight>(
        std::make_unique<SphereSampler>(Vec3(1, 2, 0), 0.3f), Spectrum(2.0f), false));
    lights.push_back(std::make_unique<PointLight>(Vec3(-2, 1, 3), Spectrum(5.0f)));
    lights.push_back(std::make_unique<SpotLight>(Vec3(2, -3, 1), Vec3(0, 1, 0.2f), Spectrum(8.0f),
                                                 25.0f, 15.0f));
    lights.push_back(quad_light(Vec3(0, 0, 1), Vec3(0, 0, 1), 0.5f, 0.0f, false));
    lights.push_back(box_light(Vec3(-1, -1, 2), 0.8f, 3.0f));
    lights.push_back(box_light(Vec3(3, 0.5f, -2), 0.4f, 6.0f));
    auto sun = std::make_unique<DirectionalLight>(Vec3(0.3f, -1, 0.2f), Spectrum(1.0f));
    sun->preprocess(Vec3(0.0f), 6.0f);
    lights.push_back(std::move(sun));
    return lights;
}

// One light's piece: what the tree chooses among.
struct Piece {
    const Light* light;
    uint32_t piece;
};
std::vector<Piece> pieces_of(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<Piece> pieces;
    for (const auto& light : lights) {
        for (uint32_t i = 0; i < light->piece_count(); ++i) pieces.push_back({light.get(), i});
    }
    return pieces;
}

// Receiving points, with a surface's normal or none (zero: a point in a medium).
struct Receiver {
    Vec3 p, n;
};
const Receiver kPoints[] = {{Vec3(0.0f), Vec3(0.0f)},
                            {Vec3(3.5f, -3.5f, 3.5f), glm::normalize(Vec3(-1, 1, 0))},
                            {Vec3(-4.5f, 0.2f, 1.0f), Vec3(1, 0, 0)},
                            {Vec3(0.1f, 2.0f, -3.9f), Vec3(0.0f)},
                            {Vec3(20.0f, 5.0f, -8.0f), glm::normalize(Vec3(0.2f, 1, 0.3f))}};

}  // namespace

TEST(LightTree, PmfsOverAllLightsSumToOne) {
    const auto lights = mixed_lights(300);
    const LightSampler sampler(lights, LightSelection::kTree);
    const std::vector<Piece> pieces = pieces_of(lights);
    ASSERT_EQ(pieces.size(), lights.size() + 2 * 11);  // two boxes of 12 pieces
    for (const auto& [p, n] : kPoints) {
        double sum = 0.0;
        for (const Piece& piece : pieces) sum += sampler.pmf(p, n, *piece.light, piece.piece);
        EXPECT_NEAR(sum, 1.0, 1e-4) << "at " << p.x << "," << p.y << "," << p.z;
    }
}

TEST(LightTreeSlow, ChoicesMatchTheStatedPmf) {
    const auto lights = mixed_lights(60);
    const LightSampler sampler(lights, LightSelection::kTree);
    const std::vector<Piece> pieces = pieces_of(lights);
    // Each light's pieces' counts, from first_count[Light::index] on.
    std::vector<size_t> first_count(lights.size() + 1, 0);
    for (const auto& light : lights)
        first_count[light->index() + 1] = first_count[light->index()] + light->piece_count();
    const int kDraws = 400000;
    for (const auto& [p, n] : kPoints) {
        std::vector<int> counts(pieces.size(), 0);
        int mismatched_pmf = 0, none = 0;
        Rng rng(11);
        for (int i = 0; i < kDraws; ++i) {
            const LightSampler::Choice c = sampler.sample(p, n, rng.next_float());
            if (!c.light) {
                ++none;
                continue;
            }
            // A light of one piece is chosen whole.
            const uint32_t piece = c.piece == LightSampler::kWholeLight ? 0 : c.piece;
            if (c.light->piece_count() == 1) {
                EXPECT_EQ(c.piece, LightSampler::kWholeLight);
            }
            ASSERT_LT(piece, c.light->piece_count());
            ++counts[first_count[c.light->index()] + piece];
            if (c.pmf != sampler.pmf(p, n, *c.light, c.piece)) ++mismatched_pmf;
        }
        EXPECT_EQ(mismatched_pmf, 0);
        EXPECT_EQ(none, 0);
        // Pearson's statistic over pieces with enough expected draws; the rest pooled.
        double statistic = 0.0, pooled_expected = 0.0, pooled_observed = 0.0;
        int bins = 0;
        for (const Piece& piece : pieces) {
            const double expected =
                kDraws * static_cast<double>(sampler.pmf(p, n, *piece.light, piece.piece));
            const double observed = counts[first_count[piece.light->index()] + piece.piece];
            if (expected == 0.0) {
                EXPECT_EQ(observed, 0.0) << "a light of pmf 0 was chosen";
                continue;
            }
            if (expected < 5.0) {
                pooled_expected += expected;
                pooled_observed += observed;
                continue;
            }
            statistic += (observed - expected) * (observed - expected) / expected;
            ++bins;
        }
        if (pooled_expected >= 5.0) {
            statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                         pooled_expected;
            ++bins;
        }
        ASSERT_GT(bins, 5);
        const double p_value = test::chi_square_upper_tail(statistic, bins - 1);
        EXPECT_GT(p_value, 0.01 / std::size(kPoints))
            << "chi-square " << statistic << " over " << bins << " bins at " << p.x << "," << p.y
            << "," << p.z;
    }
}

// A light the tree gives pmf 0 at a point must send it nothing: every sample_li from
// there comes back empty or black. And the tree does not dismiss everything: most lights
// that can reach the point keep a positive pmf.
TEST(LightTree, PmfIsZeroOnlyForLightsThatCannotReachThePoint) {
    const auto lights = mixed_lights(300);
    const LightSampler sampler(lights, LightSelection::kTree);
    Rng rng(3);
    int zero = 0, reaching = 0, box_faces_dismissed = 0;
    for (const auto& [p, n] : kPoints) {
        for (const auto& [light, piece] : pieces_of(lights)) {
            bool reaches = false;
            for (int i = 0; i < 400 && !reaches; ++i) {
                const auto ls = light->sample_li_piece(p, Vec2(rng.next_float(), rng.next_float()),
                                                       rng.next_float(), piece);
                reaches = ls && !ls->L.is_black() && ls->pdf > 0.0f;
            }
            const float pmf = sampler.pmf(p, n, *light, piece);
            if (pmf == 0.0f) {
                ++zero;
                if (light->piece_count() > 1) ++box_faces_dismissed;
                EXPECT_FALSE(reaches) << "light " << light->index() << " piece " << piece
                                      << " reaches a point where its pmf is 0";
            }
            if (reaches) ++reaching;
        }
    }
    // A box shows each point at most three faces: the tree must dismiss the others' pieces.
    EXPECT_GT(box_faces_dismissed, 10);
    // Quads facing away from a point are about half of all: the test must see both kinds.
    EXPECT_GT(zero, 300);
    EXPECT_GT(reaching, 300);
}

TEST(LightTree, PowerSelectionIsTheSameEverywhere) {
    const auto lights = mixed_lights(20);
    const LightSampler sampler(lights, LightSelection::kPower);
    for (const auto& light : lights) {
        EXPECT_EQ(sampler.pmf(kPoints[1].p, kPoints[1].n, *light), sampler.pmf(*light));
    }
    EXPECT_EQ(sampler.tree(), nullptr);
}

// The build splits subtrees among threads: the tree, and so every pmf and every choice,
// must be the same bits for one thread and for two. Enough lights that the top levels are
// built in parallel (subtrees of 4,096 lights and more).
TEST(LightTree, SameForOneAndTwoThreads) {
    const auto lights = mixed_lights(12000);
    const auto build = [&](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return std::make_unique<LightSampler>(lights, LightSelection::kTree);
    };
    const auto one = build(1);
    const auto two = build(2);
    ASSERT_NE(one->tree(), nullptr);
    EXPECT_EQ(one->tree()->node_count(), two->tree()->node_count());
    int compared = 0;
    const std::vector<Piece> pieces = pieces_of(lights);
    for (const auto& [p, n] : kPoints) {
        for (const auto& [light, piece] : pieces) {
            ASSERT_EQ(std::bit_cast<uint32_t>(one->pmf(p, n, *light, piece)),
                      std::bit_cast<uint32_t>(two->pmf(p, n, *light, piece)))
                << "light " << light->index() << " piece " << piece;
            ++compared;
        }
        Rng rng(13);
        for (int i = 0; i < 2000; ++i) {
            const float u = rng.next_float();
            const LightSampler::Choice a = one->sample(p, n, u), b = two->sample(p, n, u);
            ASSERT_EQ(a.light, b.light);
            ASSERT_EQ(a.piece, b.piece);
            ASSERT_EQ(std::bit_cast<uint32_t>(a.pmf), std::bit_cast<uint32_t>(b.pmf));
        }
    }
    EXPECT_EQ(compared, static_cast<int>(std::size(kPoints) * pieces.size()));
}

namespace {

// Checks a tree over `lights` at the test points: pmfs summing to 1, and every choice
// stating the pmf that pmf() gives.
void expect_consistent(const std::vector<std::unique_ptr<Light>>& lights) {
    const LightSampler sampler(lights, LightSelection::kTree);
    ASSERT_NE(sampler.tree(), nullptr);
    EXPECT_EQ(sampler.tree()->leaf_count(), lights.size());
    for (const auto& [p, n] : kPoints) {
        double sum = 0.0;
        for (const auto& light : lights) sum += sampler.pmf(p, n, *light);
        EXPECT_NEAR(sum, 1.0, 1e-5) << "at " << p.x << "," << p.y << "," << p.z;
        Rng rng(17);
        for (int i = 0; i < 1000; ++i) {
            const LightSampler::Choice c = sampler.sample(p, n, rng.next_float());
            ASSERT_NE(c.light, nullptr);
            EXPECT_GT(c.pmf, 0.0f);
            EXPECT_EQ(c.pmf, sampler.pmf(p, n, *c.light));
        }
    }
}

}  // namespace

// Lights whose centroids all coincide leave no axis to split along; one or two lights are
// the smallest trees. Each still gives a tree whose pmfs sum to 1 and match its choices.
TEST(LightTree, DegenerateInputs) {
    // 200 point lights at one point, of different intensities: every node's children have
    // the same box, so the walk goes by power alone and each light's pmf is its share of the
    // power (up to float rounding along the walk).
    std::vector<std::unique_ptr<Light>> same_point;
    double total = 0.0;
    for (int i = 0; i < 200; ++i) {
        same_point.push_back(
            std::make_unique<PointLight>(Vec3(1.0f, -2.0f, 0.5f), Spectrum(1.0f + i % 7)));
        total += 1.0 + i % 7;
    }
    expect_consistent(same_point);
    const LightSampler sampler(same_point, LightSelection::kTree);
    for (const auto& light : same_point) {
        const double expected = light->power().luminance() / (4.0 * kPi * total);
        EXPECT_NEAR(sampler.pmf(kPoints[2].p, kPoints[2].n, *light), expected, 1e-4 * expected);
    }
    // Quads at one place, facing every way: coincident centroids with different cones.
    std::vector<std::unique_ptr<Light>> same_centre;
    Rng rng(19);
    for (int i = 0; i < 50; ++i)
        same_centre.push_back(
            quad_light(Vec3(0.5f, 0.5f, 0.5f), random_unit(rng), 0.3f, 2.0f, i % 3 == 0));
    expect_consistent(same_centre);

    std::vector<std::unique_ptr<Light>> two;
    two.push_back(std::make_unique<PointLight>(Vec3(1, 0, 0), Spectrum(1.0f)));
    two.push_back(quad_light(Vec3(-1, 1, 0), Vec3(0, -1, 0), 0.5f, 3.0f, false));
    expect_consistent(two);

    // One light of one piece needs no tree: it is chosen with probability 1.
    std::vector<std::unique_ptr<Light>> one;
    one.push_back(std::make_unique<PointLight>(Vec3(2, 2, 2), Spectrum(1.0f)));
    const LightSampler single(one, LightSelection::kTree);
    EXPECT_EQ(single.tree(), nullptr);
    EXPECT_EQ(single.selection(), LightSelection::kTree);
    EXPECT_EQ(single.pmf(kPoints[0].p, kPoints[0].n, *one[0]), 1.0f);
    EXPECT_EQ(single.sample(kPoints[0].p, kPoints[0].n, 0.7f).light, one[0].get());
}

// A chain that the split cost peels one light at a time: point lights along x at 1.8^k,
// each twice as bright as the one before, round a cluster of 16 at the start. A light's
// path in the tree is retraced in 64 steps at most (pmf()): the build must switch to median
// splits before the chain (66 levels and more) would go deeper than that, or the pmfs of
// the deepest lights, which dominate near the cluster, would come out wrong.
TEST(LightTree, DeepChainStaysWithin64Levels) {
    std::vector<std::unique_ptr<Light>> lights;
    for (int i = 0; i < 16; ++i)
        lights.push_back(std::make_unique<PointLight>(Vec3(0, -1, 0), Spectrum(1.0f)));
    for (int k = 0; k < 66; ++k)
        lights.push_back(
            std::make_unique<PointLight>(Vec3(std::pow(1.8f, static_cast<float>(k)), -1, 0),
                                         Spectrum(std::pow(3.0f, static_cast<float>(k)))));
    expect_consistent(lights);
}

// The four lanes of LightBoundsX4 are computed at once: each must give what its bounds give
// alone, whatever the other lanes hold, and the simple cases their closed forms.
TEST(LightBoundsX4, LanesAreIndependentAndMatchClosedForms) {
    // A point light of power 4 at the origin (a point box, every direction), seen from 2
    // away by a surface facing it: 4 / 2^2.
    LightBounds point;
    point.bounds = Bounds3{Vec3(0.0f), Vec3(0.0f)};
    point.phi = 4.0f;
    point.normals = DirectionCone::whole_sphere();
    point.cos_theta_e = std::cos(0.5f * kPi);
    const Vec3 p(0, 0, 2), facing(0, 0, -1);
    EXPECT_NEAR(point.importance(p, facing), 1.0f, 1e-6f);
    // A one-sided panel facing +z below p reaches it; facing -z it cannot.
    LightBounds up;
    up.bounds = Bounds3{Vec3(-0.1f, -0.1f, 0.0f), Vec3(0.1f, 0.1f, 0.0f)};
    up.phi = 2.0f;
    up.normals = DirectionCone{Vec3(0, 0, 1), 1.0f, false};
    up.cos_theta_e = 0.0f;
    LightBounds down = up;
    down.normals.axis = Vec3(0, 0, -1);
    EXPECT_GT(up.importance(p, facing), 0.0f);
    EXPECT_EQ(down.importance(p, facing), 0.0f);
    // Straight above the panel's centre its box subtends a small cone, so the bound is
    // phi / d^2 with both cosines 1.
    EXPECT_NEAR(up.importance(p, facing), 2.0f / 4.0f, 1e-6f);

    // Every arrangement of these (and an empty lane) gives each lane its own value.
    const LightBounds lanes[] = {point, up, down, LightBounds{}};
    Rng rng(23);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 q(4.0f * rng.next_float() - 2.0f, 4.0f * rng.next_float() - 2.0f,
                     4.0f * rng.next_float() - 2.0f);
        const Vec3 n = trial % 3 == 0 ? Vec3(0.0f) : random_unit(rng);
        LightBoundsX4 four;
        int order[4] = {trial % 4, (trial + 1) % 4, (trial + 2) % 4, (trial + 3) % 4};
        for (int lane = 0; lane < 4; ++lane) four.set(lane, lanes[order[lane]]);
        const std::array<float, 4> got = four.importances(q, n);
        for (int lane = 0; lane < 4; ++lane)
            ASSERT_EQ(got[lane], lanes[order[lane]].importance(q, n)) << "lane " << lane;
    }
}

TEST(DirectionCone, MergedHoldsBothCones) {
    Rng rng(5);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const DirectionCone a{random_unit(rng), std::cos(3.0f * rng.next_float()), false};
        const DirectionCone b{random_unit(rng), std::cos(3.0f * rng.next_float()), false};
        const DirectionCone m = DirectionCone::merged(a, b);
        for (const DirectionCone& c : {a, b}) {
            // The cone's edge directions: the axis turned by its full angle.
            const Frame f = Frame::from_normal(c.axis);
            const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - c.cos_theta * c.cos_theta));
            for (int k = 0; k < 8; ++k) {
                const float phi = 2.0f * kPi * k / 8.0f;
                const Vec3 w = f.to_world(
                    Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), c.cos_theta));
                EXPECT_GE(glm::dot(w, m.axis), m.cos_theta - 1e-4f);
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 2000 * 2 * 8);
}
