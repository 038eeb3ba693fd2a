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
#include <support/render_helpers.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace glint {
namespace {

using test::example_with_settings;
using test::run_glint;

// A render's whole image (with AOVs) and its two halves.
struct Halves {
    Image full, a, b;
};

Halves render_halves(const std::string& code, int threads = 0) {
    const SceneDesc desc =
        load_scene_string(code, "denoise_test.lua", GLINT_SOURCE_DIR "/examples");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    auto integrator = make_integrator(settings);
    Film film(settings.output_width(), settings.output_height(), true, settings.output_origin(),
              true);
    Progress progress("test", 1, true);
    if (threads > 0) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        integrator->render(*scene, film, progress);
    } else {
        integrator->render(*scene, film, progress);
    }
    return {film.resolve(), film.resolve_half(0), film.resolve_half(1)};
}

float luminance(const Image& image, int x, int y) {
    return 0.2126f * image.at(x, y, 0) + 0.7152f * image.at(x, y, 1) + 0.0722f * image.at(x, y, 2);
}

// The relative MSE of `test` (glint compare's: (t - r)^2 / (r^2 + 0.01)) against the
// converged image, over the pixels of `mask` (all when null). The reference is a render
// too: its own noise, estimated per pixel from its halves as (a - b)^2 / 4, is taken off,
// so that the figure is the test image's error, not the reference's.
double error_against(const Image& test, const Halves& ref,
                     const std::vector<uint8_t>* mask = nullptr) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            if (mask && !(*mask)[static_cast<size_t>(y) * test.width + x]) continue;
            ++count;
            for (int c = 0; c < 3; ++c) {
                const double r = ref.full.at(x, y, c), t = test.at(x, y, c);
                const double d = ref.a.at(x, y, c) - ref.b.at(x, y, c);
                sum += ((t - r) * (t - r) - 0.25 * d * d) / (r * r + 1e-2);
            }
        }
    }
    return sum / (3.0 * std::max(count, 1));
}

// Edge bands from the reference's features: geometry edges where the shading normal turns
// by more than 30 degrees or the depth jumps by more than 10 % between 4-neighbours;
// texture edges where only the albedo changes (by more than 0.15 in RGB length).
struct EdgeBands {
    std::vector<uint8_t> geometry, texture;
};
EdgeBands edge_bands(const Image& ref) {
    const int w = ref.width, h = ref.height;
    const int al = ref.channel_index("albedo.R"), no = ref.channel_index("normal.X"),
              de = ref.channel_index("depth.Z");
    EdgeBands bands{std::vector<uint8_t>(static_cast<size_t>(w) * h, 0),
                    std::vector<uint8_t>(static_cast<size_t>(w) * h, 0)};
    auto vec = [&](int x, int y, int c) {
        return Vec3(ref.at(x, y, c), ref.at(x, y, c + 1), ref.at(x, y, c + 2));
    };
    for (int y = 0; y + 1 < h; ++y) {
        for (int x = 0; x + 1 < w; ++x) {
            for (const Vec2i q : {Vec2i(x + 1, y), Vec2i(x, y + 1)}) {
                const float zp = ref.at(x, y, de), zq = ref.at(q.x, q.y, de);
                const bool geometry = glm::length(vec(x, y, no) - vec(q.x, q.y, no)) > 0.52f ||
                                      std::abs(zp - zq) > 0.1f * std::max(zp, zq);
                const bool texture = glm::length(vec(x, y, al) - vec(q.x, q.y, al)) > 0.15f;
                const size_t i = static_cast<size_t>(y) * w + x,
                             j = static_cast<size_t>(q.y) * w + q.x;
                if (geometry)
                    bands.geometry[i] = bands.geometry[j] = 1;
                else if (texture)
                    bands.texture[i] = bands.texture[j] = 1;
            }
        }
    }
    // A texture edge next to a geometry edge is a geometry edge.
    for (size_t i = 0; i < bands.texture.size(); ++i)
        if (bands.geometry[i]) bands.texture[i] = 0;
    return bands;
}

// Mean over the band of the largest luminance step from a pixel to a 4-neighbour: the
// edge's contrast, which blurring lowers.
double edge_contrast(const Image& image, const std::vector<uint8_t>& band) {
    double sum = 0.0;
    int count = 0;
    for (int y = 1; y + 1 < image.height; ++y) {
        for (int x = 1; x + 1 < image.width; ++x) {
            if (!band[static_cast<size_t>(y) * image.width + x]) continue;
            const float l = luminance(image, x, y);
            float step = 0.0f;
            for (const Vec2i q :
                 {Vec2i(x + 1, y), Vec2i(x - 1, y), Vec2i(x, y + 1), Vec2i(x, y - 1)})
                step = std::max(step, std::abs(l - luminance(image, q.x, q.y)));
            sum += step;
            ++count;
        }
    }
    return count > 0 ? sum / count : 0.0;
}

int band_size(const std::vector<uint8_t>& band) {
    int n = 0;
    for (uint8_t b : band) n += b;
    return n;
}

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

TEST(Denoise, CornellBoxErrorFourTimesLowerWithSharpEdges) {
    auto code = [](int spp, int seed) {
        return example_with_settings(
            "cornell-box.lua",
            fmt::format("width = 64, height = 64, spp = {}, seed = {}, integrator = 'path'", spp,
                        seed));
    };
    check_scene(code(16, 1), code(512, 2), false, 3.0);
}

constexpr double kTextureBandBound = 0.0066;

TEST(Denoise, TexturesErrorFourTimesLowerWithSharpEdges) {
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
    // Here the filter's gain beyond the clamp is small (measured 1.0 x): most of the
    // remaining error is around the rough glass, where 16 samples leave clusters of
    // bright paths in both halves; it must at least not add error.
    // The texture edges' error, recorded as 0.00438 and bounded with a margin of a half: without
    // the albedo demodulation it doubles (issue 28's mutation check), and only this bound sees it.
    check_scene(code(16, 1), code(128, 2), true, 0.95, kTextureBandBound);
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
    const auto with =
        run_glint(fmt::format("render {} --res 32x32 --spp 4 --denoise -o {} -o {} --quiet",
                              kCornell, out("noisy.exr"), out("noisy.png")));
    ASSERT_EQ(with.exit_code, 0) << with.output;
    // The noisy outputs are the same files a render without --denoise writes.
    EXPECT_EQ(read_bytes(out("noisy.exr")), read_bytes(out("plain.exr")));
    EXPECT_EQ(read_bytes(out("noisy.png")), read_bytes(out("plain.png")));
    const Image denoised = read_image(out("noisy.denoised.exr"));
    EXPECT_EQ(denoised.width, 32);
    EXPECT_GE(denoised.channel_index("R"), 0);
    EXPECT_TRUE(std::filesystem::exists(out("noisy.denoised.png")));
}

TEST_F(DenoiseCli, RefusesWhatItCannotDenoise) {
    const auto bdpt =
        run_glint(fmt::format("render {} --res 16x16 --spp 4 --integrator bdpt "
                              "--denoise -o {} --quiet",
                              kCornell, out("x.exr")));
    EXPECT_EQ(bdpt.exit_code, 2);  // a refused combination of flags is a usage error
    EXPECT_NE(bdpt.output.find("--denoise"), std::string::npos) << bdpt.output;
    EXPECT_NE(bdpt.output.find("'bdpt'"), std::string::npos) << bdpt.output;
    const auto one = run_glint(fmt::format("render {} --res 16x16 --spp 1 --denoise -o {} --quiet",
                                           kCornell, out("x.exr")));
    EXPECT_EQ(one.exit_code, 2);
    EXPECT_NE(one.output.find("at least 2 samples"), std::string::npos) << one.output;
    EXPECT_FALSE(std::filesystem::exists(out("x.exr")));
}

}  // namespace
}  // namespace glint
