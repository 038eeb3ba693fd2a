// Analytic scenes for the path integrator: each has a closed-form answer.
#include <glint/camera/camera.h>
#include <glint/core/arena.h>
#include <glint/core/error.h>
#include <glint/core/sampler.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/path/path.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

using namespace glint;
using glint::test::expect_all_pixels;
using glint::test::mean_channel;
using glint::test::read_text;
using glint::test::render_lua;

namespace {

const char* kFurnace = R"(
    glint.background{ radiance = {0.5, 0.5, 0.5} }
    glint.camera{ eye = {0, 0, 4}, look_at = {0, 0, 0}, fov = 30 }
    glint.render{ width = 24, height = 24, spp = 16, seed = 3 }
    glint.sphere{ center = {0, 0, 0}, radius = 1, material = glint.diffuse{ reflectance = %s } }
)";

std::string furnace(const std::string& reflectance) {
    std::string code = kFurnace;
    code.replace(code.find("%s"), 2, reflectance);
    return code;
}

}  // namespace

// An albedo-1 object in a uniform environment reflects exactly what it receives: it
// disappears. Any energy loss or gain in BSDF sampling, RR or MIS shows up here.
TEST(PathIntegrator, WhiteFurnaceSphereDisappears) {
    const Image image = render_lua(furnace("1"));
    expect_all_pixels(image, Spectrum(0.5f), 0.01);
}

// A convex diffuse sphere cannot see itself, so every sample reflects the background once:
// exactly albedo * background on the sphere.
TEST(PathIntegrator, ConvexSphereReflectsAlbedoTimesBackground) {
    const Image image = render_lua(furnace("{0.8, 0.5, 0.2}"));
    const int c = image.width / 2;
    for (int y = c - 4; y < c + 4; ++y) {
        for (int x = c - 4; x < c + 4; ++x) {
            EXPECT_NEAR(image.at(x, y, 0), 0.4, 0.004);
            EXPECT_NEAR(image.at(x, y, 1), 0.25, 0.0025);
            EXPECT_NEAR(image.at(x, y, 2), 0.1, 0.001);
        }
    }
    // Corners see the background directly.
    EXPECT_FLOAT_EQ(image.at(0, 0, 0), 0.5f);
}

namespace {

// A closed diffuse sphere of radius 1 and albedo `albedo` around the origin, seen from inside
// (from `eye`, looking down -z), lit by the point lights in `lights` (Lua).
std::string closed_sphere(const std::string& integrator, int spp, int seed, double albedo,
                          const Vec3& eye, const std::string& lights, int photons = 100000) {
    return fmt::format(R"(
        glint.camera{{ eye = {{{}, {}, {}}}, look_at = {{{}, {}, -1}}, fov = 70 }}
        glint.render{{ width = 16, height = 16, spp = {}, seed = {}, integrator = '{}',
                       photons = {}, caustic_photons = 0 }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 1, material = glint.diffuse{{ reflectance = {} }} }}
        {}
    )",
                       eye.x, eye.y, eye.z, eye.x, eye.y, spp, seed, integrator, photons, albedo,
                       lights);
}

}  // namespace

// The closed furnace for the photon-mapping integrators, which store the light of every
// bounce after the first. Their noise is shared between pixels through the photons, so the
// pixels' spread does not bound it; the image mean's spread over seeds is below 0.2 % for
// both (photon at 64 spp: 1.0007-1.0020 over seeds 5, 9, 13; sppm at 32 passes of 50000
// photons: 1.031-1.033 over seeds 5 and 9), and the tolerance is 1 %. SPPM is consistent, not
// unbiased, but in a uniform field its radius update is not biased: a simulation of the update with
// Poisson photon counts (1 to 5 photons per visible point and pass at first, 16 to 64 passes) stays
// within 0.5 % of the truth.
//
// sppm is not held to this yet: it reads 3 % high here (1.031-1.040 for 16 to 256 passes;
// its indirect light 5-9 % too high at albedo 0.2, 0.5 and 0.8) while photon, path and
// path_light agree with the closed form within 0.2 %. An open finding (session note of
// issue 16), to be fixed with a test of its own.
TEST(PathIntegratorSlow, ClosedSphereAroundPointLightForPhotonMapping) {
    const std::string light = "glint.point_light{ position = {0, 0, 0}, intensity = math.pi }";
    const Image photon = render_lua(closed_sphere("photon", 16, 5, 0.5, Vec3(0.0f), light));
    EXPECT_NEAR(mean_channel(photon, 1, 0, 0, 16, 16), 1.0, 0.01) << "photon";
}

// The same sphere lit by three point lights of different intensities off the centre. The
// wall's light onto itself is uniform whatever lights it (a sphere's form factor from one
// point of its inside to an element dA of it is dA / (4 pi R^2)), so at a point x of the
// wall L(x) = a/pi (E(x) + a Phi / (4 pi R^2 (1 - a))), with E the lights' direct
// irradiance and Phi = 4 pi sum I their power. Light sampling picks one light in proportion
// to its power: a selection probability left out or wrong moves the image by tens of %.
TEST(PathIntegratorSlow, ClosedSphereWithPointLightsOfDifferentPower) {
    struct PointLight {
        Vec3 p;
        float intensity;
    };
    const PointLight lights[] = {{Vec3(0.3f, 0.2f, -0.4f), 1.0f},
                                 {Vec3(-0.5f, -0.1f, 0.1f), 4.0f},
                                 {Vec3(0.1f, -0.5f, -0.2f), 0.3f}};
    std::string lua;
    double total_intensity = 0.0;
    for (const PointLight& light : lights) {
        lua += fmt::format("glint.point_light{{ position = {{{}, {}, {}}}, intensity = {} }}\n",
                           light.p.x, light.p.y, light.p.z, light.intensity);
        total_intensity += light.intensity;
    }
    const double a = 0.5;
    const Vec3 eye(0.0f, 0.0f, 0.5f);
    const PerspectiveCamera camera(eye, Vec3(0.0f, 0.0f, -1.0f), Vec3(0, 1, 0), 70.0f,
                                   Vec2i(16, 16), 0.0f, 1.0f);
    // Radiance of the wall where the ray through film point `film` meets it.
    auto closed_form = [&](const Vec2& film) {
        const Ray ray = camera.generate_ray(film, Vec2(0.5f));
        const float b = glm::dot(ray.origin, ray.direction);
        const float t = -b + std::sqrt(b * b - (glm::dot(ray.origin, ray.origin) - 1.0f));
        const Vec3 x = ray.at(t);
        double irradiance = 0.0;
        for (const PointLight& light : lights) {
            const Vec3 d = light.p - x;
            const double r2 = glm::dot(d, d);
            irradiance += light.intensity * glm::dot(-x, d) / std::sqrt(r2) / r2;
        }
        return a / kPi * (irradiance + a * total_intensity / (1.0 - a));
    };
    for (const char* variant : {"path", "path_light"}) {
        const Image image = render_lua(closed_sphere(variant, 512, 7, a, eye, lua));
        // The residuals against the closed form have zero mean and independent pixels.
        std::vector<double> residuals;
        double expected_sum = 0.0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                constexpr int kSub = 6;
                double expected = 0.0;
                for (int i = 0; i < kSub * kSub; ++i) {
                    expected += closed_form(Vec2(x + (i % kSub + 0.5f) / kSub,
                                                 y + (i / kSub + 0.5f) / kSub)) /
                                (kSub * kSub);
                }
                residuals.push_back(image.at(x, y, 0) - expected);
                expected_sum += expected;
            }
        }
        const double n = static_cast<double>(residuals.size());
        double mean = 0.0, spread = 0.0;
        for (double r : residuals) mean += r / n;
        for (double r : residuals) spread += (r - mean) * (r - mean) / (n - 1.0);
        const double expected_mean = expected_sum / n;
        const double bound = 4.0 * std::sqrt(spread / n);
        EXPECT_LT(bound, 0.01 * expected_mean) << variant;
        EXPECT_NEAR(mean, 0.0, bound) << variant << ": image mean " << mean + expected_mean
                                      << ", closed form " << expected_mean;
    }
}

// A closed box of white walls (albedo 1) and emitters of radiance 1 that do not reflect:
// L = 1 everywhere solves the rendering equation (an emitter gives 1, a wall reflects all
// of the 1 it receives), whatever the shapes. The three emitters are faces of different
// area, so of different power (6 : 3 : 2): light sampling picks them with different
// probabilities, and an emitter found by BSDF sampling is weighted against light sampling
// with that probability, so a selection probability missing from the MIS weights, or a
// light's pdf in the wrong measure, shows as a deviation from 1.
TEST(PathIntegrator, ClosedBoxOfEmittersOfDifferentPowerIsUniform) {
    // The box [0, 1] x [0, 2] x [0, 3]; each face's vertices wind so that its normal
    // (v1 - v0) x (v2 - v0) points into the box, the side an emitter lights.
    const char* faces = R"(
        local white = glint.diffuse{ reflectance = 1 }
        local lamp = glint.emissive{ radiance = 1 }
        local function face(material, a, b, c, d)
            glint.quad{ vertices = {a, b, c, d}, material = material }
        end
        face(lamp,  {1, 0, 0}, {1, 0, 3}, {1, 2, 3}, {1, 2, 0})   -- x = 1, area 6
        face(white, {0, 0, 0}, {0, 2, 0}, {0, 2, 3}, {0, 0, 3})   -- x = 0
        face(lamp,  {0, 2, 0}, {1, 2, 0}, {1, 2, 3}, {0, 2, 3})   -- y = 2, area 3
        face(white, {0, 0, 0}, {0, 0, 3}, {1, 0, 3}, {1, 0, 0})   -- y = 0
        face(lamp,  {0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0})   -- z = 0, area 2
        face(white, {0, 0, 3}, {0, 2, 3}, {1, 2, 3}, {1, 0, 3})   -- z = 3
    )";
    for (const char* variant : {"path", "path_light", "path_bsdf"}) {
        // Light sampling alone is the noisiest here: one light per vertex, no BSDF hits.
        const int spp = std::string(variant) == "path_light" ? 2048 : 256;
        const Image image = render_lua(fmt::format(R"(
            glint.camera{{ eye = {{0.8, 1.6, 0.4}}, look_at = {{0.2, 0.4, 3}}, fov = 90 }}
            glint.render{{ width = 16, height = 16, spp = {}, seed = 4, integrator = '{}' }}
            {}
        )",
                                                   spp, variant, faces));
        for (int c = 0; c < 3; ++c) {
            const double mean = mean_channel(image, c, 0, 0, image.width, image.height);
            // BSDF sampling alone gives exactly 1 per path; 1e-4 is for float rounding.
            const double bound = 4.0 * glint::test::standard_error_of_uniform_mean(image, c) + 1e-4;
            // Light sampling alone has unbounded variance where a wall meets an emitter (the
            // 1/r^2 of area sampling), so its standard error falls slowly: it gets twice the
            // room. A 3 % bias still fails it.
            EXPECT_LT(bound, std::string(variant) == "path_light" ? 0.02 : 0.01) << variant;
            EXPECT_NEAR(mean, 1.0, bound) << variant << " channel " << c;
        }
        // Every part of the image, walls and emitters alike, is 1 within its noise.
        for (int y0 = 0; y0 < image.height; y0 += 8) {
            for (int x0 = 0; x0 < image.width; x0 += 8) {
                const double block = mean_channel(image, 1, x0, y0, x0 + 8, y0 + 8);
                const double block_bound =
                    4.0 * glint::test::standard_error_of_uniform_mean(image, 1) * 2.0 + 1e-4;
                EXPECT_NEAR(block, 1.0, block_bound) << variant << " block " << x0 << ", " << y0;
            }
        }
    }
}

// A Lambertian plane under a point light: L = rho/pi * I * cos(theta) / r^2.
TEST(PathIntegrator, DiffusePlaneUnderPointLight) {
    const int res = 64;
    const float fov = 60.0f, height = 2.0f, camera_height = 3.0f, rho = 0.5f, intensity = 10.0f;
    const Image image =
        render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, {}, 0}}, look_at = {{0, 0, 0}}, up = {{0, 0, -1}}, fov = {} }}
        glint.render{{ width = {}, height = {}, spp = 4 }}
        glint.point_light{{ position = {{0, {}, 0}}, intensity = {} }}
        glint.quad{{ vertices = {{ {{-50, 0, 50}}, {{50, 0, 50}}, {{50, 0, -50}}, {{-50, 0, -50}} }},
                     material = glint.diffuse{{ reflectance = {} }} }}
    )",
                               camera_height, fov, res, res, height, intensity, rho));

    const float tan_half = std::tan(fov * 0.5f * kPi / 180.0f);
    int checked = 0;
    for (int y = 2; y < res; y += 7) {
        for (int x = 3; x < res; x += 7) {
            // Where the pixel centre's ray meets the plane (camera looks down -y, up is -z).
            const float sx = (2.0f * (x + 0.5f) / res - 1.0f) * tan_half;
            const float sy = (1.0f - 2.0f * (y + 0.5f) / res) * tan_half;
            const Vec3 p(sx * camera_height, 0.0f, -sy * camera_height);
            const Vec3 to_light = Vec3(0.0f, height, 0.0f) - p;
            const float r2 = glm::dot(to_light, to_light);
            const float cos_theta = height / std::sqrt(r2);
            const float expected = rho / kPi * intensity * cos_theta / r2;
            EXPECT_NEAR(image.at(x, y, 1), expected, 0.01 * expected) << "pixel " << x << ", " << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 50);
}

namespace {

// A slab in front of a uniform emitter, seen at normal incidence.
Image render_slab(float absorption, float thickness, float roughness = 0.0f) {
    return render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 10}}, look_at = {{0, 0, 0}}, fov = 2 }}
        glint.render{{ width = 8, height = 8, spp = 1024, seed = 11 }}
        glint.box{{ min = {{-100, -100, {}}}, max = {{100, 100, 0}},
                    material = glint.dielectric{{ ior = 1.5, absorption = {}, roughness = {} }} }}
        glint.quad{{ vertices = {{ {{-500, -500, -5}}, {{500, -500, -5}}, {{500, 500, -5}}, {{-500, 500, -5}} }},
                     material = glint.emissive{{ radiance = 1 }} }}
    )",
                                  -thickness, absorption, roughness));
}

}  // namespace

// With R the normal-incidence Fresnel reflectance, the slab transmits the geometric series
// (1-R)^2 (1 + R^2 + R^4 + ...) = (1-R)^2 / (1-R^2) of the light behind it.
TEST(PathIntegrator, GlassSlabTransmittanceAtNormalIncidence) {
    const double R = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);
    const double expected = (1.0 - R) * (1.0 - R) / (1.0 - R * R);
    const Image image = render_slab(0.0f, 1.0f);
    const double measured = mean_channel(image, 0, 0, 0, image.width, image.height);
    EXPECT_NEAR(measured, expected, 0.01 * expected);
}

// Beer-Lambert inside the glass: each crossing multiplies by a = exp(-sigma d), giving
// (1-R)^2 a / (1 - R^2 a^2).
TEST(PathIntegrator, TintedGlassSlabFollowsBeerLambert) {
    const double R = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);
    const double sigma = 0.5, d = 1.0, a = std::exp(-sigma * d);
    const double expected = (1.0 - R) * (1.0 - R) * a / (1.0 - R * R * a * a);
    const Image image = render_slab(static_cast<float>(sigma), static_cast<float>(d));
    const double measured = mean_channel(image, 1, 0, 0, image.width, image.height);
    EXPECT_NEAR(measured, expected, 0.01 * expected);
}

// Rough glass keeps Beer-Lambert absorption: a barely rough slab (roughness 0.05, so its
// microfacets tilt by about 0.2 degrees) transmits what the smooth one does, within 2 %.
// Were absorption skipped inside rough glass, it would transmit 0.92 instead of 0.55.
TEST(PathIntegrator, RoughTintedGlassSlabFollowsBeerLambert) {
    const double R = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);
    const double sigma = 0.5, d = 1.0, a = std::exp(-sigma * d);
    const double expected = (1.0 - R) * (1.0 - R) * a / (1.0 - R * R * a * a);
    const Image image = render_slab(static_cast<float>(sigma), static_cast<float>(d), 0.05f);
    const double measured = mean_channel(image, 1, 0, 0, image.width, image.height);
    EXPECT_NEAR(measured, expected, 0.02 * expected);
}

// The index of refraction can be a texture: one that is 1.5 everywhere (a checker of two
// equal squares) gives the smooth slab's closed form, and one of 1.0 makes the slab vanish.
TEST(PathIntegrator, TexturedIndexOfRefraction) {
    auto slab = [](double ior) {
        return render_lua(fmt::format(R"(
            glint.camera{{ eye = {{0, 0, 10}}, look_at = {{0, 0, 0}}, fov = 2 }}
            glint.render{{ width = 8, height = 8, spp = 1024, seed = 11 }}
            local index = glint.texture.checker{{ even = {0}, odd = {0}, dimension = 3 }}
            glint.box{{ min = {{-100, -100, -1}}, max = {{100, 100, 0}},
                        material = glint.dielectric{{ ior = index }} }}
            glint.quad{{ vertices = {{ {{-500, -500, -5}}, {{500, -500, -5}}, {{500, 500, -5}}, {{-500, 500, -5}} }},
                         material = glint.emissive{{ radiance = 1 }} }}
        )",
                                      ior));
    };
    const double R = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);
    const double expected = (1.0 - R) * (1.0 - R) / (1.0 - R * R);
    const Image glass = slab(1.5);
    EXPECT_NEAR(mean_channel(glass, 0, 0, 0, glass.width, glass.height), expected, 0.01 * expected);
    const Image matched = slab(1.0);
    EXPECT_NEAR(mean_channel(matched, 0, 0, 0, matched.width, matched.height), 1.0, 1e-4);
}

namespace {

std::string cornell_box(int res, int spp) {
    std::FILE* file = std::fopen(GLINT_SOURCE_DIR "/examples/cornell-box.lua", "rb");
    if (!file) throw Error("cannot open examples/cornell-box.lua");
    std::string code;
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) code.append(buffer, n);
    std::fclose(file);
    // A later glint.render would be an error, so rewrite the settings line in place.
    const size_t start = code.find("glint.render{");
    const size_t output_list_end = code.find('}', code.find("output", start));
    const size_t end = code.find('}', output_list_end + 1);
    return code.substr(0, start) +
           fmt::format("glint.render{{ width = {}, height = {}, spp = {} }}", res, res, spp) +
           code.substr(end + 1);
}

}  // namespace

// The Cornell box: the light seen directly is exactly its radiance, and the image mean
// matches the published look (shared/scenes/cornell-box.md) to within a few percent.
TEST(PathIntegrator, CornellBoxLightAndMean) {
    const Image image = render_lua(cornell_box(64, 16));
    float brightest = 0.0f;
    int bx = 0, by = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (image.at(x, y, 0) > brightest) {
                brightest = image.at(x, y, 0);
                bx = x;
                by = y;
            }
        }
    }
    EXPECT_FLOAT_EQ(image.at(bx, by, 0), 17.0f);
    EXPECT_FLOAT_EQ(image.at(bx, by, 1), 12.0f);
    EXPECT_FLOAT_EQ(image.at(bx, by, 2), 4.0f);
    const double expected[3] = {0.1965, 0.1275, 0.0364};  // mean of a 256x256, 1024 spp render
    for (int c = 0; c < 3; ++c) {
        const double mean = mean_channel(image, c, 0, 0, image.width, image.height);
        EXPECT_NEAR(mean, expected[c], 0.05 * expected[c]) << "channel " << c;
    }
}

namespace {

Image render_cornell_with(const std::string& integrator, int res, int spp, int seed) {
    std::string scene = cornell_box(res, spp);
    const std::string settings = fmt::format("spp = {} }}", spp);
    scene.replace(scene.find(settings), settings.size(),
                  fmt::format("spp = {}, seed = {}, integrator = '{}' }}", spp, seed, integrator));
    return render_lua(scene);
}

}  // namespace

// Light sampling alone, BSDF sampling alone and their MIS combination are three unbiased
// estimators of the same image: each converges to the MIS reference, with an error that
// falls like 1/spp (a biased variant would plateau), and the image means agree within four
// standard errors (estimated from each variant's two renders), a bound below 1 % of the
// mean: a 2 % bias fails it, which the test checks on a scaled copy of each image.
TEST(PathIntegratorSlow, LightAndBsdfSamplingConvergeToTheSameImage) {
    const int res = 24;
    const int reference_spp = 1024;
    const Image reference = render_cornell_with("path", res, reference_spp, 99);
    double reference_error[3] = {0.0, 0.0, 0.0};  // standard error of the reference's means
    for (const char* variant : {"path", "path_light", "path_bsdf"}) {
        // BSDF sampling alone finds the small light rarely: it needs 32 times the samples
        // for a standard error as small as the others'.
        const int scale = std::string(variant) == "path_bsdf" ? 32 : 1;
        const int coarse_spp = 64 * scale, fine_spp = 256 * scale;
        const Image coarse = render_cornell_with(variant, res, coarse_spp, 1);
        const Image fine = render_cornell_with(variant, res, fine_spp, 2);
        const double error_coarse = compare_images(coarse, reference).rel_mse;
        const double error_fine = compare_images(fine, reference).rel_mse;
        EXPECT_LT(error_fine, 0.5 * error_coarse)
            << variant << ": " << error_coarse << " -> " << error_fine;
        for (int c = 0; c < 3; ++c) {
            const double fine_error = glint::test::standard_error_of_mean(
                fine, coarse, c, 0, 0, res, res, fine_spp, coarse_spp);
            if (std::string(variant) == "path") {
                reference_error[c] = fine_error * std::sqrt(double(fine_spp) / reference_spp);
            }
            const double expected = mean_channel(reference, c, 0, 0, res, res);
            const double bound = 4.0 * std::hypot(fine_error, reference_error[c]);
            auto agrees = [&](double factor) {
                return std::abs(factor * mean_channel(fine, c, 0, 0, res, res) - expected) < bound;
            };
            fmt::print("{} channel {}: mean {:.5f}, reference {:.5f}, bound {:.5f} ({:.2f} %)\n",
                       variant, c, mean_channel(fine, c, 0, 0, res, res), expected, bound,
                       100.0 * bound / expected);
            EXPECT_TRUE(agrees(1.0))
                << variant << " channel " << c << ": mean " << mean_channel(fine, c, 0, 0, res, res)
                << ", reference " << expected << ", bound " << bound;
            EXPECT_LT(bound, 0.01 * expected) << variant << " channel " << c;
            EXPECT_FALSE(agrees(1.02)) << variant << " channel " << c << ": misses a 2 % bias";
            EXPECT_FALSE(agrees(0.98)) << variant << " channel " << c << ": misses a 2 % bias";
        }
    }
}

// A Lambertian plane lit by a spherical emitter that fills a large solid angle, so BSDF
// sampling finds the light often and the MIS weights carry real weight. A uniform sphere
// of radiance Le and radius r irradiates a point at distance d with E = pi Le r^2 cos(b)/d^2
// while it is wholly above the horizon, so L = rho Le r^2 cos(b) / d^2 on the plane.
TEST(PathIntegratorSlow, PlaneUnderSphericalEmitterMatchesClosedFormForEveryStrategy) {
    const int res = 32;
    const float rho = 0.5f, radiance = 2.0f, radius = 1.0f;
    const Vec3 center(0.0f, 1.5f, 0.0f), eye(0.0f, 1.0f, 6.0f), target(0.0f, 0.3f, 0.0f);
    const PerspectiveCamera camera(eye, target, Vec3(0, 1, 0), 60.0f, Vec2i(res, res), 0.0f, 1.0f);
    for (const char* variant : {"path", "path_light", "path_bsdf"}) {
        // BSDF sampling alone finds the small emitter rarely: at 256 spp the aggregate's
        // spread over seeds is 0.7 %, too close to the 1 % tolerance; 1024 spp halves it.
        const int spp = std::string(variant) == "path_bsdf" ? 1024 : 256;
        const Image image = render_lua(fmt::format(R"(
            glint.camera{{ eye = {{0, 1, 6}}, look_at = {{0, 0.3, 0}}, fov = 60 }}
            glint.render{{ width = {}, height = {}, spp = {}, integrator = '{}' }}
            glint.sphere{{ center = {{0, 1.5, 0}}, radius = {}, material = glint.emissive{{ radiance = {} }} }}
            glint.quad{{ vertices = {{ {{-20, 0, 20}}, {{20, 0, 20}}, {{20, 0, -20}}, {{-20, 0, -20}} }},
                         material = glint.diffuse{{ reflectance = {} }} }}
        )",
                                                   res, res, spp, variant, radius, radiance, rho));
        double measured_sum = 0.0, expected_sum = 0.0;
        int pixels = 0, far_off = 0;
        // The closed form at a film position, or nothing where the plane is not what is seen.
        auto closed_form = [&](const Vec2& film) -> std::optional<double> {
            const Ray ray = camera.generate_ray(film, Vec2(0.5f));
            if (ray.direction.y >= -0.02f) return std::nullopt;
            const Vec3 oc = ray.origin - center;
            const float b = glm::dot(oc, ray.direction);
            if (b * b - (glm::dot(oc, oc) - radius * radius) > 0.0f) return std::nullopt;
            const Vec3 p = ray.at(-ray.origin.y / ray.direction.y);
            if (glm::length(Vec2(p.x, p.z)) > 8.0f) return std::nullopt;  // too dim to matter
            const Vec3 to_center = center - p;
            const float d2 = glm::dot(to_center, to_center);
            return rho * radiance * radius * radius * (to_center.y / std::sqrt(d2)) / d2;
        };
        for (int y = 0; y < res; ++y) {
            for (int x = 0; x < res; ++x) {
                // Average over the pixel, as the box filter does.
                constexpr int kSub = 8;
                double expected = 0.0;
                bool plane_only = true;
                for (int i = 0; i < kSub * kSub && plane_only; ++i) {
                    const auto value = closed_form(
                        Vec2(x + (i % kSub + 0.5f) / kSub, y + (i / kSub + 0.5f) / kSub));
                    plane_only = value.has_value();
                    expected += value.value_or(0.0) / (kSub * kSub);
                }
                if (!plane_only) continue;
                const double measured = image.at(x, y, 0);
                measured_sum += measured;
                expected_sum += expected;
                far_off += std::abs(measured - expected) > 0.05 * expected;
                ++pixels;
            }
        }
        ASSERT_GT(pixels, 200) << variant;
        EXPECT_NEAR(measured_sum / expected_sum, 1.0, 0.01) << variant;
        // BSDF sampling alone is too noisy per pixel at this sample count; the aggregate
        // above is its test.
        if (std::string(variant) != "path_bsdf") {
            EXPECT_LT(far_off, pixels / 20) << variant << ": pixels off by more than 5 %";
        }
    }
}

// A one-sided emitter placed through a mirroring transform still emits from the side its
// hits report, so light sampling and BSDF hits agree (found by the bench helper).
TEST(PathIntegrator, MirroredEmitterLightsTheSameAsUnmirrored) {
    const char* scene = R"(
        glint.camera{ eye = {0, 3, 6}, look_at = {0, 0, 0}, fov = 40 }
        glint.render{ width = 16, height = 16, spp = 64 }
        glint.quad{ vertices = {{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}}, material = glint.diffuse{} }
        local lamp = glint.group()
        lamp:quad{ vertices = {{1, 2, -1}, {1, 2, 1}, {-1, 2, 1}, {-1, 2, -1}},
                   material = glint.emissive{ radiance = 3 } }
        glint.place(lamp, %s)
    )";
    auto render_with = [&](const char* transform) {
        std::string code = scene;
        code.replace(code.find("%s"), 2, transform);
        return render_lua(code);
    };
    const Image plain = render_with("glint.scale(1)");
    const Image mirrored = render_with("glint.scale(-1, 1, 1)");
    const double plain_mean = mean_channel(plain, 0, 0, 0, 16, 16);
    EXPECT_GT(plain_mean, 0.05);
    EXPECT_NEAR(mean_channel(mirrored, 0, 0, 0, 16, 16), plain_mean, 0.02 * plain_mean);
}

// The path tracer traces a pixel's samples in packets whose paths advance together. Each
// path must come out as it would alone (li() traces one path with single-ray queries):
// same radiance, features and ray count, bit for bit, for every packet size, through
// glass and mirror bounces, paths that end early and paths that escape.
// The path tracer's packet loop, reached from the test (PathIntegrator befriends it).
namespace glint {
struct PathPacketTest {
    // Traces the paths of `rays` as one packet; each lane's radiance, features and the
    // rays traced in all.
    static std::vector<Spectrum> trace(const PathIntegrator& path, const Scene& scene,
                                       const std::vector<Ray>& rays,
                                       const std::vector<Sampler*>& samplers,
                                       std::vector<AovSample>& aovs, Arena& arena,
                                       RayCounter& counter) {
        PerLane<PathIntegrator::PathState> paths;
        for (size_t lane = 0; lane < rays.size(); ++lane) {
            paths[lane].start(rays[lane], *samplers[lane], &aovs[lane]);
        }
        path.trace_packet(scene, paths, static_cast<int>(rays.size()), arena, counter);
        std::vector<Spectrum> radiance;
        for (size_t lane = 0; lane < rays.size(); ++lane) radiance.push_back(paths[lane].L);
        return radiance;
    }
};
}  // namespace glint

TEST(PathIntegrator, PacketsGiveWhatEachPathGivesAlone) {
    const std::string code = read_text(GLINT_SOURCE_DIR "/examples/cornell-spheres.lua");
    const SceneDesc desc = load_scene_string(code, "cornell-spheres.lua");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    const auto integrator = make_integrator(settings);
    const auto& path = dynamic_cast<const PathIntegrator&>(*integrator);

    // The camera ray of `sampler`'s sample `index` of `pixel` (drawing the camera's values).
    auto camera_ray = [&](Sampler& sampler, Vec2i pixel, int index) {
        sampler.start_pixel_sample(pixel, index);
        const Vec2 film_point = Vec2(pixel) + sampler.get_pixel_2d();
        return scene->camera().sample_ray(film_point, sampler);
    };
    auto new_sampler = [&] { return make_sampler(settings.sampler, settings.spp, settings.seed); };

    Arena arena;
    int lit = 0;
    for (int py = 0; py < 6; ++py) {
        for (int px = 0; px < 6; ++px) {
            const Vec2i pixel((2 * px + 1) * settings.width / 12,
                              (2 * py + 1) * settings.height / 12);
            const int count = 1 + (py * 6 + px) % kPacketWidth;
            std::vector<std::unique_ptr<Sampler>> samplers;
            std::vector<Sampler*> lane_samplers;
            std::vector<Ray> rays;
            std::vector<AovSample> aovs(count);
            for (int lane = 0; lane < count; ++lane) {
                samplers.push_back(new_sampler());
                lane_samplers.push_back(samplers.back().get());
                rays.push_back(camera_ray(*samplers.back(), pixel, lane));
            }
            RayCounter packet_rays;
            arena.reset();
            const std::vector<Spectrum> radiance =
                PathPacketTest::trace(path, *scene, rays, lane_samplers, aovs, arena, packet_rays);

            RayCounter lone_rays;
            for (int lane = 0; lane < count; ++lane) {
                const auto sampler = new_sampler();
                const Ray ray = camera_ray(*sampler, pixel, lane);
                AovSample aov{};
                const Spectrum L = path.li(ray, *scene, *sampler, arena, lone_rays, &aov);
                const std::string where =
                    fmt::format("pixel ({}, {}), lane {} of {}", pixel.x, pixel.y, lane, count);
                EXPECT_EQ(to_rgb(radiance[lane]).r, to_rgb(L).r) << where;
                EXPECT_EQ(to_rgb(radiance[lane]).g, to_rgb(L).g) << where;
                EXPECT_EQ(to_rgb(radiance[lane]).b, to_rgb(L).b) << where;
                EXPECT_EQ(to_rgb(aovs[lane].albedo).r, to_rgb(aov.albedo).r) << where;
                EXPECT_EQ(aovs[lane].normal, aov.normal) << where;
                EXPECT_EQ(aovs[lane].depth, aov.depth) << where;
                lit += !L.is_black();
            }
            EXPECT_EQ(packet_rays.rays, lone_rays.rays)
                << "pixel (" << pixel.x << ", " << pixel.y << ")";
        }
    }
    EXPECT_GT(lit, 100);  // the comparisons are of light that got somewhere
}
