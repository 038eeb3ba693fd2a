// Transport modes and delta lobes (material/bsdf.h), for every BSDF the material registry
// builds: importance mode is the adjoint of radiance mode, sample() agrees with eval() and
// pdf() in both modes, the shading-normal correction is applied in importance mode only,
// and delta_lobes() lists exactly the delta lobes sample() chooses from, with their weights.
#include <glint/core/arena.h>
#include <glint/core/params.h>
#include <glint/core/rng.h>
#include <glint/material/registry.h>
#include <glint/material/texture/texture_table.h>
#include <glint/math/warp.h>

#include <gtest/gtest.h>
#include <support/test_util.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace glint;
using glint::test::direction;

namespace {

struct BsdfCase {
    std::string name;
    std::string type;
    std::function<void(Params&)> set;
};

std::vector<BsdfCase> bsdf_cases() {
    using V = std::vector<double>;
    return {
        {"diffuse", "diffuse",
         [](Params& p) {
             p.set("reflectance", V{0.8, 0.5, 0.2});
         }},
        {"mirror", "mirror",
         [](Params& p) {
             p.set("tint", V{0.9, 0.7, 0.4});
         }},
        {"smooth_glass", "dielectric", [](Params& p) { p.set("ior", 1.5); }},
        {"smooth_water_inverted", "dielectric", [](Params& p) { p.set("ior", 1.0 / 1.33); }},
        {"rough_glass", "dielectric",
         [](Params& p) {
             p.set("ior", 1.5);
             p.set("roughness", 0.5);
         }},
        {"smooth_gold", "conductor",
         [](Params& p) {
             p.set("preset", std::string("gold"));
             p.set("roughness", 0.0);
         }},
        {"rough_copper", "conductor",
         [](Params& p) {
             p.set("preset", std::string("copper"));
             p.set("roughness", 0.4);
             p.set("anisotropy", 0.5);
         }},
        {"smooth_plastic", "plastic",
         [](Params& p) {
             p.set("diffuse", V{0.7, 0.3, 0.1});
             p.set("roughness", 0.0);
         }},
        {"rough_plastic", "plastic",
         [](Params& p) {
             p.set("diffuse", V{0.2, 0.6, 0.9});
             p.set("roughness", 0.5);
         }},
        {"phong", "phong",
         [](Params& p) {
             p.set("diffuse", V{0.5, 0.4, 0.3});
             p.set("specular", V{0.3, 0.3, 0.3});
             p.set("exponent", 20.0);
         }},
        {"blinn", "phong",
         [](Params& p) {
             p.set("model", std::string("blinn"));
             p.set("diffuse", V{0.5, 0.4, 0.3});
             p.set("specular", V{0.3, 0.3, 0.3});
             p.set("exponent", 20.0);
         }},
        {"principled_all_lobes", "principled",
         [](Params& p) {
             p.set("base_color", V{0.8, 0.5, 0.2});
             p.set("metallic", 0.3);
             p.set("roughness", 0.4);
             p.set("transmission", 0.5);
             p.set("clearcoat", 0.7);
             p.set("clearcoat_roughness", 0.2);
             p.set("sheen", 1.0);
         }},
        {"principled_glass", "principled",
         [](Params& p) {
             p.set("base_color", V{0.9, 0.8, 0.7});
             p.set("transmission", 1.0);
             p.set("roughness", 0.3);
             p.set("ior", 1.33);
         }},
    };
}

// A geometric normal tilted away from the shading normal, as a bump map or interpolated
// normals leave it, in the local shading frame.
const Vec3 kTiltedNg = glm::normalize(Vec3(0.35f, -0.2f, 1.0f));

// Veach's correction written out here, in double, independently of bsdf.h.
double correction(const Vec3& wo, const Vec3& wi, const Vec3& ng) {
    const double numerator = std::abs(double(wo.z)) * std::abs(glm::dot(wi, ng));
    const double denominator = std::abs(glm::dot(wo, ng)) * std::abs(double(wi.z));
    return numerator / denominator;
}

bool close(double a, double b, double relative, double absolute = 1e-30) {
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + absolute;
}

bool close(const Spectrum& a, const Spectrum& b, double relative, double absolute = 1e-30) {
    for (int c = 0; c < 3; ++c) {
        if (!close(to_rgb(a)[c], to_rgb(b)[c], relative, absolute)) return false;
    }
    return true;
}

std::string text(const Spectrum& s) {
    return "(" + std::to_string(to_rgb(s).r) + ", " + std::to_string(to_rgb(s).g) + ", " +
           std::to_string(to_rgb(s).b) + ")";
}

std::string text(const Vec3& w) {
    return "(" + std::to_string(w.x) + ", " + std::to_string(w.y) + ", " + std::to_string(w.z) +
           ")";
}

// The outgoing directions every test looks from: both sides, normal to grazing.
std::vector<Vec3> outgoing_directions() {
    return {direction(0.0f),
            direction(30.0f, 0.4f),
            direction(65.0f, 2.5f),
            direction(86.0f, -1.0f),
            direction(20.0f, 1.3f, true),
            direction(55.0f, 4.0f, true),
            direction(80.0f, 0.2f, true)};
}

// Names the case in test output instead of dumping its bytes.
void PrintTo(const BsdfCase& c, std::ostream* os) {
    *os << c.name;
}

class BsdfModes : public testing::TestWithParam<BsdfCase> {
protected:
    void SetUp() override {
        Params params(GetParam().type, "test_bsdf_modes.cpp:1");
        GetParam().set(params);
        m_material = make_material(params, m_textures);
        SurfaceInteraction si;
        si.uv = Vec2(0.3f, 0.6f);
        si.ng = Vec3(0, 0, 1);
        m_bsdf = m_material->bsdf(si, m_arena);
        ASSERT_NE(m_bsdf, nullptr);
    }

    const Bsdf& bsdf() const { return *m_bsdf; }
    bool has_delta() const { return bsdf().flags() & kBsdfDelta; }
    bool refracts() const { return bsdf().flags() & kBsdfTransmission; }

private:
    TextureTable m_textures{".", true};
    std::unique_ptr<Material> m_material;
    Arena m_arena;
    const Bsdf* m_bsdf = nullptr;
};

// f*(wo, wi) = f(wi, wo): importance mode evaluated one way is radiance mode the other way,
// for reflection and for refraction (where radiance carries 1/eta^2 and importance does not).
TEST_P(BsdfModes, ImportanceIsTheAdjointOfRadiance) {
    Rng rng(31);
    int nonzero_reflections = 0, nonzero_refractions = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 wo = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 wi = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Spectrum importance = bsdf().eval(wo, wi, TransportMode::kImportance);
        const Spectrum adjoint = bsdf().eval(wi, wo, TransportMode::kRadiance);
        ASSERT_TRUE(close(importance, adjoint, 2e-4, 1e-10))
            << "wo " << text(wo) << ", wi " << text(wi) << ": importance " << text(importance)
            << ", radiance adjoint " << text(adjoint);
        if (!importance.is_black())
            ++(same_hemisphere(wo, wi) ? nonzero_reflections : nonzero_refractions);
    }
    if (!bsdf().is_delta()) {
        EXPECT_GT(nonzero_reflections, 1000);
    }
    if (refracts() && !bsdf().is_delta()) {
        EXPECT_GT(nonzero_refractions, 1000);
    }
}

// The same for delta lobes, as distributions: the adjoint of a lobe wo -> wi of weight
// c = f |cos wi| is the lobe wi -> wo, and the delta's Jacobian d(omega_o) / d(omega_i) =
// eta^2 |cos wi| / |cos wo| (eta = n(wi side) / n(wo side), Veach 1997 sec. 5.2) gives
// c_importance(wo -> wi) eta^2 = c_radiance(wi -> wo).
TEST_P(BsdfModes, DeltaLobesImportanceIsTheAdjointOfRadiance) {
    if (!has_delta()) {
        EXPECT_EQ(bsdf().delta_lobes(direction(30.0f), TransportMode::kImportance).count, 0);
        return;
    }
    int refractions = 0;
    for (const Vec3& wo : outgoing_directions()) {
        for (const BsdfSample& lobe : bsdf().delta_lobes(wo, TransportMode::kImportance)) {
            const Spectrum c_importance = lobe.f * abs_cos_theta(lobe.wi);
            const BsdfSample* back = nullptr;
            const DeltaLobes radiance = bsdf().delta_lobes(lobe.wi, TransportMode::kRadiance);
            for (const BsdfSample& r : radiance) {
                if (glm::length(r.wi - wo) < 1e-5f) back = &r;
            }
            ASSERT_NE(back, nullptr)
                << "wo " << text(wo) << ": no lobe back from " << text(lobe.wi);
            const Spectrum c_radiance = back->f * abs_cos_theta(back->wi);
            EXPECT_TRUE(close(c_importance * (lobe.eta * lobe.eta), c_radiance, 1e-4))
                << "wo " << text(wo) << (lobe.is_transmission() ? " refraction" : " reflection")
                << ": importance " << text(c_importance) << " eta " << lobe.eta
                << ", radiance back " << text(c_radiance);
            refractions += lobe.is_transmission();
        }
    }
    if (refracts()) {
        EXPECT_GT(refractions, 3);
    }
}

// A sample's f and pdf are what eval() and pdf() give for its direction, in the same mode
// and with the same geometric normal; delta samples have eval() = pdf() = 0.
TEST_P(BsdfModes, SampleAgreesWithEvalAndPdfInBothModes) {
    Rng rng(37);
    for (const TransportMode mode : {TransportMode::kRadiance, TransportMode::kImportance}) {
        for (const Vec3& ng : {Vec3(0, 0, 1), kTiltedNg}) {
            for (const Vec3& wo : outgoing_directions()) {
                int samples = 0, bad = 0;
                std::string first_bad;
                for (int i = 0; i < 2000; ++i) {
                    const Vec2 u(rng.next_float(), rng.next_float());
                    const auto s = bsdf().sample(wo, u, rng.next_float(), mode, ng);
                    if (!s) continue;
                    ++samples;
                    bool ok;
                    if (s->is_delta()) {
                        // Weights of delta samples are checked against delta_lobes() below;
                        // eval() and pdf() give only a mixed BSDF's other lobes there.
                        ok = s->pdf > 0.0f &&
                             (!bsdf().is_delta() || (bsdf().eval(wo, s->wi, mode, ng).is_black() &&
                                                     bsdf().pdf(wo, s->wi) == 0.0f));
                    } else {
                        float pdf = -1.0f;
                        const Spectrum f_pdf = bsdf().eval_pdf(wo, s->wi, pdf, mode, ng);
                        const Spectrum f = bsdf().eval(wo, s->wi, mode, ng);
                        ok = close(s->pdf, bsdf().pdf(wo, s->wi), 1e-4) && close(s->f, f, 1e-4) &&
                             f_pdf == f && pdf == bsdf().pdf(wo, s->wi);
                    }
                    if (!ok && bad++ == 0) {
                        first_bad = "wi " + text(s->wi) + ", f " + text(s->f) + ", eval " +
                                    text(bsdf().eval(wo, s->wi, mode, ng)) + ", pdf " +
                                    std::to_string(s->pdf) + " against " +
                                    std::to_string(bsdf().pdf(wo, s->wi));
                    }
                }
                EXPECT_EQ(bad, 0) << (mode == TransportMode::kRadiance ? "radiance" : "importance")
                                  << ", ng " << text(ng) << ", wo " << text(wo) << ": "
                                  << first_bad;
                EXPECT_GT(samples, 0) << "wo " << text(wo);
            }
        }
    }
}

// With ng != ns, importance mode is the radiance adjoint times |wo.ns| |wi.ng| /
// (|wo.ng| |wi.ns|); radiance mode ignores ng. Delta lobes are scaled the same way.
TEST_P(BsdfModes, ShadingNormalCorrectionInImportanceModeOnly) {
    Rng rng(41);
    int corrected = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 wo = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 wi = warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
        const Spectrum radiance = bsdf().eval(wo, wi, TransportMode::kRadiance, kTiltedNg);
        ASSERT_TRUE(radiance == bsdf().eval(wo, wi)) << "radiance mode must not use ng";
        const double factor = correction(wo, wi, kTiltedNg);
        if (!std::isfinite(factor) || factor > 1e4) continue;  // grazing the geometric plane
        const Spectrum importance = bsdf().eval(wo, wi, TransportMode::kImportance, kTiltedNg);
        const Spectrum expected = bsdf().eval(wi, wo, TransportMode::kRadiance) * float(factor);
        ASSERT_TRUE(close(importance, expected, 3e-4, 1e-10))
            << "wo " << text(wo) << ", wi " << text(wi) << ": " << text(importance) << " against "
            << text(expected) << " (factor " << factor << ")";
        corrected += !importance.is_black() && std::abs(factor - 1.0) > 0.05;
    }
    if (!bsdf().is_delta()) {
        EXPECT_GT(corrected, 1000);
    }

    for (const Vec3& wo : outgoing_directions()) {
        const DeltaLobes plain = bsdf().delta_lobes(wo, TransportMode::kImportance);
        const DeltaLobes tilted = bsdf().delta_lobes(wo, TransportMode::kImportance, kTiltedNg);
        const DeltaLobes radiance = bsdf().delta_lobes(wo, TransportMode::kRadiance, kTiltedNg);
        const DeltaLobes untilted = bsdf().delta_lobes(wo, TransportMode::kRadiance);
        ASSERT_EQ(plain.count, tilted.count);
        ASSERT_EQ(radiance.count, untilted.count);
        for (int l = 0; l < plain.count; ++l) {
            const Spectrum expected =
                plain.lobes[l].f * float(correction(wo, plain.lobes[l].wi, kTiltedNg));
            EXPECT_TRUE(close(tilted.lobes[l].f, expected, 1e-5))
                << "wo " << text(wo) << ": " << text(tilted.lobes[l].f) << " against "
                << text(expected);
            EXPECT_TRUE(radiance.lobes[l].f == untilted.lobes[l].f);
        }
    }
}

// delta_lobes() is sample() summed over u_lobe: each lobe's weight f |cos wi| is the
// expectation of f |cos wi| / pdf over the delta samples in its direction, for stratified
// u_lobe (the sum is exact up to one stratum per lobe boundary), in both modes and with a
// tilted geometric normal. BSDFs without delta lobes list none and sample none.
TEST_P(BsdfModes, DeltaLobesAreTheExpectationOfSample) {
    constexpr int kStrata = 20000;
    struct Mode {
        TransportMode mode;
        Vec3 ng;
    };
    const Mode modes[] = {{TransportMode::kRadiance, Vec3(0, 0, 1)},
                          {TransportMode::kImportance, Vec3(0, 0, 1)},
                          {TransportMode::kImportance, kTiltedNg}};
    for (const Mode& m : modes) {
        for (const Vec3& wo : outgoing_directions()) {
            const DeltaLobes lobes = bsdf().delta_lobes(wo, m.mode, m.ng);
            const std::string where =
                std::string(m.mode == TransportMode::kRadiance ? "radiance" : "importance") +
                ", ng " + text(m.ng) + ", wo " + text(wo);
            if (!has_delta()) {
                EXPECT_EQ(lobes.count, 0) << where;
            }
            double sums[2][3] = {};
            double largest = 0.0;  // the largest single sample weight, for the stratum bound
            int strays = 0;
            for (int k = 0; k < kStrata; ++k) {
                const float u_lobe = (k + 0.5f) / kStrata;
                const auto s = bsdf().sample(wo, Vec2(0.37f, 0.61f), u_lobe, m.mode, m.ng);
                if (!s || !s->is_delta()) continue;
                int match = -1;
                for (int l = 0; l < lobes.count; ++l) {
                    if (glm::length(lobes.lobes[l].wi - s->wi) < 1e-6f &&
                        lobes.lobes[l].flags == s->flags && lobes.lobes[l].eta == s->eta) {
                        match = l;
                    }
                }
                if (match < 0) {
                    ++strays;
                    continue;
                }
                for (int c = 0; c < 3; ++c) {
                    const double w = to_rgb(s->f)[c] * abs_cos_theta(s->wi) / s->pdf;
                    sums[match][c] += w;
                    largest = std::max(largest, w);
                }
            }
            EXPECT_EQ(strays, 0) << where << ": delta samples outside the listed lobes";
            for (int l = 0; l < lobes.count; ++l) {
                const BsdfSample& lobe = lobes.lobes[l];
                EXPECT_EQ(lobe.pdf, 1.0f) << where;
                EXPECT_TRUE(lobe.is_delta()) << where;
                for (int c = 0; c < 3; ++c) {
                    const double weight = to_rgb(lobe.f)[c] * abs_cos_theta(lobe.wi);
                    EXPECT_GT(weight, 0.0) << where;
                    EXPECT_NEAR(sums[l][c] / kStrata, weight, 2.0 * largest / kStrata + 1e-6)
                        << where << ", lobe " << l
                        << (lobe.is_transmission() ? " (refraction)" : " (reflection)")
                        << ", channel " << c;
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(EveryBsdf, BsdfModes, testing::ValuesIn(bsdf_cases()),
                         [](const testing::TestParamInfo<BsdfCase>& info) {
                             return info.param.name;
                         });

// Glass from inside beyond the critical angle reflects totally: one lobe of weight 1.
TEST(DeltaLobes, TotalInternalReflectionIsOneLobe) {
    TextureTable textures(".", true);
    Params params("dielectric", "test_bsdf_modes.cpp:1");
    params.set("ior", 1.5);
    const auto material = make_material(params, textures);
    Arena arena;
    const Bsdf* bsdf = material->bsdf(SurfaceInteraction(), arena);
    for (const TransportMode mode : {TransportMode::kRadiance, TransportMode::kImportance}) {
        const DeltaLobes lobes = bsdf->delta_lobes(direction(60.0f, 0.3f, true), mode);
        ASSERT_EQ(lobes.count, 1);
        EXPECT_FALSE(lobes.lobes[0].is_transmission());
        EXPECT_NEAR(to_rgb(lobes.lobes[0].f).r * abs_cos_theta(lobes.lobes[0].wi), 1.0f, 1e-6f);
        // Outside, the refraction in radiance mode is (1 - R) / eta^2; in importance mode 1 - R.
        const DeltaLobes outside = bsdf->delta_lobes(direction(0.0f), mode);
        ASSERT_EQ(outside.count, 2);
        const float r = 0.04f, t = mode == TransportMode::kRadiance ? 0.96f / 2.25f : 0.96f;
        EXPECT_NEAR(to_rgb(outside.lobes[0].f).r * abs_cos_theta(outside.lobes[0].wi), r, 1e-6f);
        EXPECT_NEAR(to_rgb(outside.lobes[1].f).r * abs_cos_theta(outside.lobes[1].wi), t, 1e-6f);
    }
}

}  // namespace
