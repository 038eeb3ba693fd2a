// Times the network denoiser (denoise/network_denoiser.h) on an image of a given size:
// prints, per network size and thread count, the best wall-clock time of REPEATS runs and
// the processor time of that run (all threads), each per megapixel, and the memory the
// network holds for one tile. On a loaded machine the processor time is the figure to
// compare: the wall-clock time counts the time other processes held the cores.
//
//   glint_bench_denoise_network [WIDTH HEIGHT [REPEATS [IMAGE.exr]]]
// Without an image, a synthetic one (a noisy gradient with features) of WIDTH x HEIGHT.
// REPEATS 0 prints only the memory (e.g. of a 4K image: 3840 2160 0).
#include <glint/denoise/network_denoiser.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <random>
#include <string>

using namespace glint;

namespace {

Image synthetic_image(int width, int height) {
    Image image = make_image(
        width, height,
        {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z"});
    std::mt19937 rng(1);
    std::exponential_distribution<float> noise(1.f);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float shade = 0.2f + 0.8f * static_cast<float>(x) / static_cast<float>(width);
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) = shade * noise(rng);
                image.at(x, y, 3 + c) = (x / 32 + y / 32) % 2 ? 0.8f : 0.3f;
            }
            image.at(x, y, 8) = 1.f;
        }
    }
    return image;
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::stoi(argv[1]) : 1024;
    const int height = argc > 2 ? std::stoi(argv[2]) : 1024;
    const int repeats = argc > 3 ? std::stoi(argv[3]) : 3;
    const Image image = argc > 4 ? read_image(argv[4]) : synthetic_image(width, height);
    if (repeats == 0) {
        for (const auto& [name, quality] : {std::pair{"fast", DenoiseQuality::Fast},
                                            std::pair{"balanced", DenoiseQuality::Balanced},
                                            std::pair{"high", DenoiseQuality::High}}) {
            NetworkDenoiseSettings settings;
            settings.quality = quality;
            fmt::print(
                "{}x{} {}: {:.0f} MB at the peak (besides the image)\n", width, height, name,
                static_cast<double>(denoise_network_memory(width, height, settings)) / (1 << 20));
        }
        return 0;
    }
    const double megapixels = image.width * static_cast<double>(image.height) * 1e-6;
    fmt::print("{}x{} ({:.3f} Mpixel), best of {}\n", image.width, image.height, megapixels,
               repeats);
    fmt::print("{:<9} {:>7} {:>12} {:>12} {:>10}\n", "quality", "threads", "wall s/MP", "cpu s/MP",
               "peak MB");
    for (const auto& [name, quality] :
         {std::pair{"fast", DenoiseQuality::Fast}, std::pair{"balanced", DenoiseQuality::Balanced},
          std::pair{"high", DenoiseQuality::High}}) {
        for (int threads : {1, 2}) {
            NetworkDenoiseSettings settings;
            settings.quality = quality;
            settings.threads = threads;
            double best_wall = repeats > 0 ? 1e30 : 0.0, best_cpu = 0.0;
            for (int r = 0; r < repeats; ++r) {
                const auto start = std::chrono::steady_clock::now();
                const std::clock_t cpu_start = std::clock();
                denoise_network(image, settings);
                const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
                const double wall =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (wall < best_wall) {
                    best_wall = wall;
                    best_cpu = cpu;
                }
            }
            const double mb =
                static_cast<double>(denoise_network_memory(image.width, image.height, settings)) /
                (1 << 20);
            fmt::print("{:<9} {:>7} {:>12.2f} {:>12.2f} {:>10.0f}\n", name, threads,
                       best_wall / megapixels, best_cpu / megapixels, mb);
        }
    }
    return 0;
}
