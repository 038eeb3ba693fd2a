#include <glint/cluster/cluster.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/core/sampler.h>
#include <glint/film/image_io.h>
#include <glint/integrator/photon/photon_tracer.h>
#include <glint/integrator/photon/sppm.h>
#include <glint/integrator/transport/hash_grid.h>
#include <glint/integrator/transport/shading.h>
#include <glint/integrator/transport/spectral_model.h>
#include <glint/integrator/transport/transport.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <unordered_map>

namespace glint {
namespace {

constexpr float kAlpha = 2.0f / 3.0f;
constexpr int kMaxCameraDepth = 16;

struct VisiblePoint {
    SurfaceInteraction si;
    Spectrum beta{0.0f};  // camera path throughput up to the point
    bool valid = false;
};

struct PixelState {
    Spectrum direct{0.0f};  // emission and next-event estimates, summed over passes
    Spectrum tau{0.0f};     // accumulated flux (Hachisuka's tau)
    double photons = 0.0;   // N
    float radius = 0.0f;
};

// Follows a camera ray through specular surfaces to its first non-specular surface, where
// the visible point is; emission seen on the way and direct light there go to `direct`.
VisiblePoint find_visible_point(const Scene& scene, const Ray& ray, Sampler& sampler, Arena& arena,
                                Spectrum& direct, RayCounter& counter) {
    const SpecularChain chain = follow_specular_chain(scene, ray, Spectrum(1.0f), sampler, arena,
                                                      counter, kMaxCameraDepth, nullptr);
    direct += chain.emitted;
    if (chain.escaped) direct += chain.beta * scene.escaped_radiance(chain.ray.direction);
    if (!chain.hit) return {};
    // Photons of zero bounces are skipped below: direct light is estimated here.
    direct += chain.beta * estimate_direct_light(scene, *chain.hit, *chain.bsdf, sampler,
                                                 LightWeighting::kNone, counter);
    return {*chain.hit, chain.beta, true};
}

// The valid visible points in a grid whose radius is the largest of their radii: a photon
// finds every point whose own radius may reach it, and keeps those whose radius does.
struct VisiblePointGrid {
    VisiblePointGrid(const std::vector<VisiblePoint>& points,
                     const std::vector<PixelState>& pixels) {
        float max_radius = 0.0f;
        std::vector<Vec3> positions;
        for (size_t i = 0; i < points.size(); ++i) {
            if (!points[i].valid) continue;
            max_radius = std::max(max_radius, pixels[i].radius);
            positions.push_back(points[i].si.p);
            pixel_of.push_back(static_cast<uint32_t>(i));
        }
        grid.build(positions, std::max(max_radius, 1e-6f));
    }
    HashGrid grid;
    std::vector<uint32_t> pixel_of;  // the pixel of each point the grid holds
};

struct Deposit {
    uint32_t pixel;
    Spectrum flux;
};

// Deposits as bytes for the exchange: the pixel, then the flux's stored values.
constexpr size_t kDepositBytes = sizeof(uint32_t) + Spectrum::kStoredValues * sizeof(float);

std::vector<uint8_t> deposit_bytes(const std::vector<Deposit>& deposits) {
    std::vector<uint8_t> bytes(deposits.size() * kDepositBytes);
    uint8_t* out = bytes.data();
    for (const Deposit& d : deposits) {
        const auto values = d.flux.stored();
        std::memcpy(out, &d.pixel, sizeof(uint32_t));
        std::memcpy(out + sizeof(uint32_t), values.data(), values.size() * sizeof(float));
        out += kDepositBytes;
    }
    return bytes;
}

void append_deposits(const std::vector<uint8_t>& bytes, std::vector<Deposit>& deposits) {
    for (size_t at = 0; at + kDepositBytes <= bytes.size(); at += kDepositBytes) {
        Deposit d;
        std::array<float, Spectrum::kStoredValues> values;
        std::memcpy(&d.pixel, bytes.data() + at, sizeof(uint32_t));
        std::memcpy(values.data(), bytes.data() + at + sizeof(uint32_t),
                    values.size() * sizeof(float));
        d.flux = Spectrum::from_stored(values);
        deposits.push_back(d);
    }
}

// Every pass's deposits in photon order: this process's photons, or, in an MPI job, each
// rank's share (consecutive photon ranges) gathered in rank order.
template <typename Sinks>
std::vector<Deposit> deposits_in_photon_order(const Sinks& sinks, Cluster* cluster) {
    std::vector<Deposit> own;
    for (const auto& sink : sinks)
        own.insert(own.end(), sink.deposits.begin(), sink.deposits.end());
    if (!cluster) return own;
    std::vector<Deposit> all;
    for (const std::vector<uint8_t>& bytes : cluster->all_gather_bytes(deposit_bytes(own)))
        append_deposits(bytes, all);
    return all;
}

// The estimate after `passes` passes of `photons_per_pass` photons: the mean direct light
// plus the photon flux over the disc each pixel's radius has shrunk to.
Spectrum pixel_estimate(const PixelState& p, int passes, uint64_t photons_per_pass) {
    const double total_photons =
        static_cast<double>(passes) * static_cast<double>(photons_per_pass);
    const Spectrum indirect = p.tau / static_cast<float>(total_photons * kPi * p.radius * p.radius);
    return p.direct / static_cast<float>(passes) + indirect;
}

// Writes the image so far next to each output: NAME.pass0008.exr for OUT = NAME.exr.
void write_intermediate(const std::vector<PixelState>& pixels, int width, int height, int passes,
                        uint64_t photons_per_pass, const RenderSettings& settings) {
    Image image = make_image(width, height, {"R", "G", "B"});
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Spectrum L = pixel_estimate(pixels[static_cast<size_t>(y) * width + x], passes,
                                              photons_per_pass);
            const Rgb rgb = to_rgb(L);
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = rgb[c];
        }
    }
    for (const std::string& output : settings.outputs) {
        std::filesystem::path path(output);
        path.replace_extension(fmt::format(".pass{:04d}{}", passes, path.extension().string()));
        write_image(path.string(), image, WriteOptions{settings.exposure, settings.tonemap});
    }
}

}  // namespace

SppmSettings SppmSettings::read(const Params& p) {
    SppmSettings s;
    s.photons = p.get_int("photons", s.photons);
    s.photon_radius = p.get_float("photon_radius", s.photon_radius);
    s.intermediate = p.get_int("intermediate", s.intermediate);
    if (s.photons < 1) p.fail_at("photons", "'photons' must be at least 1");
    if (!(s.photon_radius >= 0.0f && s.photon_radius <= 1e12f))
        p.fail_at("photon_radius",
                  "'photon_radius' must be in [0, 1e12] (0: from the scene's size)");
    if (s.intermediate < 0)
        p.fail_at("intermediate",
                  "'intermediate' must not be negative (0 writes no intermediate images)");
    return s;
}

std::unique_ptr<Integrator> SppmIntegrator::create(const RenderSettings& settings,
                                                   const Params& params) {
    // sppm has no tile loop to check the sampler's name: check it here, before any scene
    // is built, and say where it came from.
    try {
        make_sampler(settings.sampler, settings.spp, settings.seed);
    } catch (const Error& e) {
        throw Error(fmt::format("{}: {}", settings.where_of("sampler"), e.what()));
    }
    return std::make_unique<SppmIntegrator>(settings, SppmSettings::read(params));
}

RenderStats SppmIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const int w = film.width(), h = film.height();
    const size_t pixel_count = static_cast<size_t>(w) * h;
    const int passes = m_settings.spp;
    const uint64_t photons_per_pass = static_cast<uint64_t>(m_sppm.photons);
    const SceneStats& stats_in = scene.stats();
    const float scene_size =
        stats_in.bounds.is_empty() ? 1.0f : glm::length(stats_in.bounds.extent());
    const float initial_radius =
        m_sppm.photon_radius > 0.0f ? m_sppm.photon_radius : scene_size / 256.0f;

    std::vector<PixelState> pixels(pixel_count);
    for (PixelState& p : pixels) p.radius = initial_radius;
    std::vector<VisiblePoint> points(pixel_count);
    const auto prototype = make_sampler(m_settings.sampler, passes, m_settings.seed);
    PhotonTracer tracer(scene, m_settings.max_depth >= 0 ? m_settings.max_depth : 32);
    RenderStats stats;
    int stats_intermediate = 0;

    for (int pass = 0; pass < passes; ++pass) {
        // Spectral mode: the camera points and the photons of a pass carry the same
        // wavelengths (a photon's flux is read at the points it meets); the passes'
        // wavelengths stratify the spectrum (pass_wavelengths), and what a pass adds to a pixel is
        // resolved to RGB before it is summed.
        const WavelengthContext this_pass =
            pass_wavelengths(mix_bits(m_settings.seed ^ 0x59b3u), static_cast<uint32_t>(pass));
        const WavelengthContext* spectral = m_settings.spectral ? &this_pass : nullptr;
        tracer.use_wavelengths(spectral);

        // 1. Visible points, one per pixel, keyed by (seed, pixel, pass).
        std::atomic<uint64_t> camera_rays{0};
        tbb::parallel_for(0, h, [&](int y) {
            std::optional<WavelengthScope> wavelengths;
            if (spectral != nullptr) wavelengths.emplace(*spectral);
            auto sampler = prototype->clone();
            Arena arena;
            RayCounter counter;
            for (int x = 0; x < w; ++x) {
                // The film may be a crop window: pixels are named in the full image.
                const Vec2i pixel = film.origin() + Vec2i(x, y);
                sampler->start_pixel_sample(pixel, pass);
                const Vec2 film_point = Vec2(pixel) + sampler->get_pixel_2d();
                const Ray ray = scene.camera().sample_ray(film_point, *sampler);
                const size_t i = static_cast<size_t>(y) * w + x;
                arena.reset();
                std::optional<SecondaryWavelengthsScope> terminated;  // this pixel's path's
                if (spectral != nullptr) terminated.emplace();
                if (spectral == nullptr) {
                    points[i] =
                        find_visible_point(scene, ray, *sampler, arena, pixels[i].direct, counter);
                } else {
                    Spectrum direct(0.0f);
                    points[i] = find_visible_point(scene, ray, *sampler, arena, direct, counter);
                    pixels[i].direct += resolved_to_rgb(direct);
                }
            }
            camera_rays += counter.rays;
        });
        stats.rays += camera_rays.load();

        // 2-3. Photons add their flux to the visible points within each point's radius.
        const VisiblePointGrid grid(points, pixels);
        auto make_sink = [&] {
            struct Sink {
                const std::vector<VisiblePoint>* points;
                const std::vector<PixelState>* pixels;
                const VisiblePointGrid* grid;
                HashGrid::Cache cache;
                std::vector<Deposit> deposits;
                Arena arena{4096};
                void store(const PhotonHit& hit) {
                    if (hit.bounces == 0) return;  // direct light comes from next-event estimation
                    // A photon adds to each pixel at most once, so the order of the visits
                    // leaves every pixel's sum as it is.
                    grid->grid.for_each_near(hit.si->p, cache, [&](uint32_t k, float distance2) {
                        const uint32_t i = grid->pixel_of[k];
                        const VisiblePoint& vp = (*points)[i];
                        const float r = (*pixels)[i].radius;
                        if (distance2 > r * r) return;
                        arena.reset();
                        // vp.si already has its final shading frame: no second bump.
                        const Bsdf* bsdf = vp.si.material->bsdf(vp.si, arena);
                        const Spectrum f =
                            bsdf->eval(vp.si.to_local(vp.si.wo), vp.si.to_local(hit.wi));
                        if (f.is_black()) return;
                        deposits.push_back({i, resolved_to_rgb(vp.beta * f * hit.power)});
                    });
                }
            };
            return Sink{&points, &pixels, &grid, {}, {}, Arena{4096}};
        };
        const auto [first, end] = m_cluster ? m_cluster->share(photons_per_pass)
                                            : std::pair<uint64_t, uint64_t>{0, photons_per_pass};
        const auto sinks = tracer.trace(static_cast<uint64_t>(pass) * photons_per_pass + first,
                                        end - first, m_settings.seed, stats.rays, make_sink);

        // 4. Progressive update, in a fixed order.
        std::vector<Spectrum> flux(pixel_count);
        std::vector<uint32_t> found(pixel_count, 0);
        for (const Deposit& d : deposits_in_photon_order(sinks, m_cluster)) {
            flux[d.pixel] += d.flux;
            ++found[d.pixel];
        }
        for (size_t i = 0; i < pixel_count; ++i) {
            PixelState& p = pixels[i];
            if (found[i] == 0) continue;
            const double n_new = p.photons + kAlpha * found[i];
            const float r_new =
                p.radius * static_cast<float>(std::sqrt(n_new / (p.photons + found[i])));
            p.tau = (p.tau + flux[i]) * ((r_new * r_new) / (p.radius * p.radius));
            p.photons = n_new;
            p.radius = r_new;
        }
        progress.advance(pixel_count);
        const int done = pass + 1;
        if (m_sppm.intermediate > 0 && done % m_sppm.intermediate == 0 && done < passes) {
            write_intermediate(pixels, w, h, done, photons_per_pass, m_settings);
            ++stats_intermediate;
        }
    }
    if (stats_intermediate > 0) {
        stats.notes.push_back(
            fmt::format("sppm: wrote the image after every {} passes ({} intermediate images)",
                        m_sppm.intermediate, stats_intermediate));
    }

    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            film.add_sample(
                film.origin() + Vec2i(x, y),
                pixel_estimate(pixels[static_cast<size_t>(y) * w + x], passes, photons_per_pass),
                1.0f, nullptr);
        }
    }
    stats.samples = pixel_count * static_cast<uint64_t>(passes);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace glint
