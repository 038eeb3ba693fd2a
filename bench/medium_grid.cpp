// Majorant grid against one global majorant on a sparse cloud: the time each takes to
// estimate the transmittance of a set of rays to the same error. Both run the same code (a
// 1x1x1 majorant grid is one global bound), single-threaded; see bench/README.md.
//
//   glint_bench_medium_grid [--rays N] [--target-mse E] [--sigma S] [--resolution R]
#include <glint/core/rng.h>
#include <glint/medium/delta_tracking.h>
#include <glint/medium/grid/fbm_cloud.h>
#include <glint/medium/heterogeneous_medium.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace glint;

namespace {

struct Options {
    int rays = 400;
    double target_mse = 1e-4;
    float sigma = 60.0f;  // extinction per unit at density 1: a thick cloud, 2 units across
    int resolution = 16;  // majorant cells per axis
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        if (key == "--rays")
            o.rays = std::atoi(argv[i + 1]);
        else if (key == "--target-mse")
            o.target_mse = std::atof(argv[i + 1]);
        else if (key == "--sigma")
            o.sigma = float(std::atof(argv[i + 1]));
        else if (key == "--resolution")
            o.resolution = std::atoi(argv[i + 1]);
        else {
            fmt::print(stderr, "unknown option {}\n", key);
            std::exit(2);
        }
    }
    return o;
}

// Rays from points on a sphere of radius 3 round the cloud towards points inside its box.
std::vector<Ray> make_rays(int count) {
    Rng rng(2029);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const float z = 2.0f * rng.next_float() - 1.0f, phi = 6.2831853f * rng.next_float();
        const float r = std::sqrt(1.0f - z * z);
        const Vec3 origin = 3.0f * Vec3(r * std::cos(phi), r * std::sin(phi), z);
        const Vec3 target(2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f,
                          2.0f * rng.next_float() - 1.0f);
        rays.push_back(Ray{origin, glm::normalize(target - origin)});
    }
    return rays;
}

// exp(-optical depth) from 4000-step midpoint quadrature over the ray's 6 units.
double reference_transmittance(const Medium& medium, const Ray& ray) {
    const int steps = 4000;
    const double h = 6.0 / steps;
    double depth = 0.0;
    for (int i = 0; i < steps; ++i) {
        const MediumPoint p = medium.at(ray.at(float((i + 0.5) * h)));
        depth += (p.sigma_a + p.sigma_s).value(0) * h;
    }
    return std::exp(-depth);
}

struct Run {
    double seconds = 0.0;
    double mse = 0.0;       // of the per-ray means against the reference
    double variance = 0.0;  // of one estimate, averaged over rays
    long samples = 0;
};

// `samples` estimates per ray, by ratio tracking (medium.transmittance) or by delta tracking
// (the escape indicator of sample_collisions, what volpath's distance sampling costs).
Run measure(const Medium& medium, const std::vector<Ray>& rays,
            const std::vector<double>& reference, int samples, bool delta) {
    Run run;
    Rng rng(7);
    std::vector<double> sum(rays.size(), 0.0), sum2(rays.size(), 0.0);
    const auto start = std::chrono::steady_clock::now();
    for (size_t r = 0; r < rays.size(); ++r) {
        for (int s = 0; s < samples; ++s) {
            float value;
            if (delta) {
                bool collided = false;
                sample_collisions(
                    medium, rays[r], 6.0f, 0, rng,
                    [&](float, const MediumPoint& p, const Spectrum& sigma_maj, const Spectrum&) {
                        collided = rng.next_float() * sigma_maj.value(0) <
                                   (p.sigma_a + p.sigma_s).value(0);
                        return !collided;
                    });
                value = collided ? 0.0f : 1.0f;
            } else {
                value = medium.transmittance(rays[r], 6.0f, rng).value(0);
            }
            sum[r] += value;
            sum2[r] += double(value) * value;
        }
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (size_t r = 0; r < rays.size(); ++r) {
        const double mean = sum[r] / samples;
        run.mse += (mean - reference[r]) * (mean - reference[r]) / rays.size();
        run.variance += (sum2[r] / samples - mean * mean) / rays.size();
    }
    run.samples = long(samples) * long(rays.size());
    return run;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    const VoxelGrid cloud =
        make_fbm_cloud({.resolution = 128, .coverage = 0.5f}, Bounds3{Vec3(-1.0f), Vec3(1.0f)});
    long occupied = 0;
    for (int z = 0; z < 128; ++z)
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) occupied += cloud.voxel(x, y, z) > 0.0f;
    fmt::print(
        "cloud: 128^3 voxels, {:.1f} % non-empty, max density {:.3f}; sigma_t {} at "
        "density 1; {} rays\n",
        100.0 * occupied / (128.0 * 128 * 128), cloud.max_value(), o.sigma, o.rays);
    const Rgb sigma_s(o.sigma * 0.8f), sigma_a(o.sigma * 0.2f);
    const HeterogeneousMedium grid_medium(cloud, Transform(), sigma_a, sigma_s, 0.0f, o.resolution);
    const HeterogeneousMedium global_medium(cloud, Transform(), sigma_a, sigma_s, 0.0f, 1);
    const std::vector<Ray> rays = make_rays(o.rays);
    std::vector<double> reference;
    for (const Ray& ray : rays) reference.push_back(reference_transmittance(grid_medium, ray));

    for (const bool delta : {false, true}) {
        fmt::print("\n{} (target MSE {:g} of the per-ray mean):\n",
                   delta ? "delta tracking (escape indicator)" : "ratio tracking", o.target_mse);
        double times[2] = {0, 0};
        int i = 0;
        for (const HeterogeneousMedium* medium : {&grid_medium, &global_medium}) {
            // A pilot run gives each estimator's variance per sample, and from it the samples
            // per ray that reach the target error; the timed run then takes that many.
            const Run pilot = measure(*medium, rays, reference, 64, delta);
            const int samples = std::max(1, int(std::ceil(pilot.variance / o.target_mse)));
            const Run run = measure(*medium, rays, reference, samples, delta);
            times[i++] = run.seconds;
            fmt::print(
                "  {:>20}: {:6d} samples/ray, {:8.3f} s, MSE {:.3g}, {:.3f} us/sample, "
                "variance/sample {:.4g}\n",
                medium == &grid_medium ? fmt::format("majorant grid {}^3", o.resolution)
                                       : std::string("one global majorant"),
                samples, run.seconds, run.mse, 1e6 * run.seconds / run.samples, run.variance);
        }
        fmt::print("  time to equal error: the majorant grid is {:.1f}x sooner\n",
                   times[1] / times[0]);
    }
    return 0;
}
