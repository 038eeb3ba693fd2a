// Beer-Lambert absorption inside glass, as every integrator renders it: a diffuse floor lit
// by a wide emitter through a thick slab of tinted glass. Only the path tracer's result was
// tested before (test_path's slab); here light tracing, bdpt, vcm, mlt, sppm and the preview
// must agree with it within their noise (issue 28). The glass halves the red and removes
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
// path from the floor to the light crosses the glass.
std::string floor_under_glass(const std::string& integrator, int spp, int seed) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 0.5}}, look_at = {{0, 0, 0}}, up = {{0, 1, 0}}, fov = 40 }}
        glint.render{{ width = 12, height = 12, spp = {}, seed = {}, integrator = '{}',
                      max_depth = 12 }}
        glint.quad{{ vertices = {{ {{-50, -50, 0}}, {{50, -50, 0}}, {{50, 50, 0}}, {{-50, 50, 0}} }},
                    material = glint.diffuse{{ reflectance = 0.5 }} }}
        glint.box{{ min = {{-1000, -1000, 1}}, max = {{1000, 1000, 2}},
                   material = glint.dielectric{{ ior = 1.5, absorption = {{0.7, 0.2, 2.3}} }} }}
        glint.quad{{ vertices = {{ {{-400, -400, 6}}, {{-400, 400, 6}}, {{400, 400, 6}}, {{400, -400, 6}} }},
                    material = glint.emissive{{ radiance = 1 }} }}
    )",
                       spp, seed, integrator);
}

struct Case {
    const char* integrator;
    int spp;
    int images;
};

}  // namespace

TEST(Absorption, EveryIntegratorAgreesWithThePathTracerThroughTintedGlass) {
    const Case cases[] = {{"light", 32, 4}, {"bdpt", 16, 4}, {"vcm", 16, 4},
                          {"mlt", 16, 4},   {"sppm", 16, 4}, {"preview", 16, 4}};
    Estimate reference[3];
    for (int c = 0; c < 3; c += 2) {
        reference[c] =
            image_mean([](int seed) { return floor_under_glass("path", 128, 100 + seed); }, 4, c);
        fmt::print("path channel {}: {:.5f} +- {:.5f}\n", c, reference[c].mean, reference[c].se);
    }
    // The absorption matters: blue is well below red (without it they would be equal).
    ASSERT_LT(reference[2].mean, 0.5 * reference[0].mean);
    for (const Case& k : cases) {
        SCOPED_TRACE(k.integrator);
        for (int c = 0; c < 3; c += 2) {
            const Estimate e =
                image_mean([&](int seed) { return floor_under_glass(k.integrator, k.spp, seed); },
                           k.images, c);
            const double noise = 4.0 * std::hypot(e.se, reference[c].se);
            fmt::print("{} channel {}: {:.5f} +- {:.5f} (path {:.5f})\n", k.integrator, c, e.mean,
                       e.se, reference[c].mean);
            // Fine enough to see a missing absorption (a factor of 1.5 to 10 here).
            EXPECT_LT(noise, 0.1 * reference[c].mean) << "channel " << c;
            EXPECT_NEAR(e.mean, reference[c].mean, noise + 0.01 * reference[c].mean)
                << "channel " << c;
        }
    }
}
