// Analytic scenes for the path integrator: each has a closed-form answer.
#include <glint/core/error.h>
#include <glint/film/image.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cmath>

using namespace glint;
using glint::test::mean_channel;
using glint::test::render_lua;

namespace {

// Every pixel's RGB must be within `tolerance` (relative) of `expected`.
void expect_all_pixels(const Image& image, const Spectrum& expected, double tolerance) {
    int failures = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double v = image.at(x, y, c);
                if (std::abs(v - expected[c]) > tolerance * expected[c] && failures++ < 5) {
                    ADD_FAILURE() << fmt::format("pixel ({}, {}) channel {}: {} expected {}", x, y, c, v, expected[c]);
                }
            }
        }
    }
    EXPECT_EQ(failures, 0);
}

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

// A Lambertian plane under a point light: L = rho/pi * I * cos(theta) / r^2.
TEST(PathIntegrator, DiffusePlaneUnderPointLight) {
    const int res = 64;
    const float fov = 60.0f, height = 2.0f, camera_height = 3.0f, rho = 0.5f, intensity = 10.0f;
    const Image image = render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, {}, 0}}, look_at = {{0, 0, 0}}, up = {{0, 0, -1}}, fov = {} }}
        glint.render{{ width = {}, height = {}, spp = 4 }}
        glint.point_light{{ position = {{0, {}, 0}}, intensity = {} }}
        glint.quad{{ vertices = {{ {{-50, 0, 50}}, {{50, 0, 50}}, {{50, 0, -50}}, {{-50, 0, -50}} }},
                     material = glint.diffuse{{ reflectance = {} }} }}
    )", camera_height, fov, res, res, height, intensity, rho));

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

// A smooth slab in front of a uniform emitter, seen at normal incidence.
Image render_slab(float absorption, float thickness) {
    return render_lua(fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 10}}, look_at = {{0, 0, 0}}, fov = 2 }}
        glint.render{{ width = 8, height = 8, spp = 1024, seed = 11 }}
        glint.box{{ min = {{-100, -100, {}}}, max = {{100, 100, 0}},
                    material = glint.dielectric{{ ior = 1.5, absorption = {} }} }}
        glint.quad{{ vertices = {{ {{-500, -500, -5}}, {{500, -500, -5}}, {{500, 500, -5}}, {{-500, 500, -5}} }},
                     material = glint.emissive{{ radiance = 1 }} }}
    )", -thickness, absorption));
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

// Same seed, same bits, whatever the number of threads.
TEST(PathIntegrator, ImageIsIdenticalForAnyThreadCount) {
    const std::string scene = cornell_box(48, 4);
    const Image one = render_lua(scene, 1);
    const Image two = render_lua(scene, 2);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_TRUE(one.pixels == two.pixels);
}

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
