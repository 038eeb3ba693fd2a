// Beer-Lambert absorption inside glass, as every integrator renders it: a diffuse floor lit
// by a wide emitter through a thick slab of tinted glass. Only the path tracer's result was
// tested before (test_path's slab); here light tracing, bdpt, vcm, mlt and sppm must agree
// with it within their noise (issue 28). The glass halves the red and removes
// nine tenths of the blue on the way down, so an integrator that skipped the absorption
// would be off by far more than the noise.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/image_comparison.h>
#include <support/render_helpers.h>

#include <cmath>
#include <string>

using namespace glint;
using namespace glint::test;

namespace {

// The floor (z = 0) seen from below the slab (z from 1 to 2), the emitter above it; every
// path from the floor to the light crosses the glass. The wide scene (floor and emitter far
// larger than the view) suits the integrators that start at the camera; light tracing needs
// the small one, where most light paths land on the floor the camera sees whole.
std::string floor_under_glass(const std::string& integrator, int spp, int seed, bool small) {
    const double floor = small ? 1.0 : 50.0, light = small ? 3.0 : 400.0;
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 0, {}}}, look_at = {{0, 0, 0}}, up = {{0, 1, 0}}, fov = {} }}
        glint.render{{ width = 12, height = 12, spp = {}, seed = {}, integrator = '{}',
                      max_depth = 12 }}
        glint.quad{{ vertices = {{ {{-{f}, -{f}, 0}}, {{{f}, -{f}, 0}}, {{{f}, {f}, 0}}, {{-{f}, {f}, 0}} }},
                    material = glint.diffuse{{ reflectance = 0.5 }} }}
        glint.box{{ min = {{-1000, -1000, 1}}, max = {{1000, 1000, 2}},
                   material = glint.dielectric{{ ior = 1.5, absorption = {{0.7, 0.2, 2.3}} }} }}
        glint.quad{{ vertices = {{ {{-{l}, -{l}, 6}}, {{-{l}, {l}, 6}}, {{{l}, {l}, 6}}, {{{l}, -{l}, 6}} }},
                    material = glint.emissive{{ radiance = 1 }} }}
    )",
                       small ? 0.9 : 0.5, small ? 100 : 40, spp, seed, integrator,
                       fmt::arg("f", floor), fmt::arg("l", light));
}

struct Case {
    const char* integrator;
    int spp;
    bool small;
};

}  // namespace

// Each channel's image mean within four standard errors (of both) of the path tracer's,
// plus 1 % for the merging integrators' kernel; the noise itself below a quarter of the
// mean, fine enough to see a missing absorption (a factor of 2.3 in red, 14 in blue here).
// The preview is not among them: it is biased here (docs/robustness.md, issue 28 item 3:
// the strongly absorbed blue comes out about 30 % too bright on the wide scene, and the
// small scene's floor some 18 times too dark, absorption or not); it joins once fixed.
TEST(AbsorptionSlow, EveryIntegratorAgreesWithThePathTracerThroughTintedGlass) {
    const Case cases[] = {{"light", 128, true},
                          {"bdpt", 16, false},
                          {"vcm", 32, false},
                          {"mlt", 16, false},
                          {"sppm", 32, false}};
    Estimate reference[2][3];
    for (const bool small : {false, true}) {
        for (int c = 0; c < 3; c += 2) {
            reference[small][c] = image_mean(
                [&](int seed) { return floor_under_glass("path", 128, 100 + seed, small); }, 4, c);
        }
        // The absorption matters: blue is well below red (without it they would be equal).
        ASSERT_LT(reference[small][2].mean, 0.5 * reference[small][0].mean);
    }
    for (const Case& k : cases) {
        SCOPED_TRACE(k.integrator);
        for (int c = 0; c < 3; c += 2) {
            const Estimate& ref = reference[k.small][c];
            const Estimate e = image_mean(
                [&](int seed) { return floor_under_glass(k.integrator, k.spp, seed, k.small); }, 4,
                c);
            const double noise = 4.0 * std::hypot(e.se, ref.se);
            fmt::print("{} channel {}: {:.5f} +- {:.5f} (path {:.5f} +- {:.5f})\n", k.integrator, c,
                       e.mean, e.se, ref.mean, ref.se);
            EXPECT_LT(noise, 0.25 * ref.mean) << "channel " << c;
            EXPECT_NEAR(e.mean, ref.mean, noise + 0.01 * ref.mean) << "channel " << c;
        }
    }
}
