// Throughput of Embree alone on a glint scene: random incoherent rays through the scene's
// acceleration structure, with no shading, sampling or film around them. The ratio of the
// renderer's rays/s to this number says how much the path tracer costs on top of Embree.
//
//   glint_bench_embree [scene.lua] [--rays N] [--threads T]
//
// Rays start uniformly inside the scene bounds and go in uniformly random directions, so
// neighbouring rays share nothing (like the deeper bounces of a path tracer). Half of them
// are closest-hit queries to infinity, half are occlusion queries between two random points
// in the bounds, the mix a path tracer with next-event estimation issues.
#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/math/warp.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

namespace {

using namespace glint;

constexpr uint64_t kRaysPerChunk = 4096;

struct Options {
    std::string scene = "examples/cornell-box.lua";
    uint64_t rays = 20'000'000;
    int threads = 0;  // 0 = all cores
};

void usage() {
    fmt::print(stderr,
               "usage: glint_bench_embree [scene.lua] [--rays N] [--threads T]\n"
               "  scene.lua   scene to trace (default examples/cornell-box.lua)\n"
               "  --rays N    number of rays (default 2e7; 2e7 notation is accepted)\n"
               "  --threads T worker threads (default: all cores)\n");
}

// Parses a positive count, accepting "20000000" as well as "2e7".
std::optional<double> parse_count(const char* text) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(value >= 1.0) || value > 1e15) return std::nullopt;
    return value;
}

std::optional<Options> parse_options(int argc, char** argv) {
    Options options;
    bool have_scene = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") return std::nullopt;
        if ((arg == "--rays" || arg == "--threads") && i + 1 < argc) {
            const std::optional<double> value = parse_count(argv[++i]);
            if (!value) return std::nullopt;
            if (arg == "--rays")
                options.rays = static_cast<uint64_t>(*value);
            else
                options.threads = static_cast<int>(*value);
        } else if (!arg.empty() && arg[0] != '-' && !have_scene) {
            options.scene = arg;
            have_scene = true;
        } else {
            return std::nullopt;
        }
    }
    return options;
}

Vec3 uniform_in(const Bounds3& bounds, Rng& rng) {
    const Vec3 u(rng.next_float(), rng.next_float(), rng.next_float());
    return bounds.min + u * bounds.extent();
}

// Traces rays [begin, end) of chunk `chunk`; returns how many hit (or were occluded).
uint64_t trace_chunk(const Accel& accel, const Bounds3& bounds, uint64_t chunk, uint64_t begin,
                     uint64_t end) {
    Rng rng(chunk);
    uint64_t hits = 0;
    for (uint64_t i = begin; i < end; ++i) {
        const Vec3 origin = uniform_in(bounds, rng);
        if (i % 2 == 0) {
            const Vec3 direction =
                warp::square_to_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
            hits += accel.intersect(Ray{origin, direction, 0.0f, kInfinity}).has_value();
        } else {
            // A shadow ray as the path tracer spawns it: unnormalised, stopping just short
            // of the target point.
            const Vec3 target = uniform_in(bounds, rng);
            hits += accel.occluded(Ray{origin, target - origin, 0.0f, 1.0f - 1e-4f});
        }
    }
    return hits;
}

// Traces `rays` rays in chunks of kRaysPerChunk on the current TBB arena; returns the hits.
uint64_t trace(const Accel& accel, const Bounds3& bounds, uint64_t rays) {
    const uint64_t chunks = (rays + kRaysPerChunk - 1) / kRaysPerChunk;
    std::atomic<uint64_t> hits{0};
    tbb::parallel_for(tbb::blocked_range<uint64_t>(0, chunks, 1),
                      [&](const tbb::blocked_range<uint64_t>& range) {
                          uint64_t local = 0;
                          for (uint64_t c = range.begin(); c < range.end(); ++c) {
                              const uint64_t begin = c * kRaysPerChunk;
                              const uint64_t end = std::min(begin + kRaysPerChunk, rays);
                              local += trace_chunk(accel, bounds, c, begin, end);
                          }
                          hits += local;
                      });
    return hits.load();
}

int run(const Options& options) {
    const SceneDesc desc = load_scene_file(options.scene);
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    const Bounds3 bounds = scene->stats().bounds;
    if (bounds.is_empty()) throw Error(fmt::format("scene '{}' has no geometry", options.scene));

    const int threads =
        options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);

    // Untimed warm-up: page in the BVH and start the worker threads.
    trace(scene->accel(), bounds, std::min<uint64_t>(options.rays / 20 + 1, 1'000'000));

    const auto start = std::chrono::steady_clock::now();
    const uint64_t hits = trace(scene->accel(), bounds, options.rays);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    fmt::print("embree bare: {} rays in {:.2f} s = {:.2f} M rays/s ({} threads)\n", options.rays,
               seconds, options.rays / seconds * 1e-6, threads);
    fmt::print("scene {}: {} triangles, {} shapes, {:.1f}% of rays hit or were occluded\n",
               options.scene, scene->stats().triangles, scene->stats().shapes,
               100.0 * static_cast<double>(hits) / static_cast<double>(options.rays));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<Options> options = parse_options(argc, argv);
    if (!options) {
        usage();
        return 2;
    }
    try {
        return run(*options);
    } catch (const glint::Error& e) {
        fmt::print(stderr, "glint_bench_embree: error: {}\n", e.what());
        return 1;
    }
}
