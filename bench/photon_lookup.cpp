// Photon-map lookup cost against the number of stored photons (issue 17): k-nearest queries
// at a fixed k should cost about the same for any photon count. Photons lie on the floor and
// the back wall of a unit box (as a global map's do, on surfaces); queries are at random points
// of both planes and of a plane halfway between (where few photons lie within the cap).
// Prints nanoseconds per query and photons examined per query. Not part of CI.
#include <glint/integrator/photon/photon_map.h>

#include <fmt/format.h>

#include <chrono>
#include <random>

using namespace glint;

namespace {

Vec3 on_surfaces(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float a = u(rng), b = u(rng);
    return u(rng) < 0.5f ? Vec3(a, 0.0f, b) : Vec3(a, b, 0.0f);
}

}  // namespace

int main(int argc, char** argv) {
    const int k = argc > 1 ? std::atoi(argv[1]) : 50;
    const float max_radius = argc > 2 ? std::strtof(argv[2], nullptr) : std::sqrt(3.0f) / 20.0f;
    fmt::print("k = {}, maximum radius {:.4f} (box diagonal / 20 = {:.4f})\n", k, max_radius,
               std::sqrt(3.0f) / 20.0f);
    fmt::print("{:>9} {:>12} {:>12} {:>12} {:>12}\n", "photons", "ns/query", "examined", "ns (mid)",
               "exam. (mid)");
    for (int n : {4000, 16000, 64000, 129000, 512000, 2000000}) {
        std::mt19937 rng(7);
        std::vector<Photon> photons(static_cast<size_t>(n));
        for (Photon& p : photons) p = {on_surfaces(rng), Vec3(0, 1, 0), Spectrum(1.0f)};
        const PhotonMap map(std::move(photons));
        std::vector<std::pair<float, uint32_t>> found;
        auto run = [&](bool mid) {
            std::mt19937 qrng(11);
            std::uniform_real_distribution<float> u(0.0f, 1.0f);
            const int queries = 200000;
            uint64_t examined = 0;
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < queries; ++i) {
                const Vec3 q = mid ? Vec3(u(qrng), 0.5f * u(qrng), 0.5f) : on_surfaces(qrng);
                examined += map.nearest(q, k, max_radius * max_radius, found);
            }
            const double ns =
                std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start)
                    .count();
            return std::pair{ns / queries, static_cast<double>(examined) / queries};
        };
        const auto [ns, examined] = run(false);
        const auto [ns_mid, examined_mid] = run(true);
        fmt::print("{:>9} {:>12.0f} {:>12.1f} {:>12.0f} {:>12.1f}\n", n, ns, examined, ns_mid,
                   examined_mid);
    }
}
