// The real-time preview: its caustic converges to sppm's, photons survive a camera move
// and not a light move, and the image is the same for any thread count.
#include <glint/core/progress.h>
#include <glint/core/rng.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/preview.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace glint;

namespace {

// A glass sphere above a diffuse floor, lit by a point light above and to the side: the
// sphere focuses the light into a bright caustic on the floor beside it.
std::string caustic_scene(const std::string& render) {
    return fmt::format(R"(
        glint.render{{ width = 64, height = 48, {} }}
        glint.camera{{ eye = {{0, 3.2, 3.4}}, look_at = {{0.5, 0, 0}}, fov = 40 }}
        glint.quad{{ vertices = {{{{-4, 0, 4}}, {{4, 0, 4}}, {{4, 0, -4}}, {{-4, 0, -4}}}},
                    material = glint.diffuse{{ reflectance = 0.7 }} }}
        glint.sphere{{ center = {{0, 0.9, 0}}, radius = 0.6, material = glint.dielectric{{ ior = 1.5 }} }}
        glint.point_light{{ position = {{-2.5, 4, 0}}, intensity = 30 }}
    )",
                       render);
}

// The caustic's pixels in caustic_scene: the bright spot on the floor beside the sphere
// and the sphere's shadow around it.
constexpr int kX0 = 27, kY0 = 16, kX1 = 43, kY1 = 32;

Image crop(const Image& image, int x0, int y0, int x1, int y1) {
    Image region = make_image(x1 - x0, y1 - y0, {"R", "G", "B"});
    for (int c = 0; c < 3; ++c)
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) region.at(x - x0, y - y0, c) = image.at(x, y, c);
    return region;
}

double region_error(const Image& test, const Image& reference) {
    return compare_images(crop(test, kX0, kY0, kX1, kY1), crop(reference, kX0, kY0, kX1, kY1))
        .rel_mse;
}

using test::BuiltScene;

BuiltScene build_scene(const std::string& code) {
    return test::build_lua(code, "preview-test.lua");
}

}  // namespace

// The preview's caustic region approaches sppm's image as passes accumulate. The ambient
// term is off: it is a documented bias (sppm carries the true indirect light, which here is
// nearly nothing). Expected relative MSE against the reference = the preview's noise + the
// reference's noise + bias^2; both noises are measured from pairs of independent renders,
// and the bound allows twice them (their estimates fluctuate) plus 0.005 for the bias: the
// blur of the final radius (0.013 after 64 passes, a tenth of a pixel's footprint) and
// the light that bounces off the floor through the glass, which sppm has and the preview
// does not.
TEST(PreviewSlow, CausticConvergesToSppm) {
    auto sppm = [&](int seed) {
        return test::render_lua(caustic_scene(fmt::format(
            "integrator = 'sppm', spp = 128, photons = 20000, photon_radius = 0.1, seed = {}",
            seed)));
    };
    const Image sppm_a = sppm(7), sppm_b = sppm(8);
    Image reference = sppm_a;
    for (size_t i = 0; i < reference.pixels.size(); ++i)
        reference.pixels[i] = 0.5f * (sppm_a.pixels[i] + sppm_b.pixels[i]);
    // One render's relative variance is half the pair's relative MSE; the mean of two has
    // half that.
    const double reference_noise = region_error(sppm_a, sppm_b) / 4.0;

    auto preview = [&](int passes, int seed) {
        return test::render_lua(caustic_scene(fmt::format(
            "integrator = 'preview', spp = {}, preview_ambient = 0, seed = {}", passes, seed)));
    };
    const double early = region_error(preview(4, 1), reference);
    const Image late = preview(64, 1);
    const double error = region_error(late, reference);
    const double noise = region_error(preview(64, 2), late) / 2.0;
    std::printf(
        "relative MSE over the caustic: 4 passes %.4f, 64 passes %.4f (noise %.4f, "
        "reference noise %.4f)\n",
        early, error, noise, reference_noise);
    EXPECT_LT(error, 0.6 * early);
    EXPECT_LT(error, 2.0 * (noise + reference_noise) + 0.005);
}

// A camera move keeps the photons and the shrinking radius; a light move drops them.
TEST(Preview, CameraChangeKeepsPhotonsLightChangeDropsThem) {
    BuiltScene b = build_scene(caustic_scene("integrator = 'preview', preview_photons = 5000"));
    auto integrator = make_integrator(b.settings);
    auto* preview = dynamic_cast<PreviewIntegrator*>(integrator.get());
    ASSERT_NE(preview, nullptr);
    auto* progressive = dynamic_cast<ProgressiveIntegrator*>(integrator.get());
    ASSERT_NE(progressive, nullptr);
    Film film(b.settings.width, b.settings.height, false);
    Progress progress("test", 1, true);

    for (int pass = 0; pass < 3; ++pass) progressive->render_pass(*b.scene, film, pass, progress);
    EXPECT_EQ(preview->photon_passes(), 3);
    const size_t photons = preview->stored_photons();
    const float radius = preview->radius();
    EXPECT_GT(photons, 0u);

    progressive->scene_changed(SceneChange::camera);
    film.clear();
    progressive->render_pass(*b.scene, film, 0, progress);
    EXPECT_EQ(preview->photon_passes(), 4);
    EXPECT_GT(preview->stored_photons(), photons);  // one more batch on top of the three
    EXPECT_LT(preview->radius(), radius);           // the schedule goes on

    progressive->scene_changed(SceneChange::lights_or_objects);
    film.clear();
    progressive->render_pass(*b.scene, film, 0, progress);
    EXPECT_EQ(preview->photon_passes(), 1);
    EXPECT_LT(preview->stored_photons(), photons);  // one batch only
}

// An analytic caustic: a spot light of intensity I at height h over a Lambertian floor
// (albedo rho) shines up, with a sharp cone of 30 degrees, at a horizontal mirror ceiling of
// tint t at height H. The floor gets no direct light, only the mirror's reflection (caustic
// photons), as if from a light of intensity t I at the mirror image of the spot, height
// 2H - h, whose cone covers the view: L = rho / pi t I (2H - h) / d^3.
// Block means of 8 x 8 pixels must agree within 3 %: the largest deviation of the 16 blocks
// is 2.3 % after 32 passes and 1.0 % after 128 (so it is the photons' noise, not a bias),
// about 1.5 % after the 64 passes here. Light that the floor reflects back to the mirror
// is left out on both sides (the preview carries no indirect light; its ambient term is off).
TEST(PreviewSlow, MirrorCeilingCausticMatchesClosedForm) {
    const int res = 32;
    const float fov = 60.0f, camera_height = 1.5f, h = 0.5f, H = 2.0f, rho = 0.5f, t = 0.8f,
                intensity = 4.0f;
    const Image image = test::render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, {}, 0}}, look_at = {{0, 0, 0}}, up = {{0, 0, -1}}, fov = {} }}
        glint.render{{ width = {}, height = {}, spp = 64, integrator = 'preview',
                       preview_ambient = 0, seed = 3 }}
        glint.spot_light{{ position = {{0, {}, 0}}, look_at = {{0, 10, 0}}, intensity = {},
                           cone_angle = 30, falloff_start = 30 }}
        glint.quad{{ vertices = {{ {{-50, 0, 50}}, {{50, 0, 50}}, {{50, 0, -50}}, {{-50, 0, -50}} }},
                     material = glint.diffuse{{ reflectance = {} }} }}
        glint.quad{{ vertices = {{ {{-50, {}, -50}}, {{50, {}, -50}}, {{50, {}, 50}}, {{-50, {}, 50}} }},
                     material = glint.mirror{{ tint = {} }} }}
    )",
                                                     camera_height, fov, res, res, h, intensity,
                                                     rho, H, H, H, H, t));
    const float tan_half = std::tan(fov * 0.5f * kPi / 180.0f);
    auto expected_at = [&](float x, float y) {
        // Where the ray through film point (x, y) meets the floor (camera looks down -y).
        const float sx = (2.0f * x / res - 1.0f) * tan_half;
        const float sy = (1.0f - 2.0f * y / res) * tan_half;
        const Vec3 p(sx * camera_height, 0.0f, -sy * camera_height);
        const float d = glm::length(Vec3(0.0f, 2.0f * H - h, 0.0f) - p);
        return rho / kPi * intensity * t * (2.0f * H - h) / (d * d * d);
    };
    double worst = 0.0;
    for (int by = 0; by < res; by += 8) {
        for (int bx = 0; bx < res; bx += 8) {
            double measured = 0.0, expected = 0.0;
            for (int y = by; y < by + 8; ++y) {
                for (int x = bx; x < bx + 8; ++x) {
                    measured += image.at(x, y, 1);
                    expected += expected_at(x + 0.5f, y + 0.5f);
                }
            }
            EXPECT_NEAR(measured / expected, 1.0, 0.03) << "block at " << bx << ", " << by;
            worst = std::max(worst, std::abs(measured / expected - 1.0));
        }
    }
    std::printf("largest relative deviation of a block: %.4f\n", worst);
}

// The camera pass's packet form (4 x 2 pixels a packet, shadow rays as a second packet)
// gives each pixel what the one-ray form gives it, bit for bit: the same sample draws, the
// same hits, the same sums in the same order. The scene has every case a lane meets: the
// sky, a visible area light (an emitter without a BSDF), a glass sphere and a mirror (lanes
// that go on alone through specular chains, some escaping), a diffuse floor lit by a spot
// and an area light with shadows, and caustic photons. The film is 63 x 47, so the last
// column and row of blocks are partly outside it. With ReSTIR the first stage's camera rays
// and visibility reuse's shadow rays go in packets the same way, and the reservoirs it hands
// to the next pass and to the second stage must be the same too.
class PreviewPackets : public ::testing::TestWithParam<const char*> {};

TEST_P(PreviewPackets, GiveTheOneRayImageBitForBit) {
    BuiltScene b = build_scene(std::string(R"(
        glint.render{ width = 63, height = 47, integrator = 'preview', preview_photons = 4000,
                      )") + GetParam() + R"( }
        glint.camera{ eye = {0, 1.4, 4}, look_at = {0, 0.7, 0}, fov = 50 }
        glint.background{ radiance = 0.2 }
        glint.quad{ vertices = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}},
                    material = glint.diffuse{ reflectance = 0.7 } }
        glint.sphere{ center = {-0.5, 0.6, 0}, radius = 0.6, material = glint.dielectric{ ior = 1.5 } }
        glint.quad{ vertices = {{0.6, 0, -1}, {1.6, 0, -0.6}, {1.6, 1.2, -0.6}, {0.6, 1.2, -1}},
                    material = glint.mirror{} }
        glint.quad{ vertices = {{-2, 1.8, -1}, {-1, 1.8, -1}, {-1, 1.8, -2}, {-2, 1.8, -2}},
                    material = glint.emissive{ radiance = 4, two_sided = true } }
        glint.spot_light{ position = {-2.5, 4, 0}, look_at = {-0.5, 0, 0}, intensity = 30,
                          cone_angle = 30, falloff_start = 25 }
    )");
    std::vector<Image> images;
    for (const bool packets : {true, false}) {
        auto integrator = make_integrator(b.settings);
        auto* preview = dynamic_cast<PreviewIntegrator*>(integrator.get());
        ASSERT_NE(preview, nullptr);
        preview->set_packets(packets);
        Film film(b.settings.width, b.settings.height, false);
        Progress progress("test", 1, true);
        for (int pass = 0; pass < 3; ++pass) preview->render_pass(*b.scene, film, pass, progress);
        images.push_back(film.resolve());
    }
    ASSERT_EQ(images[0].pixels.size(), images[1].pixels.size());
    size_t differing = 0, lit = 0;
    for (size_t i = 0; i < images[0].pixels.size(); ++i) {
        differing += images[0].pixels[i] != images[1].pixels[i];
        lit += images[0].pixels[i] > 0.0f;
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(lit, images[0].pixels.size() / 2);
}

INSTANTIATE_TEST_SUITE_P(Modes, PreviewPackets,
                         ::testing::Values("preview_restir = 'off'",
                                           "preview_restir = 'unbiased', preview_bounces = 1",
                                           "preview_restir = 'biased'"));
