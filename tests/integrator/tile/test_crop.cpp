// Crop windows: every pixel of a cropped render is bit for bit the same pixel of the full
// render, for each integrator that supports it and for adaptive sampling, whose decisions
// look at neighbouring pixels; light, bdpt, vcm and mlt refuse a crop.
#include <glint/core/error.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

using namespace glint;
using glint::test::render_lua;

namespace {

// A small scene with an edge-rich glass ball, a floor and an area light; `settings`
// completes glint.render.
std::string scene(const std::string& settings) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 1.5, 4}}, look_at = {{0, 0.5, 0}}, fov = 45 }}
        glint.render{{ width = 24, height = 16, spp = 4, {} }}
        glint.quad{{ vertices = {{ {{-5, 0, 5}}, {{5, 0, 5}}, {{5, 0, -5}}, {{-5, 0, -5}} }},
                     material = glint.diffuse{{ reflectance = 0.6 }} }}
        glint.quad{{ vertices = {{ {{-0.5, 3, -0.5}}, {{0.5, 3, -0.5}}, {{0.5, 3, 0.5}}, {{-0.5, 3, 0.5}} }},
                     material = glint.emissive{{ radiance = 10 }} }}
        glint.sphere{{ center = {{0, 0.6, 0}}, radius = 0.6, material = glint.dielectric{{ ior = 1.5 }} }}
        glint.sphere{{ center = {{1.2, 0.3, 0.5}}, radius = 0.3, material = glint.diffuse{{ reflectance = 0.4 }} }}
    )",
                       settings);
}

void expect_window_of(const Image& crop, const Image& full, int x0, int y0, int x1, int y1) {
    ASSERT_EQ(crop.width, x1 - x0);
    ASSERT_EQ(crop.height, y1 - y0);
    ASSERT_EQ(crop.channels.size(), full.channels.size());
    int different = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            for (size_t c = 0; c < full.channels.size(); ++c) {
                const float a = crop.at(x - x0, y - y0, static_cast<int>(c));
                const float b = full.at(x, y, static_cast<int>(c));
                if (a != b && ++different <= 5) {
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << ": " << a
                                  << " cropped, " << b << " in full";
                }
            }
        }
    }
    EXPECT_EQ(different, 0);
}

class CropWindow : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(CropWindow, PixelsAreTheFullRendersBitForBit) {
    const std::string settings = GetParam();
    const Image full = render_lua(scene(settings));
    // An inner window, one touching the image's corner, and one of two pixels (sppm hashes
    // its visible points into as many buckets as the window has pixels: in two buckets, a
    // point's cells collide, and a point listed twice in a bucket would gather twice).
    for (const auto& [x0, y0, x1, y1] :
         {std::array<int, 4>{5, 3, 17, 11}, std::array<int, 4>{0, 9, 7, 16},
          std::array<int, 4>{10, 10, 12, 11}}) {
        SCOPED_TRACE(fmt::format("crop {{{}, {}, {}, {}}}", x0, y0, x1, y1));
        const Image crop = render_lua(
            scene(fmt::format("{}, crop = {{{}, {}, {}, {}}}", settings, x0, y0, x1, y1)), 2);
        expect_window_of(crop, full, x0, y0, x1, y1);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, CropWindow,
    ::testing::Values("integrator = 'path', aovs = true", "integrator = 'whitted'",
                      "integrator = 'photon', photons = 2000, caustic_photons = 2000",
                      "integrator = 'sppm', photons = 3000, photon_radius = 0.4, spp = 3",
                      "integrator = 'path', adaptive = 'sobel', edge_threshold = 0.1",
                      "integrator = 'path', adaptive = 'variance', target_error = 0.3, spp = 2, "
                      "max_spp = 32"));

TEST(Crop, RefusedByLightPathMethodsAndCheckedAgainstTheResolution) {
    for (const char* integrator : {"light", "bdpt", "vcm", "mlt"}) {
        try {
            render_lua(scene(fmt::format("integrator = '{}', crop = {{0, 0, 4, 4}}", integrator)));
            ADD_FAILURE() << integrator << " accepted a crop";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("does not support 'crop'"), std::string::npos)
                << e.what();
        }
    }
    for (const char* crop : {"{0, 0, 25, 4}", "{4, 4, 4, 8}", "{0, 0, 4}", "{-1, 0, 4, 4}",
                             "{0.5, 0, 4, 4}", "{0, 0, 4, 17}"}) {
        try {
            render_lua(scene(fmt::format("integrator = 'path', crop = {}", crop)));
            ADD_FAILURE() << "crop " << crop << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("'crop' must be"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(":3:"), std::string::npos) << e.what();
        }
    }
}
