// The viewer's progressive loop without a window: N passes equal `glint render --spp N` bit
// for bit, changes restart accumulation, and a cancelled pass leaves nothing behind.
#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/denoise/network_denoiser.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/view/camera_controller.h>
#include <glint/view/progressive_session.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

namespace glint {
namespace {

constexpr int kPasses = 8;

std::string cornell(const std::string& extra) {
    return test::example_with_settings(
        "cornell-box.lua",
        fmt::format("width = 20, height = 16, spp = {}, seed = 3{}", kPasses, extra));
}

ProgressiveSession make_session(const std::string& code) {
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    return ProgressiveSession(desc, parse_render_settings(&*desc.render));
}

// Every pass of the session until it stops; returns the film's image.
Image render_all(ProgressiveSession& session) {
    Progress progress("test", 1, true);
    EXPECT_EQ(session.render_next(progress), PassKind::reduced);
    EXPECT_TRUE(session.showing_reduced());
    for (int pass = 1; pass <= kPasses; ++pass) {
        EXPECT_EQ(session.render_next(progress), PassKind::full);
        EXPECT_EQ(session.passes(), pass);
        EXPECT_FALSE(session.showing_reduced());
    }
    EXPECT_EQ(session.render_next(progress), PassKind::none);
    EXPECT_EQ(session.passes(), kPasses);
    return session.image();
}

void expect_same_bits(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    int differing = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            for (int c = 0; c < 3; ++c) differing += a.at(x, y, c) != b.at(x, y, c);
        }
    }
    EXPECT_EQ(differing, 0) << "values differ from the one-go render";
}

struct SameBitsCase {
    std::string integrator, sampler;
    int threads;
    friend void PrintTo(const SameBitsCase& c, std::ostream* os) {
        *os << c.integrator << ", " << c.sampler << ", " << c.threads << " threads";
    }
};

class SameBits : public testing::TestWithParam<SameBitsCase> {};

// The claim of issue 18: with the camera still, N passes show what render --spp N writes.
TEST_P(SameBits, PassesEqualOneRender) {
    const SameBitsCase& c = GetParam();
    const std::string code =
        cornell(fmt::format(", integrator = '{}', sampler = '{}', photons = 2000, "
                            "caustic_photons = 2000",
                            c.integrator, c.sampler));
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, c.threads);
    ProgressiveSession session = make_session(code);
    expect_same_bits(render_all(session), test::render_lua(code, c.threads));
}

INSTANTIATE_TEST_SUITE_P(
    View, SameBits,
    testing::Values(SameBitsCase{"path", "sobol", 1}, SameBitsCase{"path", "sobol", 2},
                    SameBitsCase{"path", "stratified", 2}, SameBitsCase{"path", "independent", 2},
                    SameBitsCase{"whitted", "sobol", 2}, SameBitsCase{"photon", "sobol", 2}),
    [](const testing::TestParamInfo<SameBitsCase>& info) {
        return info.param.integrator + "_" + info.param.sampler + "_" +
               std::to_string(info.param.threads);
    });

// Full passes until the session stops; returns the film's image.
Image finish(ProgressiveSession& session) {
    Progress progress("test", 1, true);
    while (session.render_next(progress) != PassKind::none) {
    }
    EXPECT_EQ(session.passes(), kPasses);
    return session.image();
}

TEST(ProgressiveSession, CameraMoveRestartsAndEqualsAFreshSession) {
    const std::string code = cornell(", integrator = 'path'");
    SceneDesc desc = load_scene_string(code, "cornell.lua");
    ProgressiveSession session = make_session(code);
    Progress progress("test", 1, true);
    for (int i = 0; i < 3; ++i) session.render_next(progress);
    ASSERT_EQ(session.passes(), 2);

    CameraController controller(&*desc.camera);
    controller.orbit(20.0f, 10.0f);
    session.set_camera(controller.params());
    EXPECT_EQ(session.passes(), 2) << "a change waits for the next pass";
    EXPECT_EQ(session.render_next(progress), PassKind::reduced);
    EXPECT_EQ(session.passes(), 0);
    EXPECT_TRUE(session.showing_reduced());
    EXPECT_EQ(session.render_next(progress), PassKind::full);
    EXPECT_EQ(session.passes(), 1);
    const Image moved = finish(session);

    // The same view from the start: nothing of the old view may remain in the film.
    desc.camera = controller.params();
    ProgressiveSession fresh(desc, parse_render_settings(&*desc.render));
    expect_same_bits(moved, render_all(fresh));
}

TEST(ProgressiveSession, ReducedPassIsShownEnlarged) {
    ProgressiveSession session = make_session(cornell(""));
    Progress progress("test", 1, true);
    ASSERT_EQ(session.render_next(progress), PassKind::reduced);
    const Image shown = session.image();
    ASSERT_EQ(shown.width, 20);
    ASSERT_EQ(shown.height, 16);
    // 1/4 size: each 4 x 4 block is one pixel of the reduced pass; the blocks are not all
    // the same (the box is not uniform).
    bool blocks_differ = false;
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 20; ++x) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(shown.at(x, y, c), shown.at(x / 4 * 4, y / 4 * 4, c));
                blocks_differ |= shown.at(x, y, c) != shown.at(0, 0, c);
            }
        }
    }
    EXPECT_TRUE(blocks_differ);
}

TEST(ProgressiveSession, LightPowerRestartsAndScalesTheImage) {
    const std::string code = cornell(", integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    ProgressiveSession session = make_session(code);
    const Image before = render_all(session);

    LightEdits lights(desc);
    ASSERT_EQ(lights.lights().size(), 1u);  // the one emissive quad
    EXPECT_TRUE(lights.lights()[0].movable);
    lights.lights()[0].power_scale = 2.0f;
    session.set_lights(lights);
    const Image after = render_all(session);
    // One light: the light sampler's choice and every pdf stay; each sample's radiance is
    // exactly doubled (a power of two), and so is every pixel.
    for (size_t i = 0; i < before.pixels.size(); ++i)
        ASSERT_EQ(after.pixels[i], 2.0f * before.pixels[i]) << "value " << i;
}

TEST(ProgressiveSession, MovedLightChangesTheScene) {
    const std::string code = test::example_with_settings(
        "point-caustic.lua", "width = 16, height = 16, spp = 8, integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "point.lua");
    LightEdits lights(desc);
    ASSERT_FALSE(lights.lights().empty());
    ASSERT_TRUE(lights.lights()[0].movable);
    lights.lights()[0].offset = Vec3(0.5f, -0.25f, 1.0f);
    const SceneDesc moved = lights.apply(desc);
    const Params before = desc.lights[0], after = moved.lights[0];
    const Vec3 p0 = before.get_vec3("position"), p1 = after.get_vec3("position");
    EXPECT_EQ(p1, p0 + Vec3(0.5f, -0.25f, 1.0f));

    ProgressiveSession session(desc, parse_render_settings(&*desc.render));
    const Image original = render_all(session);
    session.set_lights(lights);
    const Image shifted = render_all(session);
    EXPECT_NE(original.pixels, shifted.pixels);
}

// An emissive shape moves by a transform in front of its own: the built light emits from
// the moved quad, and the picture changes.
TEST(ProgressiveSession, MovedAreaLightEmitsFromItsNewPlace) {
    const std::string code = cornell(", integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    LightEdits lights(desc);
    ASSERT_EQ(lights.lights().size(), 1u);
    lights.lights()[0].offset = Vec3(10.0f, -300.0f, 20.0f);
    const SceneDesc moved = lights.apply(desc);
    const RenderSettings settings = parse_render_settings(&*desc.render);
    const auto scene = build_scene(moved, settings);
    ASSERT_EQ(scene->lights().size(), 1u);
    for (const Vec2 u : {Vec2(0.1f, 0.2f), Vec2(0.9f, 0.7f)}) {
        const auto emission = scene->lights()[0]->sample_le(u, Vec2(0.5f), 0.5f);
        ASSERT_TRUE(emission.has_value());
        EXPECT_NEAR(emission->ray.origin.y, 548.7f - 300.0f, 0.1f);
        EXPECT_GE(emission->ray.origin.x, 213.0f + 10.0f - 0.1f);
        EXPECT_LE(emission->ray.origin.x, 343.0f + 10.0f + 0.1f);
        EXPECT_GE(emission->ray.origin.z, 227.0f + 20.0f - 0.1f);
        EXPECT_LE(emission->ray.origin.z, 332.0f + 20.0f + 0.1f);
    }
    ProgressiveSession session(desc, settings);
    const Image before = render_all(session);
    session.set_lights(lights);
    EXPECT_NE(render_all(session).pixels, before.pixels);
}

TEST(ProgressiveSession, CancelledPassRestarts) {
    const std::string code = cornell(", integrator = 'path'");
    ProgressiveSession session = make_session(code);
    Progress quiet("test", 1, true);
    session.render_next(quiet);
    session.render_next(quiet);
    ASSERT_EQ(session.passes(), 1);
    std::atomic<int> cancel{1};
    Progress cancelled("test", 1, true);
    cancelled.set_cancel_flag(&cancel);
    EXPECT_THROW(session.render_next(cancelled), Interrupted);
    // The cut pass is thrown away with the rest; the result is still the one-go render.
    expect_same_bits(render_all(session), test::render_lua(code));
}

TEST(ProgressiveSession, IntegratorChoice) {
    const std::string code = cornell("");
    ProgressiveSession session = make_session(code);
    const std::vector<std::string> names =
        ProgressiveSession::progressive_integrators(session.settings());
    for (const char* name : {"path", "path_light", "path_bsdf", "whitted", "photon"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    for (const char* name : {"bdpt", "light", "sppm", "vcm", "mlt"})
        EXPECT_EQ(std::find(names.begin(), names.end(), name), names.end()) << name;
    EXPECT_THROW(session.set_integrator("bdpt"), Error);
    EXPECT_EQ(session.integrator(), "path");
    Progress progress("test", 1, true);
    session.render_next(progress);
    session.render_next(progress);
    session.set_integrator("whitted");
    EXPECT_EQ(session.render_next(progress), PassKind::reduced);
    EXPECT_EQ(session.passes(), 0);
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

// The viewer's "denoise when still": the network on the accumulated film equals the network
// on `glint render`'s image of the same passes, and the film's own image is unchanged by
// recording AOVs.
TEST(ProgressiveSession, DenoisedImageIsTheNetworkOnTheFilm) {
    const std::string code = cornell("");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    const RenderSettings settings = parse_render_settings(&*desc.render);
    SessionOptions options;
    options.aovs = true;
    ProgressiveSession session(desc, settings, options);
    ProgressiveSession plain = make_session(code);
    const Image plain_image = render_all(plain);
    const Image film = render_all(session);
    const Image rgb = without_channels(film, {"albedo.", "normal.", "depth."});
    EXPECT_EQ(rgb.pixels, plain_image.pixels);
    Progress progress("test", 1, true);
    const Image denoised = session.denoised_image(progress, 2);
    NetworkDenoiseSettings network;
    network.threads = 2;
    EXPECT_EQ(denoised.pixels, denoise_network(film, network).pixels);
    EXPECT_THROW(plain.denoised_image(progress, 2), Error);  // no AOVs
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

// Temporal mode: after a move the reprojected history fills the view (no reduced pass); once
// the camera stops, the image becomes the film's again, bit for bit, after the history's
// length plus one passes; a light edit drops the history.
TEST(ProgressiveSession, TemporalModeBlendsHistoryThenConvergesToTheFilm) {
    const int max_length = 4;
    const std::string code = test::example_with_settings(
        "cornell-box.lua", "width = 20, height = 16, spp = 64, seed = 3, integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    SessionOptions options;
    options.realtime = true;
    options.temporal = true;
    options.temporal_max_length = max_length;
    ProgressiveSession session(desc, parse_render_settings(&*desc.render), options);
    Progress progress("test", 1, true);
    EXPECT_EQ(session.render_next(progress), PassKind::reduced);  // nothing to reproject yet
    for (int i = 0; i < 3; ++i) EXPECT_EQ(session.render_next(progress), PassKind::full);
    EXPECT_FALSE(session.has_history());

    CameraController controller(&*desc.camera);
    controller.orbit(2.0f, 0.0f);
    session.set_camera(controller.params());
    EXPECT_FALSE(session.next_pass_reduced());
    EXPECT_TRUE(session.next_pass_shows_move());
    EXPECT_EQ(session.render_next(progress), PassKind::full);
    EXPECT_TRUE(session.has_history());
    EXPECT_FALSE(session.next_pass_shows_move());
    auto differing = [&] {
        const Image shown = session.image(), film = session.film_image();
        int count = 0;
        for (std::size_t i = 0; i < shown.pixels.size(); ++i)
            count += shown.pixels[i] != film.pixels[i];
        return count;
    };
    EXPECT_GT(differing(), 0) << "the history is blended in";
    // The first pass after the move blends a history of 3 passes; it fades out by one per
    // pass, so the shown image is the film's from pass 3 + 1 on (lengths are capped at 4).
    for (int pass = 2; pass <= max_length + 1; ++pass) {
        EXPECT_EQ(session.render_next(progress), PassKind::full);
        if (pass <= 3) {
            EXPECT_GT(differing(), 0) << "pass " << pass;
        }
    }
    EXPECT_EQ(differing(), 0) << "after the stop, exactly the plain average of the still passes";

    // The denoiser filters what is shown, keeping its size and leaving the history alone.
    const Image filtered = session.svgf_image();
    EXPECT_EQ(filtered.width, 20);
    EXPECT_EQ(filtered.num_channels(), 3);

    LightEdits lights(desc);
    lights.lights()[0].power_scale = 2.0f;
    session.set_lights(lights);
    session.render_next(progress);
    EXPECT_FALSE(session.has_history()) << "a light edit resets the history";
}

TEST(ProgressiveSession, TemporalModeAndSvgfGiveTheSameBitsForOneAndTwoThreads) {
    const std::string code = test::example_with_settings(
        "cornell-box.lua", "width = 24, height = 18, spp = 64, seed = 3, integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    auto run = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        SessionOptions options;
        options.realtime = true;
        options.temporal = true;
        options.reduced_scale = 1;
        ProgressiveSession session(desc, parse_render_settings(&*desc.render), options);
        Progress progress("test", 1, true);
        CameraController controller(&*desc.camera);
        for (int move = 0; move < 3; ++move) {
            for (int pass = 0; pass < 2; ++pass) session.render_next(progress);
            controller.orbit(3.0f, 1.0f);
            session.set_camera(controller.params());
        }
        session.render_next(progress);
        EXPECT_TRUE(session.has_history());
        return std::pair{session.image(), session.svgf_image()};
    };
    const auto [one, one_svgf] = run(1);
    const auto [two, two_svgf] = run(2);
    expect_same_bits(one, two);
    expect_same_bits(one_svgf, two_svgf);
}

// A session with the viewer's realtime buffers in temporal mode, full size from the first pass.
SessionOptions temporal_options(int max_length = 32) {
    SessionOptions options;
    options.realtime = true;
    options.temporal = true;
    options.temporal_max_length = max_length;
    options.reduced_scale = 1;
    return options;
}

// With the camera still the shown image converges to the film's, and SVGF's must too: its
// thresholds come from one frame's variance, so beyond the history's length (4 frames here)
// the variance it sees falls as 1 / frames and the filter fades. Without that it kept
// blurring a converged image: on the Cornell box at 640 x 480 its relative MSE against path's
// stayed at 0.0044 from 5 s to 20 s after a stop; with it, 0.0009 at 20 s (bench/README.md).
TEST(ProgressiveSession, SvgfFadesAsAStillImageConverges) {
    const std::string code = test::example_with_settings(
        "cornell-box.lua", "width = 24, height = 18, spp = 1024, seed = 3, integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    ProgressiveSession session(desc, parse_render_settings(&*desc.render),
                               temporal_options(/*max_length=*/4));
    Progress progress("test", 1, true);
    // How far the filtered image is from the unfiltered one, relative to its brightness.
    auto filtered_change = [&] {
        const Image shown = session.image(), filtered = session.svgf_image();
        double difference = 0.0, total = 0.0;
        for (std::size_t i = 0; i < shown.pixels.size(); ++i) {
            difference += std::abs(filtered.pixels[i] - shown.pixels[i]);
            total += std::abs(shown.pixels[i]);
        }
        return difference / total;
    };
    for (int pass = 0; pass < 4; ++pass) session.render_next(progress);
    const double at_history_length = filtered_change();
    for (int pass = 4; pass < 256; ++pass) session.render_next(progress);
    const double converged = filtered_change();
    std::printf("SVGF's change to the shown image: %.4f after 4 passes, %.4f after 256\n",
                at_history_length, converged);
    EXPECT_GT(at_history_length, 0.01) << "the filter smooths a noisy image";
    EXPECT_LT(converged, 0.3 * at_history_length) << "0.56 without the fading";
}

// The lamp seen directly passes through SVGF: its pixels are exact, and so bright that even
// small weights spread its light into the ceiling around it (the first frame after a move
// had 17 times the relative MSE against path's: bench/README.md).
TEST(ProgressiveSession, SvgfLeavesLampsSeenDirectlyAlone) {
    const std::string code = test::example_with_settings(
        "cornell-box.lua", "width = 40, height = 40, spp = 64, seed = 3, integrator = 'path'");
    const SceneDesc desc = load_scene_string(code, "cornell.lua");
    ProgressiveSession session(desc, parse_render_settings(&*desc.render), temporal_options());
    Progress progress("test", 1, true);
    for (int pass = 0; pass < 4; ++pass) session.render_next(progress);
    const Image shown = session.image(), filtered = session.svgf_image();
    // The lamp's pixels, as the session's geometry buffer sees them (pixel centres).
    const RenderSettings settings = parse_render_settings(&*desc.render);
    const auto scene = build_scene(desc, settings);
    const GeometryBuffer buffer =
        trace_geometry_buffer(*scene, *make_camera(*desc.camera, Vec2i(40, 40)), 40, 40);
    int lamp = 0, changed = 0;
    for (std::size_t i = 0; i < buffer.size(); ++i) {
        if (!buffer.emitter[i]) continue;
        ++lamp;
        for (int c = 0; c < 3; ++c)
            changed += filtered.pixels[3 * i + c] != shown.pixels[3 * i + c];
    }
    EXPECT_GT(lamp, 4);
    EXPECT_EQ(changed, 0);
}

TEST(ProgressiveSession, TemporalModeNeedsRealtimeBuffers) {
    const SceneDesc desc = load_scene_string(cornell(""), "cornell.lua");
    SessionOptions options;
    options.temporal = true;
    EXPECT_THROW(ProgressiveSession(desc, parse_render_settings(&*desc.render), options), Error);
}

}  // namespace
}  // namespace glint
