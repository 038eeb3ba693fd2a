// The shutter: camera rays' times are uniform over it (chi-square, for every sampler) and
// stratified over a pixel's samples; a camera that draws no time leaves the sampler's
// dimensions as they were; shutter parameters and their errors.
#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/core/sampler.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/chi_square.h>

#include <algorithm>
#include <vector>

using namespace glint;

namespace {

constexpr float kOpen = 0.2f, kClose = 0.7f;

PerspectiveCamera test_camera() {
    PerspectiveCamera camera(Vec3(0.0f), Vec3(0, 0, -1), Vec3(0, 1, 0), 45.0f, Vec2i(16, 16), 0.0f,
                             1.0f);
    camera.set_shutter(kOpen, kClose);
    camera.set_time_sampled(true);
    return camera;
}

std::unique_ptr<Camera> shutter_camera_from(const std::string& code) {
    const SceneDesc desc = load_scene_string(code, "shutter-test.lua");
    return make_camera(*desc.camera, Vec2i(16, 16));
}

}  // namespace

TEST(Shutter, TimesAreUniformOverTheShutterForEverySampler) {
    const PerspectiveCamera camera = test_camera();
    constexpr int kBins = 40;
    constexpr int kSpp = 64;
    for (const char* name : {"independent", "stratified", "sobol"}) {
        const auto sampler = make_sampler(name, kSpp, 7);
        std::vector<double> counts(kBins, 0.0);
        int total = 0;
        for (int y = 0; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                for (int i = 0; i < kSpp; ++i) {
                    sampler->start_pixel_sample(Vec2i(x, y), i);
                    sampler->get_pixel_2d();
                    const Ray ray = camera.sample_ray(Vec2(x + 0.5f, y + 0.5f), *sampler);
                    ASSERT_GE(ray.time, kOpen);
                    ASSERT_LE(ray.time, kClose);
                    const float u = (ray.time - kOpen) / (kClose - kOpen);
                    ++counts[std::min(kBins - 1, static_cast<int>(u * kBins))];
                    ++total;
                }
            }
        }
        const double expected = static_cast<double>(total) / kBins;
        double statistic = 0.0;
        for (double count : counts) statistic += (count - expected) * (count - expected) / expected;
        const double p = test::chi_square_upper_tail(statistic, kBins - 1);
        EXPECT_GT(p, 0.01) << name << ": chi-square " << statistic << " on " << kBins - 1
                           << " degrees of freedom";
    }
}

TEST(Shutter, TimesAreStratifiedOverAPixelsSamples) {
    // A pixel's 16 samples put one time in each sixteenth of the shutter.
    const PerspectiveCamera camera = test_camera();
    constexpr int kSpp = 16;
    for (const char* name : {"stratified", "sobol"}) {
        const auto sampler = make_sampler(name, kSpp, 11);
        for (int pixel = 0; pixel < 8; ++pixel) {
            std::vector<int> strata(kSpp, 0);
            for (int i = 0; i < kSpp; ++i) {
                sampler->start_pixel_sample(Vec2i(pixel, 3), i);
                sampler->get_pixel_2d();
                const Ray ray = camera.sample_ray(Vec2(pixel + 0.5f, 3.5f), *sampler);
                const float u = (ray.time - kOpen) / (kClose - kOpen);
                ++strata[std::min(kSpp - 1, static_cast<int>(u * kSpp))];
            }
            EXPECT_EQ(*std::max_element(strata.begin(), strata.end()), 1)
                << name << ", pixel " << pixel;
        }
    }
}

TEST(Shutter, AStillCameraDrawsNoTime) {
    PerspectiveCamera camera = test_camera();
    camera.set_time_sampled(false);
    const auto a = make_sampler("sobol", 4, 3);
    const auto b = make_sampler("sobol", 4, 3);
    a->start_pixel_sample(Vec2i(2, 2), 1);
    b->start_pixel_sample(Vec2i(2, 2), 1);
    const Ray ray = camera.sample_ray(Vec2(2.5f), *a);
    EXPECT_EQ(ray.time, kOpen);
    EXPECT_EQ(a->get_1d(), b->get_1d());  // the next dimension is the first one
}

TEST(Shutter, MovingCameraCarriesItsRays) {
    const auto camera =
        shutter_camera_from("glint.camera{ eye = {0, 0, 0}, look_at = {0, 0, -1}, shutter = {0, 1} }");
    camera->set_motion(MotionTransform({Transform(), Transform::translate(Vec3(2, 0, 0))}));
    camera->set_time_sampled(true);
    const auto sampler = make_sampler("independent", 1, 5);
    for (int i = 0; i < 20; ++i) {
        sampler->start_pixel_sample(Vec2i(i, 0), 0);
        const Ray ray = camera->sample_ray(Vec2(8.0f), *sampler);
        EXPECT_NEAR(ray.origin.x, 2.0f * ray.time, 1e-5f);
        EXPECT_NEAR(ray.direction.z, -1.0f, 1e-5f);
    }
}

TEST(Shutter, BadShuttersAreErrorsNamingTheLine) {
    EXPECT_NO_THROW(shutter_camera_from("glint.camera{ shutter = {0, 1} }"));
    for (const char* shutter : {"{0.5, 0.2}", "{-0.1, 0.5}", "{0, 1.5}", "{0.5}", "{0, 0.5, 1}"}) {
        try {
            shutter_camera_from(std::string("glint.camera{ shutter = ") + shutter + " }");
            ADD_FAILURE() << shutter << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("shutter-test.lua:1"), std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("shutter"), std::string::npos) << e.what();
        }
    }
}
