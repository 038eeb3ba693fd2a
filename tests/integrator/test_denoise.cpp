// The denoiser (film/denoise.h) on rendered images: error against a converged reference,
// sharpness of texture and geometry edges, fireflies, determinism; and `--denoise` in the
// command line.
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/film/denoise.h>
#include <glint/film/image_io.h>
#include <glint/integrator/integrator.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/denoise_metrics.h>
#include <support/render_helpers.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace glint {
namespace {

using test::band_size;
using test::edge_bands;
using test::edge_contrast;
using test::EdgeBands;
using test::error_against;
using test::example_with_settings;
using test::Halves;
using test::luminance;
using test::render_halves;
using test::run_glint;

// The issue's criteria on one scene at 16 spp: the denoised image's error at least 4 x
// lower than the noisy one's; in the edge bands no worse than the noisy one's, and the
// edges' contrast at least 80 % of the reference's.
void check_scene(const std::string& noisy_code, const std::string& reference_code,
                 bool has_texture_edges, double filter_gain, double texture_band_bound = 0.0) {
    const Halves noisy = render_halves(noisy_code);
    const Halves ref = render_halves(reference_code);
    const Image denoised = denoise(noisy.full, noisy.a, noisy.b);

    const double noisy_error = error_against(noisy.full, ref);
    const double denoised_error = error_against(denoised, ref);
    ::testing::Test::RecordProperty("noisy_rel_mse", fmt::format("{:.5f}", noisy_error));
    ::testing::Test::RecordProperty("denoised_rel_mse", fmt::format("{:.5f}", denoised_error));
    EXPECT_LT(4.0 * denoised_error, noisy_error)
        << "noisy " << noisy_error << ", denoised " << denoised_error;

    // The filter's own share, apart from the firefly clamp: the error of the image with
    // only its fireflies clamped (a search radius of 0).
    DenoiseSettings clamp_only;
    clamp_only.radius = 0;
    const double clamped_error =
        error_against(denoise(noisy.full, noisy.a, noisy.b, clamp_only), ref);
    fmt::print("fireflies clamped only: {:.5f} ({:.1f} x the denoised error)\n", clamped_error,
               clamped_error / denoised_error);
    EXPECT_LT(filter_gain * denoised_error, clamped_error);

    const EdgeBands bands = edge_bands(ref.full);
    ASSERT_GT(band_size(bands.geometry), 50);
    std::vector<std::pair<const char*, const std::vector<uint8_t>*>> checks = {
        {"geometry", &bands.geometry}};
    if (has_texture_edges) {
        ASSERT_GT(band_size(bands.texture), 50);
        checks.push_back({"texture", &bands.texture});
    }
    for (const auto& [name, band] : checks) {
        SCOPED_TRACE(name);
        const double noisy_band = error_against(noisy.full, ref, band);
        const double denoised_band = error_against(denoised, ref, band);
        EXPECT_LE(denoised_band, noisy_band);
        if (std::string(name) == "texture" && texture_band_bound > 0.0) {
            EXPECT_LT(denoised_band, texture_band_bound);
        }
        const double ref_contrast = edge_contrast(ref.full, *band);
        const double denoised_contrast = edge_contrast(denoised, *band);
        EXPECT_GE(denoised_contrast, 0.8 * ref_contrast)
            << "reference " << ref_contrast << ", denoised " << denoised_contrast;
        fmt::print(
            "{} edges ({} pixels): error noisy {:.5f} denoised {:.5f}; contrast "
            "reference {:.4f} denoised {:.4f}\n",
            name, band_size(*band), noisy_band, denoised_band, ref_contrast, denoised_contrast);
    }
    fmt::print("whole image: noisy {:.5f}, denoised {:.5f} ({:.1f} x lower)\n", noisy_error,
               denoised_error, noisy_error / denoised_error);
}

TEST(DenoiseSlow, CornellBoxErrorFourTimesLowerWithSharpEdges) {
    auto code = [](int spp, int seed) {
        return example_with_settings(
            "cornell-box.lua",
            fmt::format("width = 64, height = 64, spp = {}, seed = {}, integrator = 'path'", spp,
                        seed));
    };
    check_scene(code(16, 1), code(512, 2), false, 3.0);
}

constexpr double kTextureBandBound = 0.0066;

TEST(DenoiseSlow, TexturesErrorFourTimesLowerWithSharpEdges) {
    auto code = [](int spp, int seed) {
        return example_with_settings(
            "textures.lua",
            fmt::format(
                "width = 160, height = 90, crop = {{16, 24, 144, 84}}, spp = {}, seed = {}, "
                "max_depth = 8",
                spp, seed));
    };
    // The objects and the floor in front of the wall, at the example's detail per pixel
    // (a smaller image has more detail per pixel than any denoiser can keep); the reference
    // is noisy too, which error_against() allows for.
    // Here the filter's gain beyond the clamp is small (measured 1.0 x; 0.95 x since the path
    // tracer's square-root roulette keeps more of the long paths through the rough glass):
    // most of the remaining error is around that glass, where 16 samples leave clusters of
    // bright paths in both halves; it must not add more than a tenth.
    // The texture edges' error, recorded as 0.00438 and bounded with a margin of a half: without
    // the albedo demodulation it doubles (issue 28's mutation check), and only this bound sees it.
    check_scene(code(16, 1), code(128, 2), true, 0.9, kTextureBandBound);
}

Halves small_cornell() {
    return render_halves(example_with_settings(
        "cornell-box.lua", "width = 48, height = 48, spp = 16, seed = 3, integrator = 'path'"));
}

TEST(Denoise, PlantedFireflyIsRemoved) {
    const Halves clean = small_cornell();
    const Image reference = denoise(clean.full, clean.a, clean.b);
    const int px = 20, py = 30;  // on the floor
    auto plant = [&](Image& image) {
        for (int c = 0; c < 3; ++c) image.at(px, py, c) *= 1000.0f;
    };
    // In the whole pixel (both halves), and in one half only, as a rare path would be.
    for (const bool both : {true, false}) {
        SCOPED_TRACE(both ? "both halves" : "one half");
        Halves planted = clean;
        plant(planted.a);
        if (both) plant(planted.b);
        for (int c = 0; c < 3; ++c)
            planted.full.at(px, py, c) = 0.5f * (planted.a.at(px, py, c) + planted.b.at(px, py, c));
        const Image result = denoise(planted.full, planted.a, planted.b);
        // Nowhere in the window the firefly could reach is the result more than a little
        // above what the clean image denoises to.
        for (int y = py - 8; y <= py + 8; ++y) {
            for (int x = px - 8; x <= px + 8; ++x) {
                EXPECT_LE(luminance(result, x, y), 1.5f * luminance(reference, x, y) + 0.02f)
                    << "pixel " << x << ", " << y;
            }
        }
    }
}

TEST(Denoise, NoiseFreeImageIsLeftAsItIs) {
    // A checkerboard texture under a smooth gradient of light, with identical halves: no
    // noise, so no neighbour counts unless it is equal, and demodulation and remodulation
    // cancel. A filter that averaged across the texture's edges, or a firefly clamp that
    // took the top of the gradient for a firefly, would change pixels.
    const int w = 24, h = 20;
    Image image = make_image(w, h,
                             {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X",
                              "normal.Y", "normal.Z", "depth.Z"});
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float albedo = ((x / 3 + y / 3) % 2) ? 0.8f : 0.1f;
            const float light = 1.0f + 0.5f * std::sin(0.3f * x) * std::cos(0.2f * y);
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) = albedo * light * (1.0f + 0.1f * c);
                image.at(x, y, 3 + c) = albedo;
            }
            image.at(x, y, 8) = 1.0f;
            image.at(x, y, 9) = 2.0f;
        }
    }
    const Image result = denoise(image, image, image);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(result.at(x, y, c), image.at(x, y, c), 1e-5f * image.at(x, y, c))
                    << x << ", " << y;
            }
        }
    }
}

TEST(Denoise, BitIdenticalForAnyThreadCount) {
    const Halves one = render_halves(
        example_with_settings("cornell-box.lua",
                              "width = 40, height = 36, spp = 8, seed = 4, integrator = 'path'"),
        1);
    const Halves two = render_halves(
        example_with_settings("cornell-box.lua",
                              "width = 40, height = 36, spp = 8, seed = 4, integrator = 'path'"),
        2);
    EXPECT_EQ(one.a.pixels, two.a.pixels);
    EXPECT_EQ(one.b.pixels, two.b.pixels);
    // The denoiser on an image big enough for TBB to share its rows among threads: noisy
    // halves (a fixed pseudo-random sequence) over a few features.
    const int w = 160, h = 120;
    Image halves[2];
    uint32_t state = 12345;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    for (Image& half : halves) {
        half = make_image(w, h, one.full.channels);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                for (int c = 0; c < 3; ++c) {
                    half.at(x, y, c) = next() * (x < w / 2 ? 1.0f : 4.0f);
                    half.at(x, y, 3 + c) = (x / 8 + y / 8) % 2 ? 0.7f : 0.2f;
                }
                half.at(x, y, y < h / 2 ? 7 : 8) = 1.0f;
                half.at(x, y, 9) = 1.0f + 0.01f * x;
            }
        }
    }
    Image full = halves[0];
    for (size_t i = 0; i < full.pixels.size(); ++i)
        full.pixels[i] = 0.5f * (halves[0].pixels[i] + halves[1].pixels[i]);
    Image results[3];
    const int threads[3] = {1, 2, 4};
    for (int k = 0; k < 3; ++k) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads[k]);
        results[k] = denoise(full, halves[0], halves[1]);
    }
    EXPECT_EQ(results[0].pixels, results[1].pixels);
    EXPECT_EQ(results[0].pixels, results[2].pixels);
}

TEST(Denoise, MissingFeaturesOrSizesThrow) {
    const Image rgb = make_image(4, 4, {"R", "G", "B"});
    EXPECT_THROW(denoise(rgb, rgb, rgb), Error);
    const Film plain(4, 4, true);
    EXPECT_THROW(denoise(plain), Error);
}

class DenoiseCli : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = std::filesystem::temp_directory_path() /
                fmt::format("glint-denoise-{}-{}", info->name(), ::getpid());
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::string out(const std::string& name) const { return (m_dir / name).string(); }
    std::filesystem::path m_dir;
};

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const std::string kCornell = GLINT_SOURCE_DIR "/examples/cornell-box.lua";

TEST_F(DenoiseCli, WritesDenoisedOutputsBesideUnchangedNoisyOnes) {
    const auto plain = run_glint(fmt::format("render {} --res 32x32 --spp 4 -o {} -o {} --quiet",
                                             kCornell, out("plain.exr"), out("plain.png")));
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    // The network (the default) and the non-local means filter.
    for (const std::string method : {"", "nlm"}) {
        SCOPED_TRACE(method);
        const auto with =
            run_glint(fmt::format("render {} --res 32x32 --spp 4 --denoise {} -o {} -o {} --quiet",
                                  kCornell, method, out("noisy.exr"), out("noisy.png")));
        ASSERT_EQ(with.exit_code, 0) << with.output;
        // The noisy outputs are the same files a render without --denoise writes.
        EXPECT_EQ(read_bytes(out("noisy.exr")), read_bytes(out("plain.exr")));
        EXPECT_EQ(read_bytes(out("noisy.png")), read_bytes(out("plain.png")));
        const Image denoised = read_image(out("noisy.denoised.exr"));
        EXPECT_EQ(denoised.width, 32);
        EXPECT_GE(denoised.channel_index("R"), 0);
        EXPECT_TRUE(std::filesystem::exists(out("noisy.denoised.png")));
    }
}

TEST_F(DenoiseCli, RefusesWhatItCannotDenoise) {
    const auto bdpt =
        run_glint(fmt::format("render {} --res 16x16 --spp 4 --integrator bdpt "
                              "--denoise -o {} --quiet",
                              kCornell, out("x.exr")));
    EXPECT_EQ(bdpt.exit_code, 2);  // a refused combination of flags is a usage error
    EXPECT_NE(bdpt.output.find("--denoise"), std::string::npos) << bdpt.output;
    EXPECT_NE(bdpt.output.find("'bdpt'"), std::string::npos) << bdpt.output;
    // The non-local means filter needs two halves of at least one sample; the network not.
    const auto one = run_glint(fmt::format(
        "render {} --res 16x16 --spp 1 --denoise nlm -o {} --quiet", kCornell, out("x.exr")));
    EXPECT_EQ(one.exit_code, 2);
    EXPECT_NE(one.output.find("at least 2 samples"), std::string::npos) << one.output;
    EXPECT_FALSE(std::filesystem::exists(out("x.exr")));
    const auto network = run_glint(fmt::format(
        "render {} --res 16x16 --spp 1 --denoise -o {} --quiet", kCornell, out("x.exr")));
    EXPECT_EQ(network.exit_code, 0) << network.output;
    const auto unknown = run_glint(fmt::format(
        "render {} --res 16x16 --spp 1 --denoise median -o {} --quiet", kCornell, out("y.exr")));
    EXPECT_NE(unknown.exit_code, 0);
    EXPECT_NE(unknown.output.find("median"), std::string::npos) << unknown.output;
}

// Without the weights, --denoise fails before rendering, names the install step, and writes
// nothing; --denoise nlm still works.
TEST_F(DenoiseCli, MissingWeightsNameTheInstallStep) {
    const std::string env = "GLINT_DENOISE_WEIGHTS=" + out("no-weights") + " ";
    const auto missing =
        test::run_command(fmt::format("{}{} render {} --res 16x16 --spp 2 --denoise -o {} --quiet",
                                      env, test::glint_binary(), kCornell, out("x.exr")));
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.output.find("scripts/install-deps.sh"), std::string::npos) << missing.output;
    EXPECT_NE(missing.output.find("--denoise"), std::string::npos) << missing.output;
    EXPECT_FALSE(std::filesystem::exists(out("x.exr")));
    const auto nlm = test::run_command(
        fmt::format("{}{} render {} --res 16x16 --spp 2 --denoise nlm -o {} --quiet", env,
                    test::glint_binary(), kCornell, out("x.exr")));
    EXPECT_EQ(nlm.exit_code, 0) << nlm.output;
}

// The scene's settings choose the network's size; a bad one names the scene's line.
TEST_F(DenoiseCli, SceneChoosesQualityAndBadValuesNameTheLine) {
    const std::string scene = out("scene.lua");
    std::ofstream(scene)
        << "glint.render{ width = 16, height = 16, spp = 2, denoise = true,\n"
           "               denoise_quality = 'fast', output = '"
        << out("s.exr") << "' }\n"
        << "glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }\n"
        << "glint.sphere{ radius = 1, material = glint.diffuse{ reflectance = {0.5, 0.5, 0.5} } }\n"
        << "glint.point_light{ position = {0, 2, 2}, intensity = 5 }\n";
    const auto fast = run_glint(fmt::format("render {} --quiet", scene));
    EXPECT_EQ(fast.exit_code, 0) << fast.output;
    EXPECT_TRUE(std::filesystem::exists(out("s.denoised.exr")));
    const auto bad = run_glint(fmt::format("render {} --denoise-quality ultra --quiet", scene));
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.output.find("ultra"), std::string::npos) << bad.output;
    std::string text = read_bytes(scene);
    text.replace(text.find("'fast'"), 6, "'ultra'");
    std::ofstream(scene) << text;
    const auto bad_scene = run_glint(fmt::format("render {} --quiet", scene));
    EXPECT_EQ(bad_scene.exit_code, 1);
    EXPECT_NE(bad_scene.output.find("scene.lua:1"), std::string::npos) << bad_scene.output;
    EXPECT_NE(bad_scene.output.find("denoise_quality"), std::string::npos) << bad_scene.output;
}

}  // namespace
}  // namespace glint
