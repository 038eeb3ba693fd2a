// The preview in participating media (integrator/photon/preview_media.h): its single
// scattering converges to volpath's with max_depth = 1 (homogeneous chromatic fog and a
// procedural cloud), its volumetric caustic (the volume photons' beam estimate) to bdpt's,
// its photons survive a camera move, and the image is the same for any thread count.
#include <glint/core/progress.h>
#include <glint/core/rng.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/photon/preview_media.h>
#include <glint/medium/henyey_greenstein.h>
#include <glint/scene/build.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/image_comparison.h>
#include <support/media_scenes.h>
#include <support/render_helpers.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace glint;

namespace {

// The fog room (or a procedural cloud in it) without mirror or glass: the light the fog
// scatters straight from the lamp and the surfaces' direct light are all there is at depth 1.
std::string fog_without_glass(const std::string& render, const std::string& medium) {
    return test::fog_room("local fog = " + medium, "width = 24, height = 24, " + render, "");
}

const char* const kChromaticFog =
    "glint.medium{ sigma_a = 0.05, sigma_s = {0.3, 0.6, 1.2}, g = 0.3 }";
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
    const double reference_noise =
        compare_images(references[0], references[1]).rel_mse / 2.0 / kRenders;
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
        std::printf("channel %d: preview %.5f +- %.5f, reference %.5f +- %.5f\n", c, ep.mean, ep.se,
                    er.mean, er.se);
        EXPECT_LT(std::abs(ep.mean - er.mean), 4.0 * sigma) << "channel " << c;
    }
}

// A volumetric caustic alone: fog below an opaque black plate whose square hole lies within
// a glass sphere's outline (seen from the lamp above), so all light that reaches the fog went
// through the glass. Surfaces are black. bdpt with max_depth = 3 then renders just what the
// preview does: light - glass - glass - fog - camera (the beam), and the lamp seen through
// the glass; it leaves out scattering twice after the glass (4 bounces), which the preview
// leaves out too, and light reflected inside the sphere (about 0.2 %), which the preview has.
std::string volumetric_caustic(const std::string& render) {
    return fmt::format(R"(
local fog = glint.medium{{ sigma_a = 0.05, sigma_s = 0.6, g = 0.3 }}
local black = glint.diffuse{{ reflectance = 0 }}
glint.camera{{ eye = {{0, 0.7, 3.2}}, look_at = {{0, 0.65, 0}}, fov = 40 }}
glint.render{{ width = 32, height = 32, {} }}
-- Fog below an opaque black plate; the plate's square hole is inside the glass sphere's
-- outline, so all light reaching the fog went through the glass.
glint.box{{ min = {{-1, 0.01, -1}}, max = {{1, 1.15, 1}}, material = glint.interface{{ interior = fog }} }}
glint.quad{{ vertices = {{ {{-2, 0, -2}}, {{-2, 0, 2}}, {{2, 0, 2}}, {{2, 0, -2}} }}, material = black }}
glint.box{{ min = {{-2, 1.48, -2}}, max = {{2, 1.52, -0.2}}, material = black }}
glint.box{{ min = {{-2, 1.48, 0.2}}, max = {{2, 1.52, 2}}, material = black }}
glint.box{{ min = {{-2, 1.48, -0.2}}, max = {{-0.2, 1.52, 0.2}}, material = black }}
glint.box{{ min = {{0.2, 1.48, -0.2}}, max = {{2, 1.52, 0.2}}, material = black }}
glint.sphere{{ center = {{0, 1.5, 0}}, radius = 0.32, material = glint.dielectric{{ ior = 1.5 }} }}
glint.quad{{ vertices = {{ {{-0.1, 2.6, -0.1}}, {{0.1, 2.6, -0.1}}, {{0.1, 2.6, 0.1}}, {{-0.1, 2.6, 0.1}} }},
            material = glint.emissive{{ radiance = 300 }} }}
    )",
                       render);
}

// The mean of channel c of `image` over the pixels [x0, x1) x [y0, y1).
double region_mean(const Image& image, int c, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += image.at(x, y, c);
    return sum / (static_cast<double>(x1 - x0) * (y1 - y0));
}

}  // namespace

// The preview in the fog room without glass, filled with `medium`, against volpath with
// max_depth = 1 (expect_converges); `mode` adds render settings to both. Each pixel
// estimates its own single scattering (preview_fog_interleave = false) unless `interleave`:
// then the estimates are shared between neighbours (interleaved_fog.h), which blurs the
// fog's light by about a pixel; at 24 x 24 pixels, each 1/24 of the view, the blur's error
// per pixel is allowed as `bias`, while the image's means must still agree.
static void expect_single_scattering_like_volpath(const char* medium, const std::string& mode,
                                                  int preview_spp, int volpath_spp,
                                                  bool interleave = false, double bias = 0.0005) {
    expect_converges(
        [&](int seed) {
            return fog_without_glass(
                fmt::format("integrator = 'preview', spp = {}, preview_ambient = 0, "
                            "preview_fog_interleave = {}, {}seed = {}",
                            preview_spp, interleave, mode, seed),
                medium);
        },
        [&](int seed) {
            return fog_without_glass(
                fmt::format("integrator = 'volpath', spp = {}, max_depth = 1, {}seed = {}",
                            volpath_spp, mode, seed),
                medium);
        },
        bias);
}

// Without mirrors or glass the preview's image is the surfaces' direct light and the light
// the fog scatters once straight from the lamp, with the transmittance of the fog on every
// segment; volpath with max_depth = 1 renders exactly that. The ambient term is off (it
// stands for the later bounces). Chromatic fog: the distance sampling's weights over the
// channels are in play.
TEST(PreviewMediaSlow, SingleScatteringInChromaticFogMatchesVolpath) {
    expect_single_scattering_like_volpath(kChromaticFog, "", 256, 512);
}

// Spectral mode: each pass's camera paths carry one set of wavelengths, at which the fog's
// coefficients and the transmittance are taken (volpath's paths each their own set).
TEST(PreviewMediaSlow, SpectralSingleScatteringMatchesVolpath) {
    expect_single_scattering_like_volpath(kChromaticFog, "spectral = true, ", 256, 256);
}

// The same in a procedural cloud: points along the camera rays are drawn uniformly and the
// transmittance estimated by ratio tracking.
TEST(PreviewMediaSlow, SingleScatteringInACloudMatchesVolpath) {
    expect_single_scattering_like_volpath(kCloud, "", 128, 256);
}

// Single scattering shared between neighbours (the default): the same light, blurred by
// about a pixel. Spectral mode too: a pixel's estimate is read at the wavelengths of the
// pixels that share it.
TEST(PreviewMediaSlow, InterleavedSingleScatteringKeepsTheFogsLight) {
    expect_single_scattering_like_volpath(kChromaticFog, "", 256, 512, true, 0.005);
    expect_single_scattering_like_volpath(kChromaticFog, "spectral = true, ", 256, 256, true,
                                          0.005);
}

TEST(PreviewMediaSlow, InterleavedSingleScatteringInACloud) {
    expect_single_scattering_like_volpath(kCloud, "", 128, 256, true, 0.015);
}

// A fog that glows (chromatic emission): each camera segment through it gathers what it
// emits, the transmittance times sigma_a Le in closed form, as volpath's depth-1 paths do
// (glow reaching the camera unscattered; glow lighting a surface or scattered is deeper).
TEST(PreviewMediaSlow, GlowingFogMatchesVolpath) {
    expect_single_scattering_like_volpath(
        "glint.medium{ sigma_a = {0.4, 0.6, 0.9}, sigma_s = 0.3, g = 0.2, "
        "emission = {2, 1, 0.4} }",
        "", 64, 256);
}

// The beam's core and the whole beam of volumetric_caustic(): the preview's and bdpt's
// means (green) over four renders each, within four standard errors plus 2 % for what the
// two leave out differently (light reflected inside the glass) and for the radius' blur at
// the core. Away from the beam's edges, where the estimate's radius blurs it, the volume
// photons' beam estimate converges to bdpt's volumetric caustic.
static void expect_beam_agrees_with_bdpt(bool spectral) {
    constexpr int kRenders = 4;
    const char* const mode = spectral ? "spectral = true, " : "";
    const std::vector<Image> previews = test::render_seeds(
        [&](int seed) {
            return volumetric_caustic(
                fmt::format("integrator = 'preview', spp = 64, preview_photons = 10000, "
                            "preview_ambient = 0, preview_volume_radius = 0.02, {}seed = {}",
                            mode, seed));
        },
        kRenders);
    const std::vector<Image> bdpts = test::render_seeds(
        [&](int seed) {
            return volumetric_caustic(fmt::format(
                "integrator = 'bdpt', spp = 1024, max_depth = 3, {}seed = {}", mode, seed));
        },
        kRenders);
    struct Region {
        const char* name;
        int x0, y0, x1, y1;
    };
    for (const Region& r : {Region{"core", 15, 12, 17, 22}, Region{"beam", 12, 8, 20, 26}}) {
        std::vector<double> p, b;
        for (const Image& image : previews)
            p.push_back(region_mean(image, 1, r.x0, r.y0, r.x1, r.y1));
        for (const Image& image : bdpts) b.push_back(region_mean(image, 1, r.x0, r.y0, r.x1, r.y1));
        const test::Estimate ep = test::estimate(p, 1.0), eb = test::estimate(b, 1.0);
        const double sigma = std::sqrt(ep.se * ep.se + eb.se * eb.se);
        std::printf("%s%s: preview %.5f +- %.5f, bdpt %.5f +- %.5f\n", mode, r.name, ep.mean, ep.se,
                    eb.mean, eb.se);
        EXPECT_GT(eb.mean, 0.0) << r.name;
        EXPECT_LT(std::abs(ep.mean - eb.mean), 4.0 * sigma + 0.02 * eb.mean) << r.name;
    }
}

TEST(PreviewMediaSlow, VolumetricCausticAgreesWithBdpt) {
    expect_beam_agrees_with_bdpt(false);
}

// Spectral mode: the volume photons carry their pass's wavelengths, and the transmittance
// from the lens to each is taken at them.
TEST(PreviewMediaSlow, SpectralVolumetricCausticAgreesWithBdpt) {
    expect_beam_agrees_with_bdpt(true);
}

// A medium the scene defines but places nowhere (no surface bounds it, the camera is not in
// it) changes nothing: the preview and bdpt give the same bits as without it (the preview
// would otherwise take its slower one-ray path for media).
TEST(PreviewMedia, AMediumPlacedNowhereChangesNothing) {
    const std::string scene = R"(
glint.camera{ eye = {0, 1, 4}, look_at = {0, 1, 0}, fov = 45 }
glint.quad{ vertices = { {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2} },
            material = glint.diffuse{ reflectance = 0.6 } }
glint.sphere{ center = {0, 0.8, 0}, radius = 0.4, material = glint.dielectric{ ior = 1.5 } }
glint.sphere{ center = {0, 2.2, 0}, radius = 0.1, material = glint.emissive{ radiance = 100 } }
)";
    const std::string unused = "local fog = glint.medium{ density = 0.5, albedo = 0.9 }\n";
    for (const char* integrator : {"preview", "bdpt"}) {
        const std::string render = fmt::format(
            "glint.render{{ width = 24, height = 24, spp = 4, integrator = '{}', seed = 5 }}\n",
            integrator);
        const Image with = test::render_lua(unused + render + scene, 2);
        const Image without = test::render_lua(render + scene, 2);
        ASSERT_EQ(with.pixels.size(), without.pixels.size());
        double sum = 0.0;
        for (size_t i = 0; i < with.pixels.size(); ++i) {
            ASSERT_EQ(with.pixels[i], without.pixels[i]) << integrator << ", value " << i;
            sum += with.pixels[i];
        }
        EXPECT_GT(sum, 0.0) << integrator;
    }
}

// The volume photons are traced in chunks and binned in their order: the same image for
// one and two threads, bit for bit.
TEST(PreviewMedia, SameImageForOneAndTwoThreads) {
    const std::string code =
        volumetric_caustic("integrator = 'preview', spp = 4, preview_photons = 5000, seed = 3");
    const Image one = test::render_lua(code, 1), two = test::render_lua(code, 2);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    double sum = 0.0;
    for (size_t i = 0; i < one.pixels.size(); ++i) {
        ASSERT_EQ(one.pixels[i], two.pixels[i]) << "value " << i;
        sum += one.pixels[i];
    }
    EXPECT_GT(sum, 0.0);
}

// Volume photons are in world space: a camera move keeps them (seen anew from the new
// view) and their shrinking radius; a light move drops them.
TEST(PreviewMedia, CameraMoveKeepsVolumePhotonsLightMoveDropsThem) {
    test::BuiltScene b = test::build_lua(
        volumetric_caustic("integrator = 'preview', preview_photons = 5000"), "preview-media.lua");
    auto integrator = make_integrator(b.settings);
    auto* preview = dynamic_cast<PreviewIntegrator*>(integrator.get());
    ASSERT_NE(preview, nullptr);
    Film film(b.settings.width, b.settings.height, false);
    Progress progress("test", 1, true);
    for (int pass = 0; pass < 3; ++pass) preview->render_pass(*b.scene, film, pass, progress);
    const size_t photons = preview->stored_volume_photons();
    const float radius = preview->volume_radius();
    EXPECT_GT(photons, 0u);
    EXPECT_GT(radius, 0.0f);

    preview->scene_changed(SceneChange::camera);
    film.clear();
    preview->render_pass(*b.scene, film, 0, progress);
    EXPECT_GT(preview->stored_volume_photons(), photons);  // a fourth batch on the three
    EXPECT_LT(preview->volume_radius(), radius);

    preview->scene_changed(SceneChange::lights_or_objects);
    film.clear();
    preview->render_pass(*b.scene, film, 0, progress);
    EXPECT_LT(preview->stored_volume_photons(), photons);  // one batch only
}

// The volume photons binned by tiles give every pixel the beam radiance estimate by its
// definition: the sum, in the photons' order, of power x phase x the kernel 1 / (pi r^2
// batches) over the photons within r of the pixel's ray and between its start and end.
// Camera in clear air with nothing between it and the photons (transmittance 1); photons
// of two batches scattered round the view, some beyond its edge; rays through pixel
// centres, ending at several depths. The same bits, so the four-wide test and the tiles
// leave out no photon and change no sum.
TEST(PreviewMedia, VolumePhotonViewGivesTheBeamEstimate) {
    test::BuiltScene b = test::build_lua(
        "glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 40 }\n"
        "glint.render{ width = 40, height = 30, spp = 1 }\n",
        "view.lua");
    const Camera& camera = b.scene->camera();
    Rng rng(31);
    std::vector<std::vector<VolumePhoton>> batches(2);
    for (std::vector<VolumePhoton>& batch : batches) {
        for (int i = 0; i < 400; ++i) {
            VolumePhoton photon;
            photon.p = Vec3(4.4f * rng.next_float() - 2.2f, 3.4f * rng.next_float() - 1.7f,
                            2.0f * rng.next_float() - 1.0f);
            photon.wi = glm::normalize(
                Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
            photon.power = Spectrum(rng.next_float());
            photon.g = rng.next_float() - 0.5f;
            batch.push_back(photon);
        }
    }
    const float radius2 = 0.3f * 0.3f;
    VolumePhotonView view;
    view.build(*b.scene, nullptr, batches, -1, radius2, Vec2i(0), Vec2i(40, 30), nullptr);
    ASSERT_GT(view.size(), 600u);
    const float kernel = 1.0f / (kPi * radius2 * 2.0f);
    int lit = 0;
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 40; ++x) {
            const Ray ray = camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            const float t_end =
                (x + y) % 3 == 0 ? kInfinity : 4.0f + 0.05f * static_cast<float>(x % 7);
            Spectrum expected(0.0f);
            for (const std::vector<VolumePhoton>& batch : batches) {
                for (const VolumePhoton& photon : batch) {
                    const Vec3 v = photon.p - ray.origin;
                    const float along = glm::dot(v, ray.direction);
                    if (!(along > 0.0f && along < t_end)) continue;
                    if (!(glm::dot(v, v) - along * along < radius2)) continue;
                    expected += photon.power * Spectrum(1.0f) * kernel *
                                HenyeyGreenstein(photon.g).eval(-ray.direction, photon.wi);
                }
            }
            const Spectrum got = view.estimate(Vec2i(x, y), ray.origin, ray.direction, t_end);
            lit += expected.max_value() > 0.0f;
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(got.value(c), expected.value(c)) << x << ", " << y << " channel " << c;
        }
    }
    EXPECT_GT(lit, 400);  // most pixels see photons
}
