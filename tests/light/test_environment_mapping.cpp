// Light probes in each layout (environment_mapping.h): the documented directions of each
// layout, the round trip direction -> image -> direction, chi-square of the environment
// light's sampling with each mapping, and one sky given in every layout lighting a scene as
// its lat-long form does. The probe images are written here from one function of direction.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/light/environment_mapping.h>
#include <glint/light/registry.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/chi_square.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <cmath>
#include <string>

using namespace glint;

namespace {

constexpr EnvironmentMapping kAll[] = {
    EnvironmentMapping::kLatLong, EnvironmentMapping::kMirrorBall, EnvironmentMapping::kAngular,
    EnvironmentMapping::kCubeCross};

const char* name_of(EnvironmentMapping m) {
    switch (m) {
        case EnvironmentMapping::kLatLong:
            return "latlong";
        case EnvironmentMapping::kMirrorBall:
            return "mirror_ball";
        case EnvironmentMapping::kAngular:
            return "angular";
        case EnvironmentMapping::kCubeCross:
            return "cube_cross";
    }
    return "";
}

// A sky with a colour gradient from the zenith, a lighter side towards +x and a broad, bright
// patch (no sharp edges, so that every layout's resampling keeps it).
Rgb sky(const Vec3& d) {
    const float up = 0.5f * (d.y + 1.0f);
    const Vec3 sun = glm::normalize(Vec3(0.5f, 0.6f, -0.6f));
    const float glow = std::exp(8.0f * (glm::dot(d, sun) - 1.0f));
    return Rgb(0.3f + 0.4f * up + 0.2f * d.x, 0.35f + 0.3f * up, 0.7f - 0.3f * up) +
           Rgb(12.0f, 10.0f, 7.0f) * glow;
}

// The sky written in `mapping`'s layout, `size` pixels high; cells with nothing are black.
std::string write_probe(const test::TempDir& dir, EnvironmentMapping mapping, int size) {
    const int width = mapping == EnvironmentMapping::kLatLong     ? 2 * size
                      : mapping == EnvironmentMapping::kCubeCross ? size / 3 * 4
                                                                  : size;
    Image image = make_image(width, size, {"R", "G", "B"});
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < width; ++x) {
            const Vec2 p((x + 0.5f) / width, (y + 0.5f) / size);
            const std::optional<Vec3> d = environment_direction(mapping, p);
            const Rgb value = d ? sky(*d) : Rgb(0.0f);
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = value[c];
        }
    }
    const std::string file = dir.file(fmt::format("{}.exr", name_of(mapping)));
    write_image(file, image);
    return file;
}

std::unique_ptr<Light> environment(const std::string& file, EnvironmentMapping mapping) {
    Params params("environment", "test.lua:1");
    params.set("file", file);
    params.set("mapping", std::string(name_of(mapping)));
    auto light = make_light(params, ".");
    light->preprocess(Vec3(0.0f), 1.0f);
    return light;
}

Vec3 random_direction(Rng& rng) {
    const float z = 1.0f - 2.0f * rng.next_float(), phi = 2.0f * kPi * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

// The documentation's fixed points of each layout.
TEST(EnvironmentMapping, DocumentedDirections) {
    auto expect_dir = [](EnvironmentMapping m, Vec2 p, Vec3 expected) {
        const std::optional<Vec3> d = environment_direction(m, p);
        ASSERT_TRUE(d.has_value()) << name_of(m);
        EXPECT_NEAR(glm::distance(*d, expected), 0.0f, 1e-5f)
            << name_of(m) << " at (" << p.x << ", " << p.y << ")";
    };
    expect_dir(EnvironmentMapping::kLatLong, {0.5f, 0.5f}, {0, 0, -1});
    expect_dir(EnvironmentMapping::kLatLong, {0.25f, 0.5f}, {-1, 0, 0});
    // The ball's centre reflects the camera (+z); half way out it reflects the side (its
    // normal at 45 degrees: sin 45 from the centre), at the top the zenith.
    expect_dir(EnvironmentMapping::kMirrorBall, {0.5f, 0.5f}, {0, 0, 1});
    const float s = 0.5f * std::sqrt(0.5f);
    expect_dir(EnvironmentMapping::kMirrorBall, {0.5f + s, 0.5f}, {1, 0, 0});
    expect_dir(EnvironmentMapping::kMirrorBall, {0.5f, 0.5f - s}, {0, 1, 0});
    // Angular: the angle from +z is pi times the radius.
    expect_dir(EnvironmentMapping::kAngular, {0.5f, 0.5f}, {0, 0, 1});
    expect_dir(EnvironmentMapping::kAngular, {0.75f, 0.5f}, {1, 0, 0});
    expect_dir(EnvironmentMapping::kAngular, {0.5f, 0.25f}, {0, 1, 0});
    expect_dir(EnvironmentMapping::kAngular, {0.5f, 0.0f}, {0, 0, -1});
    // The cross: face centres.
    const auto cell = [](float col, float row) { return Vec2((col + 0.5f) / 4, (row + 0.5f) / 3); };
    expect_dir(EnvironmentMapping::kCubeCross, cell(1, 1), {0, 0, -1});
    expect_dir(EnvironmentMapping::kCubeCross, cell(0, 1), {-1, 0, 0});
    expect_dir(EnvironmentMapping::kCubeCross, cell(2, 1), {1, 0, 0});
    expect_dir(EnvironmentMapping::kCubeCross, cell(3, 1), {0, 0, 1});
    expect_dir(EnvironmentMapping::kCubeCross, cell(1, 0), {0, 1, 0});
    expect_dir(EnvironmentMapping::kCubeCross, cell(1, 2), {0, -1, 0});
    // Seen from inside, right of the face ahead is +x and its top edge meets the up face's
    // bottom edge.
    const Vec3 right_of_ahead =
        *environment_direction(EnvironmentMapping::kCubeCross, {0.499f, 0.5f});
    EXPECT_GT(right_of_ahead.x, 0.5f);
    const Vec3 top_of_ahead =
        *environment_direction(EnvironmentMapping::kCubeCross, {0.375f, 0.3337f});
    const Vec3 bottom_of_up =
        *environment_direction(EnvironmentMapping::kCubeCross, {0.375f, 0.3330f});
    EXPECT_LT(glm::distance(top_of_ahead, bottom_of_up), 0.01f);
    EXPECT_FALSE(environment_direction(EnvironmentMapping::kCubeCross, cell(0, 0)).has_value());
    EXPECT_FALSE(environment_direction(EnvironmentMapping::kMirrorBall, {0.02f, 0.02f}));
}

// direction -> image point -> direction is the identity, for every layout.
TEST(EnvironmentMapping, RoundTrip) {
    Rng rng(5);
    for (EnvironmentMapping m : kAll) {
        for (int i = 0; i < 5000; ++i) {
            const Vec3 d = random_direction(rng);
            if (m == EnvironmentMapping::kMirrorBall && d.z < -0.99f) continue;  // the rim
            const Vec2 p = environment_image_point(m, d);
            ASSERT_TRUE(p.x >= 0.0f && p.x <= 1.0f && p.y >= 0.0f && p.y <= 1.0f) << name_of(m);
            const std::optional<Vec3> back = environment_direction(m, p);
            ASSERT_TRUE(back.has_value()) << name_of(m);
            EXPECT_LT(glm::distance(*back, d), 2e-3f) << name_of(m) << " direction " << i;
        }
    }
}

// Chi-square of sample_li's directions against pdf_li_escaped with each mapping (bins in
// the map's frame turned so its pole lies on the test's z, as test_environment_light does).
TEST(EnvironmentMapping, SamplingMatchesDensityWithEachMapping) {
    test::TempDir dir;
    auto to_test_frame = [](const Vec3& w) { return Vec3(w.z, w.x, w.y); };
    auto from_test_frame = [](const Vec3& t) { return Vec3(t.y, t.z, t.x); };
    for (EnvironmentMapping m : kAll) {
        const auto light = environment(write_probe(dir, m, 48), m);
        auto sample = [&](const Vec2& u, float u_select) -> std::optional<Vec3> {
            const auto s = light->sample_li(Vec3(0.1f, 0.2f, -0.1f), u, u_select);
            if (!s) return std::nullopt;
            return to_test_frame(s->wi);
        };
        auto pdf = [&](const Vec3& t) {
            return static_cast<double>(light->pdf_li_escaped(from_test_frame(t)));
        };
        const auto result = test::chi_square_directions(sample, pdf, 200000, 17, 32, 64, 0.005);
        EXPECT_TRUE(result.passed) << name_of(m) << ": " << result.details;
        EXPECT_NEAR(result.integrated_pdf, 1.0, 2e-3) << name_of(m) << ": " << result.details;
    }
}

// One sky in each layout: an escaped ray sees the same radiance as through the lat-long
// form (within the resampling's blur), and a diffuse sphere on a floor renders the same:
// relative MSE under the noise of two lat-long renders with other seeds, plus a small
// allowance for the resampling, and channel means within 1 %. Every map is turned half a
// turn, so that the camera (looking along -z) sees +z behind the sphere: a mirror ball's
// blind spot, -z, where its whole rim is one direction, is then behind the camera, where a
// photographer puts it too.
TEST(EnvironmentMapping, TheSameSkyInEveryLayoutRendersTheSame) {
    test::TempDir dir;
    const std::string latlong = write_probe(dir, EnvironmentMapping::kLatLong, 64);
    const auto reference_light = environment(latlong, EnvironmentMapping::kLatLong);
    auto scene = [&](const std::string& file, EnvironmentMapping m, int seed) {
        return fmt::format(R"(
            glint.environment{{ file = "{}", mapping = "{}", rotation = 180 }}
            glint.camera{{ eye = {{0, 1.5, 4}}, look_at = {{0, 0.3, 0}}, fov = 40 }}
            glint.render{{ width = 32, height = 24, spp = 256, seed = {} }}
            glint.sphere{{ center = {{0, 0.6, 0}}, radius = 0.6, material = glint.diffuse{{ reflectance = 0.8 }} }}
            glint.quad{{ vertices = {{{{-3, 0, -3}}, {{-3, 0, 3}}, {{3, 0, 3}}, {{3, 0, -3}}}},
                         material = glint.diffuse{{ reflectance = 0.5 }} }}
        )",
                           file, name_of(m), seed);
    };
    const Image reference = test::render_lua(scene(latlong, EnvironmentMapping::kLatLong, 1));
    const Image other_seed = test::render_lua(scene(latlong, EnvironmentMapping::kLatLong, 2));
    const double noise = compare_images(other_seed, reference).rel_mse;
    for (EnvironmentMapping m : {EnvironmentMapping::kMirrorBall, EnvironmentMapping::kAngular,
                                 EnvironmentMapping::kCubeCross}) {
        SCOPED_TRACE(name_of(m));
        const std::string file = write_probe(dir, m, m == EnvironmentMapping::kCubeCross ? 48 : 96);
        const auto light = environment(file, m);
        Rng rng(11);
        double error = 0.0, total = 0.0;
        for (int i = 0; i < 4000; ++i) {
            const Vec3 d = random_direction(rng);
            if (m == EnvironmentMapping::kMirrorBall && d.z < -0.9f) continue;  // the rim's blur
            const Spectrum a = light->le_escaped(d), b = reference_light->le_escaped(d);
            error += std::abs(a.luminance() - b.luminance());
            total += b.luminance();
        }
        EXPECT_LT(error / total, 0.02) << "mean relative radiance difference";
        const Image image = test::render_lua(scene(file, m, 2));
        const double rel_mse = compare_images(image, reference).rel_mse;
        EXPECT_LT(rel_mse, 1.5 * noise + 1e-3) << "noise between seeds " << noise;
        for (int c = 0; c < 3; ++c) {
            const double mean = test::mean_channel(image, c, 0, 0, image.width, image.height);
            const double ref = test::mean_channel(reference, c, 0, 0, image.width, image.height);
            EXPECT_NEAR(mean, ref, 0.01 * ref) << "channel " << c;
        }
    }
}

// A layout whose image has the wrong shape, and an unknown mapping, are errors naming the
// script line and what was expected.
TEST(EnvironmentMapping, WrongShapeOrUnknownMappingIsAnError) {
    test::TempDir dir;
    const std::string latlong = write_probe(dir, EnvironmentMapping::kLatLong, 16);  // 32 x 16
    for (const char* mapping : {"mirror_ball", "angular", "cube_cross"}) {
        const std::string message =
            test::error_of([&] { environment(latlong, *environment_mapping_named(mapping)); });
        EXPECT_NE(message.find("test.lua:1"), std::string::npos) << message;
        EXPECT_NE(message.find(mapping == std::string("cube_cross") ? "4 faces wide" : "square"),
                  std::string::npos)
            << message;
    }
    Params params("environment", "test.lua:1");
    params.set("file", latlong);
    params.set("mapping", std::string("sphere"));
    const std::string message = test::error_of([&] { make_light(params, "."); });
    EXPECT_NE(message.find("'mapping' must be"), std::string::npos) << message;
}
