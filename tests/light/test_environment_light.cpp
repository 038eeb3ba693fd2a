// The environment light: its lat-long mapping and rotation, sampling against its density
// (chi-square), unbiased irradiance, photon emission, renders (white furnace, the three
// path-tracing strategies agree, photon mapping sees it), and scene errors. The maps are
// small images this file writes to a temporary directory.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/photon.h>
#include <glint/light/environment_light.h>
#include <glint/light/registry.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/chi_square.h>
#include <support/render_helpers.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

using namespace glint;
using glint::test::expect_all_pixels;
using glint::test::render_lua;

namespace {

namespace fs = std::filesystem;

constexpr int kSkyWidth = 64, kSkyHeight = 32;
constexpr int kSunX = 20, kSunY = 9;  // centre of a 3 x 3 pixel sun, 53 degrees from the zenith
const Spectrum kSunRadiance = uplift(Rgb(60.0f, 50.0f, 40.0f), RgbRole::unbounded);

// A blue-to-white sky, varying in azimuth too, with a bright sun.
Spectrum sky_pixel(int x, int y) {
    if (std::abs(x - kSunX) <= 1 && std::abs(y - kSunY) <= 1) return kSunRadiance;
    const float v = (y + 0.5f) / kSkyHeight, u = (x + 0.5f) / kSkyWidth;
    const float azimuth = 1.0f + 0.3f * std::cos(2.0f * kPi * u);
    return uplift(Rgb(0.3f + 0.5f * v, 0.4f + 0.4f * v, 0.8f - 0.3f * v), RgbRole::unbounded) *
           azimuth;
}

// Eight columns and four rows of different colours, to pin down the mapping.
Spectrum compass_pixel(int x, int y) {
    return uplift(Rgb(0.1f + x, 0.2f + y, 0.05f * (x + 8 * y) + 0.1f), RgbRole::unbounded);
}

void write_map(const fs::path& path, int width, int height,
               const std::function<Spectrum(int, int)>& pixel) {
    Image image = make_image(width, height, {"R", "G", "B"});
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = to_rgb(pixel(x, y))[c];
        }
    }
    write_image(path.string(), image);
}

// The maps, written once per test run into a directory removed at exit.
struct Maps {
    fs::path dir = fs::temp_directory_path() / fmt::format("glint-environment-{}", ::getpid());
    fs::path sky = dir / "sky.exr";
    fs::path uniform = dir / "uniform.exr";
    fs::path compass = dir / "compass.exr";
    fs::path grey_png = dir / "grey.png";

    Maps() {
        fs::create_directories(dir);
        write_map(sky, kSkyWidth, kSkyHeight, sky_pixel);
        write_map(uniform, kSkyWidth, kSkyHeight, [](int, int) { return Spectrum(0.5f); });
        write_map(compass, 8, 4, compass_pixel);
        write_map(grey_png, 4, 2, [](int, int) { return Spectrum(0.2f); });
    }
    ~Maps() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

const Maps& maps() {
    static const Maps instance;
    return instance;
}

// Through the registry, as a scene script makes it; the scene around it has radius 1.
std::unique_ptr<Light> environment(const fs::path& file, float rotation = 0.0f,
                                   const Spectrum& intensity = Spectrum(1.0f)) {
    Params params("environment", "test.lua:1");
    params.set("file", file.filename().string());
    params.set("rotation", static_cast<double>(rotation));
    params.set("intensity",
               std::vector<double>{to_rgb(intensity).r, to_rgb(intensity).g, to_rgb(intensity).b});
    auto light = make_light(params, file.parent_path().string());
    light->preprocess(Vec3(0.0f), 1.0f);
    return light;
}

// The documented mapping, written out independently of the light's code:
// direction(u, v) = (-sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)), theta = pi v,
// phi = 2 pi u, then a right-handed rotation by `degrees` about +y.
Vec3 documented_direction(double u, double v, double degrees = 0.0) {
    const double theta = M_PI * v, phi = 2.0 * M_PI * u;
    const double x = -std::sin(theta) * std::sin(phi), y = std::cos(theta),
                 z = std::sin(theta) * std::cos(phi);
    const double a = degrees * M_PI / 180.0;
    return Vec3(static_cast<float>(x * std::cos(a) + z * std::sin(a)), static_cast<float>(y),
                static_cast<float>(-x * std::sin(a) + z * std::cos(a)));
}

Vec3 pixel_direction(int x, int y, int width, int height, double degrees = 0.0) {
    return documented_direction((x + 0.5) / width, (y + 0.5) / height, degrees);
}

void expect_spectrum_near(const Spectrum& a, const Spectrum& b, float relative,
                          const std::string& label) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(to_rgb(a)[c], to_rgb(b)[c], relative * std::max(std::abs(to_rgb(b)[c]), 1e-6f))
            << label << " channel " << c;
    }
}

}  // namespace

// Every pixel centre's direction, by the documented formula, sees that pixel's value; a
// rotation moves it about +y as documented.
TEST(EnvironmentLight, LatLongMappingAndRotationAsDocumented) {
    // The prose of the documentation: the centre column looks along -z, a quarter turn
    // before it along -x, the top row is the zenith.
    EXPECT_NEAR(glm::length(documented_direction(0.5, 0.5) - Vec3(0, 0, -1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(documented_direction(0.25, 0.5) - Vec3(-1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(documented_direction(0.5, 0.5, 90.0) - Vec3(-1, 0, 0)), 0.0f, 1e-6f);
    for (const float degrees : {0.0f, 90.0f, -35.0f}) {
        const auto light = environment(maps().compass, degrees);
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 8; ++x) {
                const Vec3 w = pixel_direction(x, y, 8, 4, degrees);
                expect_spectrum_near(light->le_escaped(w), compass_pixel(x, y), 1e-4f,
                                     fmt::format("rotation {} pixel ({}, {})", degrees, x, y));
                // Directions need not be unit.
                expect_spectrum_near(light->le_escaped(3.0f * w), compass_pixel(x, y), 1e-4f,
                                     "scaled direction");
            }
        }
    }
    // Straight up is the top row, straight down the bottom row (their averages, as the
    // lookup clamps at the poles); between pixel centres the lookup is bilinear.
    const auto light = environment(maps().compass);
    const Vec2 up = dynamic_cast<const EnvironmentLight&>(*light).uv_of(Vec3(0, 1, 0));
    EXPECT_NEAR(up.y, 0.0f, 1e-6f);
    const Spectrum between = light->le_escaped(documented_direction(2.0 / 8.0, 1.5 / 4.0));
    expect_spectrum_near(between, (compass_pixel(1, 1) + compass_pixel(2, 1)) * 0.5f, 1e-3f,
                         "halfway between two pixel centres");
    EXPECT_TRUE(light->is_infinite());
    EXPECT_FALSE(light->is_delta());
}

TEST(EnvironmentLight, RotationMovesTheSunAndIntensityScales) {
    const Vec3 sun = pixel_direction(kSunX, kSunY, kSkyWidth, kSkyHeight);
    const Vec3 turned = pixel_direction(kSunX, kSunY, kSkyWidth, kSkyHeight, 90.0);
    const auto plain = environment(maps().sky);
    const auto rotated = environment(maps().sky, 90.0f);
    expect_spectrum_near(plain->le_escaped(sun), kSunRadiance, 1e-4f, "sun");
    expect_spectrum_near(rotated->le_escaped(turned), kSunRadiance, 1e-4f, "turned sun");
    EXPECT_LT(to_rgb(rotated->le_escaped(sun)).r, 2.0f);  // only sky where the sun was
    // The sun holds about a third of the sampling weight: light samples follow it.
    Rng rng(4);
    int near_turned_sun = 0, near_old_sun = 0;
    for (int i = 0; i < 1000; ++i) {
        const auto s =
            rotated->sample_li(Vec3(0.0f), Vec2(rng.next_float(), rng.next_float()), 0.5f);
        ASSERT_TRUE(s.has_value());
        near_turned_sun += glm::dot(s->wi, turned) > std::cos(glm::radians(10.0f));
        near_old_sun += glm::dot(s->wi, sun) > std::cos(glm::radians(10.0f));
    }
    EXPECT_GT(near_turned_sun, 200);
    EXPECT_LT(near_old_sun, 20);

    const Spectrum tint = uplift(Rgb(2.5f, 1.0f, 0.5f), RgbRole::unbounded);
    const auto brighter = environment(maps().sky, 0.0f, tint);
    for (const Vec3& w : {sun, Vec3(0.3f, 0.8f, -0.2f), Vec3(0.0f, -1.0f, 0.1f)}) {
        expect_spectrum_near(brighter->le_escaped(w), plain->le_escaped(w) * tint, 1e-5f, "tinted");
    }
    expect_spectrum_near(brighter->power(), plain->power() * tint, 1e-4f, "power");
}

// Chi-square of sample_li's directions against pdf_li_escaped. The test's bins are rings of
// cos(theta) about its z axis and sectors of phi, so the directions are turned to put the
// map's pole (+y) on z: then the density's steps, along rows and columns of the map, fall
// along the bins' edges, which the numerical integration resolves.
TEST(EnvironmentLight, SamplingMatchesDensity) {
    auto to_test_frame = [](const Vec3& w) { return Vec3(w.z, w.x, w.y); };
    auto from_test_frame = [](const Vec3& t) { return Vec3(t.y, t.z, t.x); };
    for (const float degrees : {0.0f, 70.0f}) {
        const auto light = environment(maps().sky, degrees);
        const Vec3 ref(0.2f, -0.1f, 0.3f);
        auto sample = [&](const Vec2& u, float u_select) -> std::optional<Vec3> {
            const auto s = light->sample_li(ref, u, u_select);
            if (!s) return std::nullopt;
            return to_test_frame(s->wi);
        };
        auto pdf = [&](const Vec3& t) {
            return static_cast<double>(light->pdf_li_escaped(from_test_frame(t)));
        };
        const auto result = test::chi_square_directions(sample, pdf, 200000, 13, 32, 64, 0.005);
        EXPECT_TRUE(result.passed) << "rotation " << degrees << ": " << result.details;
        EXPECT_NEAR(result.integrated_pdf, 1.0, 2e-3) << result.details;
        EXPECT_NEAR(result.sample_fraction, 1.0, 1e-9) << result.details;
    }
}

// A sample's radiance is what an escaped ray in its direction sees, its density what
// pdf_li_escaped says, and its shadow-ray target lies outside the scene.
TEST(EnvironmentLight, SampleAgreesWithLookupAndDensity) {
    const auto light = environment(maps().sky, 30.0f);
    Rng rng(8);
    int pdf_mismatches = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 ref(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f);
        const auto s = light->sample_li(ref, Vec2(rng.next_float(), rng.next_float()), 0.5f);
        ASSERT_TRUE(s.has_value());
        EXPECT_NEAR(glm::length(s->wi), 1.0f, 1e-5f);
        EXPECT_FALSE(s->is_delta);
        expect_spectrum_near(s->L, light->le_escaped(s->wi), 1e-3f, "radiance");
        // Rounding may carry a direction across a cell edge, where the density steps.
        pdf_mismatches += std::abs(s->pdf - light->pdf_li_escaped(s->wi)) > 1e-3f * s->pdf;
        EXPECT_GT(glm::length(s->p), 1.5f);  // beyond the scene's bounding sphere (radius 1)
        EXPECT_NEAR(glm::dot(glm::normalize(s->p - ref), s->wi), 1.0f, 1e-5f);
    }
    EXPECT_LE(pdf_mismatches, 5);
}

// Light sampling estimates the irradiance of an up-facing point without bias: the Monte
// Carlo estimate matches the image's radiance integrated numerically over the hemisphere.
TEST(EnvironmentLight, IrradianceEstimateIsUnbiased) {
    for (const float degrees : {0.0f, 140.0f}) {
        const auto light = environment(maps().sky, degrees);
        // E = integral of L cos(theta) d(omega) over the upper half of the map, by the
        // midpoint rule in (u, v), where d(omega) = 2 pi^2 sin(theta) du dv.
        constexpr int kU = 1024, kV = 256;
        double expected[3] = {0.0, 0.0, 0.0};
        for (int j = 0; j < kV; ++j) {
            const double v = 0.5 * (j + 0.5) / kV;
            const double weight = 2.0 * M_PI * M_PI * std::sin(M_PI * v) * std::cos(M_PI * v) *
                                  (1.0 / kU) * (0.5 / kV);
            for (int i = 0; i < kU; ++i) {
                const Spectrum L =
                    light->le_escaped(documented_direction((i + 0.5) / kU, v, degrees));
                for (int c = 0; c < 3; ++c) expected[c] += to_rgb(L)[c] * weight;
            }
        }
        Rng rng(21);
        constexpr int kSamples = 400000;
        double estimate[3] = {0.0, 0.0, 0.0};
        for (int i = 0; i < kSamples; ++i) {
            const auto s =
                light->sample_li(Vec3(0.0f), Vec2(rng.next_float(), rng.next_float()), 0.5f);
            if (!s || s->wi.y <= 0.0f) continue;
            for (int c = 0; c < 3; ++c)
                estimate[c] += to_rgb(s->L)[c] * s->wi.y / s->pdf / kSamples;
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(estimate[c], expected[c], 0.01 * expected[c])
                << "rotation " << degrees << " channel " << c;
        }
    }
}

// 8-bit images hold sRGB-encoded values and are decoded; float images are linear.
TEST(EnvironmentLight, EightBitImagesAreDecodedFromSrgb) {
    const auto light = environment(maps().grey_png);
    expect_spectrum_near(light->le_escaped(Vec3(0.3f, 0.5f, 0.1f)), Spectrum(0.2f), 0.02f, "png");
    const auto linear = environment(maps().uniform);
    expect_spectrum_near(linear->le_escaped(Vec3(0.3f, 0.5f, 0.1f)), Spectrum(0.5f), 1e-6f, "exr");
}

// Photons leave a disk outside the scene and carry the light's power: a sphere of radius R
// in the scene intercepts pi R^2 times the radiance integrated over all directions (each
// direction's parallel beam meets its cross-section), and with reflectance 0 the global
// map holds exactly those first hits.
TEST(EnvironmentLight, PhotonsCarryThePowerASphereIntercepts) {
    const std::string code = fmt::format(R"(
        glint.environment{{ file = "{}", rotation = 25 }}
        glint.render{{ integrator = 'photon', photons = 200000, caustic_photons = 0, seed = 5 }}
        glint.sphere{{ center = {{0.5, 0, 0}}, radius = 1, material = glint.diffuse{{ reflectance = 0 }} }}
    )",
                                         maps().sky.string());
    const SceneDesc desc = load_scene_string(code, "test.lua");
    const RenderSettings settings = parse_render_settings(&*desc.render);
    const auto scene = build_scene(desc, settings);
    ASSERT_NE(scene->environment(), nullptr);
    PhotonIntegrator integrator(settings, PhotonSettings::read(settings.params));
    integrator.build_maps(*scene);
    double stored[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < integrator.global_map().size(); ++i) {
        for (int c = 0; c < 3; ++c) stored[c] += to_rgb(integrator.global_map()[i].power)[c];
    }
    // The radiance integral over the sphere of directions, numerically from the lookup.
    constexpr int kU = 512, kV = 256;
    double integral[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < kV; ++j) {
        const double v = (j + 0.5) / kV;
        const double weight = 2.0 * M_PI * M_PI * std::sin(M_PI * v) / (kU * kV);
        for (int i = 0; i < kU; ++i) {
            const Spectrum L = scene->escaped_radiance(documented_direction((i + 0.5) / kU, v));
            for (int c = 0; c < 3; ++c) integral[c] += to_rgb(L)[c] * weight;
        }
    }
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(stored[c], M_PI * integral[c], 0.015 * M_PI * integral[c]) << "channel " << c;
    }
}

namespace {

// A diffuse sphere on a diffuse floor under the sun-and-sky map.
std::string sphere_on_floor(const char* integrator, int spp, int seed) {
    return fmt::format(R"(
        glint.environment{{ file = "{}", rotation = 30 }}
        glint.camera{{ eye = {{0, 2, 5}}, look_at = {{0, 0.6, 0}}, fov = 40 }}
        glint.render{{ width = 16, height = 16, spp = {}, seed = {}, integrator = '{}',
                       photons = 20000, caustic_photons = 0 }}
        glint.sphere{{ center = {{0, 1, 0}}, radius = 1,
                       material = glint.diffuse{{ reflectance = {{0.8, 0.6, 0.4}} }} }}
        glint.quad{{ vertices = {{ {{-3, 0, 3}}, {{3, 0, 3}}, {{3, 0, -3}}, {{-3, 0, -3}} }},
                     material = glint.diffuse{{ reflectance = 0.5 }} }}
    )",
                       maps().sky.string(), spp, seed, integrator);
}

}  // namespace

// An albedo-1 sphere under a uniform environment reflects exactly what it receives: it
// disappears. For the path tracer this holds only if the environment's light samples and
// the BSDF's escaped rays together count the environment once; for Whitted, whose direct
// light is the whole answer on a convex sphere, if light sampling alone is unbiased.
TEST(EnvironmentLightSlow, WhiteFurnaceSphereDisappears) {
    // A uniform map is light-sampled uniformly over the sphere, so half the light samples
    // fall below each point's horizon: within 1 % at every pixel, the sphere's rim included,
    // takes a few thousand samples.
    for (const auto& [integrator, spp] : {std::pair{"path", 4096}, std::pair{"whitted", 1024}}) {
        const Image image = render_lua(fmt::format(R"(
            glint.environment{{ file = "{}" }}
            glint.camera{{ eye = {{0, 0, 4}}, look_at = {{0, 0, 0}}, fov = 30 }}
            glint.render{{ width = 12, height = 12, spp = {}, seed = 3, integrator = '{}' }}
            glint.sphere{{ center = {{0, 0, 0}}, radius = 1, material = glint.diffuse{{ reflectance = 1 }} }}
        )",
                                                   maps().uniform.string(), spp, integrator));
        SCOPED_TRACE(integrator);
        expect_all_pixels(image, Spectrum(0.5f), 0.01);
    }
}

// Light sampling alone, BSDF sampling alone and their MIS combination converge to the
// same image. If a variant is unbiased, its relative MSE against the MIS render is the sum
// of both variances, each half the relative MSE between two renders with other seeds; the
// threshold allows 50 % more for the scatter of that estimate.
TEST(EnvironmentLight, PathStrategiesAgree) {
    const Image reference_a = render_lua(sphere_on_floor("path", 1024, 1));
    const Image reference_b = render_lua(sphere_on_floor("path", 1024, 2));
    const double reference_noise = compare_images(reference_b, reference_a).rel_mse;
    for (const char* variant : {"path_light", "path_bsdf"}) {
        const Image a = render_lua(sphere_on_floor(variant, 256, 3));
        const Image b = render_lua(sphere_on_floor(variant, 256, 4));
        const double noise = compare_images(b, a).rel_mse;
        const double expected = 0.5 * (reference_noise + noise);
        const double measured = compare_images(a, reference_a).rel_mse;
        EXPECT_LT(measured, 1.5 * expected)
            << variant << ": relMSE " << measured << ", unbiased would be " << expected;
        for (int c = 0; c < 3; ++c) {
            const double mean = test::mean_channel(a, c, 0, 0, a.width, a.height);
            const double ref = test::mean_channel(reference_a, c, 0, 0, a.width, a.height);
            EXPECT_NEAR(mean, ref, 0.02 * ref) << variant << " channel " << c;
        }
    }
}

// Photon mapping and SPPM see the environment behind the scene and are lit by it (direct
// light by light sampling, indirect light by photons from the environment): their image
// means match the path tracer's.
TEST(EnvironmentLight, OtherIntegratorsAgreeWithPathTracing) {
    const Image reference = render_lua(sphere_on_floor("path", 256, 1));
    for (const char* integrator : {"photon", "sppm"}) {
        const Image image = render_lua(sphere_on_floor(integrator, 64, 1));
        for (int c = 0; c < 3; ++c) {
            const double mean = test::mean_channel(image, c, 0, 0, image.width, image.height);
            const double ref = test::mean_channel(reference, c, 0, 0, image.width, image.height);
            EXPECT_NEAR(mean, ref, 0.05 * ref) << integrator << " channel " << c;
        }
        // The corner sees the sky directly.
        EXPECT_NEAR(image.at(0, 0, 0), reference.at(0, 0, 0), 0.01 * reference.at(0, 0, 0))
            << integrator;
    }
}

// Scene errors name the file and the script line.
TEST(EnvironmentLight, MissingOrUnreadableFileIsAnErrorNamingFileAndLine) {
    const fs::path not_an_image = maps().dir / "notes.exr";
    {
        std::FILE* f = std::fopen(not_an_image.string().c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("not an image", f);
        std::fclose(f);
    }
    const struct {
        std::string file;
        std::string what;
    } cases[] = {{(maps().dir / "does-not-exist.exr").string(), "does not exist"},
                 {not_an_image.string(), "cannot read environment map"}};
    for (const auto& c : cases) {
        const std::string code =
            fmt::format(R"(glint.camera{{ eye = {{0, 0, 4}}, look_at = {{0, 0, 0}} }}
            glint.sphere{{ center = {{0, 0, 0}}, radius = 1, material = glint.diffuse{{}} }}
            glint.environment{{ file = "{}" }}
        )",
                        c.file);
        const SceneDesc desc = load_scene_string(code, "scene.lua");
        try {
            build_scene(desc, parse_render_settings(nullptr));
            ADD_FAILURE() << "no error for " << c.file;
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("scene.lua:3:"), std::string::npos) << message;
            EXPECT_NE(message.find(c.file), std::string::npos) << message;
            EXPECT_NE(message.find(c.what), std::string::npos) << message;
        }
    }
}

// From the command line: exit status 1, the file and line in the message, no image.
TEST(EnvironmentLight, CommandLineReportsAMissingMap) {
    const fs::path dir = maps().dir / "cli";
    fs::create_directories(dir);
    const fs::path scene = dir / "sky.lua";
    {
        std::FILE* f = std::fopen(scene.string().c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs(
            "glint.render{ width = 4, height = 4, spp = 1 }\n"
            "glint.environment{ file = \"maps/absent.hdr\", rotation = 90 }\n",
            f);
        std::fclose(f);
    }
    const fs::path output = dir / "out.exr";
    const auto result =
        test::run_glint(fmt::format("render {} -o {} --quiet", scene.string(), output.string()));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("sky.lua:2:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("maps/absent.hdr"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(output));
}

TEST(EnvironmentLight, AtMostOneEnvironmentAndNoBackgroundBesideIt) {
    const std::string file = maps().uniform.string();
    const std::string two = fmt::format(R"(glint.environment{{ file = "{}" }}
        glint.environment{{ file = "{}", rotation = 10 }}
    )",
                                        file, file);
    const std::string with_background = fmt::format(R"(glint.environment{{ file = "{}" }}
        glint.background{{ radiance = 1 }}
    )",
                                                    file);
    for (const auto& [code, line] :
         {std::pair{two, "scene.lua:2:"}, std::pair{with_background, "scene.lua:2:"}}) {
        try {
            build_scene(load_scene_string(code, "scene.lua"), parse_render_settings(nullptr));
            ADD_FAILURE() << "no error for " << code;
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(line), std::string::npos) << message;
            EXPECT_NE(message.find("scene.lua:1"), std::string::npos) << message;  // the first one
        }
    }
}

TEST(EnvironmentLight, RejectsBadParameters) {
    const std::string file = maps().uniform.string();
    for (const std::string& extra :
         {std::string("intensity = -1"), std::string("transform = glint.scale(2)"),
          std::string("rotaton = 3")}) {
        const std::string code =
            fmt::format(R"(glint.environment{{ file = "{}", {} }})", file, extra);
        EXPECT_THROW(
            build_scene(load_scene_string(code, "scene.lua"), parse_render_settings(nullptr)),
            Error)
            << extra;
    }
    // A rotating transform is accepted and composes with `rotation`.
    const std::string code = fmt::format(
        R"(glint.environment{{ file = "{}", rotation = 30, transform = glint.rotate(60, {{0, 1, 0}}) }})",
        maps().compass.string());
    const auto scene =
        build_scene(load_scene_string(code, "scene.lua"), parse_render_settings(nullptr));
    expect_spectrum_near(scene->escaped_radiance(pixel_direction(3, 1, 8, 4, 90.0)),
                         compass_pixel(3, 1), 1e-4f, "rotation 30 then 60");
}
