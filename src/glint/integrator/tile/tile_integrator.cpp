#include <glint/core/arena.h>
#include <glint/core/cancel.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/core/sampler.h>
#include <glint/integrator/tile/tile_integrator.h>
#include <glint/integrator/transport/spectral_model.h>

#include <fmt/format.h>
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <chrono>

namespace glint {

namespace {

constexpr int kTileSize = 16;

// Luminance compressed to [0, 1) so that edge thresholds mean the same in dark and bright
// images.
float tone(const Image& image, int x, int y) {
    const float l = Rgb(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)).luminance();
    return l / (1.0f + std::max(0.0f, l));
}

// Pixels where the Sobel gradient of the tone-mapped luminance exceeds `threshold`, grown
// by `radius` pixels so that both sides of every edge are refined.
std::vector<uint8_t> sobel_edge_mask(const Image& image, float threshold, int radius) {
    const int w = image.width, h = image.height;
    auto at = [&](int x, int y) {
        return tone(image, std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1));
    };
    std::vector<uint8_t> edges(static_cast<size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float gx = (at(x + 1, y - 1) + 2 * at(x + 1, y) + at(x + 1, y + 1)) -
                             (at(x - 1, y - 1) + 2 * at(x - 1, y) + at(x - 1, y + 1));
            const float gy = (at(x - 1, y + 1) + 2 * at(x, y + 1) + at(x + 1, y + 1)) -
                             (at(x - 1, y - 1) + 2 * at(x, y - 1) + at(x + 1, y - 1));
            edges[static_cast<size_t>(y) * w + x] = std::sqrt(gx * gx + gy * gy) / 4.0f > threshold;
        }
    }
    std::vector<uint8_t> mask(edges.size(), 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!edges[static_cast<size_t>(y) * w + x]) continue;
            for (int dy = -radius; dy <= radius; ++dy) {
                for (int dx = -radius; dx <= radius; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < w && ny < h)
                        mask[static_cast<size_t>(ny) * w + nx] = 1;
                }
            }
        }
    }
    return mask;
}

}  // namespace

TileIntegrator::TileIntegrator(const RenderSettings& settings) : m_settings(settings) {
    // Check the names now, before any scene is built, and say where each came from.
    blame_setting(settings, "filter",
                  [&] { m_filter = make_filter(settings.filter, settings.filter_radius); });
    blame_setting(settings, "sampler",
                  [&] { make_sampler(settings.sampler, settings.spp, settings.seed); });
    blame_setting(settings, "adaptive", [&] {
        if (settings.adaptive != "none" && settings.adaptive != "sobel" &&
            settings.adaptive != "variance") {
            throw Error(fmt::format("unknown adaptive mode '{}' (expected: none, sobel, variance)",
                                    settings.adaptive));
        }
    });
}

RenderStats TileIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const uint64_t prepare_rays = prepare(scene);
    m_prepared = false;  // render() may be given another scene each time than the passes
    RenderStats stats = render_tiles(scene, film, progress);
    stats.rays += prepare_rays;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

RenderStats TileIntegrator::render_tiles(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    // A crop window: samples never leave their pixel (filter importance sampling), but
    // adaptive sampling decides from neighbours; so render the window widened by how far
    // those decisions reach (clipped to the image, where the full render clips too), and
    // keep the window. Its pixels then get exactly the samples the full render gives them.
    const int reach = adaptive_reach();
    const Vec2i window_end = film.origin() + Vec2i(film.width(), film.height());
    const Vec2i lo = glm::max(film.origin() - reach, Vec2i(0));
    const Vec2i hi = glm::min(window_end + reach, Vec2i(m_settings.width, m_settings.height));
    if (lo == film.origin() && hi == window_end) {
        render_window(scene, film, progress, stats);
    } else {
        Film wider(hi.x - lo.x, hi.y - lo.y, film.has_aovs(), lo, film.has_halves());
        render_window(scene, wider, progress, stats);
        film = wider.window(film.origin(), film.width(), film.height());
        for (ExtraChannel& channel : stats.channels) {
            std::vector<float> values;
            for (int y = film.origin().y; y < window_end.y; ++y) {
                for (int x = film.origin().x; x < window_end.x; ++x) {
                    values.push_back(
                        channel.values[static_cast<size_t>(y - lo.y) * wider.width() + (x - lo.x)]);
                }
            }
            channel.values = std::move(values);
        }
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

void TileIntegrator::add_luminance_view(const Scene& scene, const Film& film, bool& view,
                                        const std::string& name, RenderStats& stats) {
    Film view_film(film.width(), film.height(), false, film.origin());
    Progress quiet(name, 1, true);
    view = true;
    const RenderStats view_stats = render_tiles(scene, view_film, quiet);
    view = false;
    const Image image = view_film.resolve();
    ExtraChannel channel{name, {}};
    channel.values.reserve(static_cast<size_t>(image.width) * static_cast<size_t>(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            channel.values.push_back(
                Rgb(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)).luminance());
    stats.channels.push_back(std::move(channel));
    stats.rays += view_stats.rays;
}

RenderStats TileIntegrator::render_pass(const Scene& scene, Film& film, int pass,
                                        Progress& progress) {
    if (pass < 0 || pass >= m_settings.spp) {
        throw Error(fmt::format("pass {} is outside the {} samples per pixel of the sampler", pass,
                                m_settings.spp));
    }
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    if (!m_prepared) {
        stats.rays = prepare(scene);
        m_prepared = true;
    }
    // Made exactly as render_uniform makes it (samplers are cheap to make): sample `pass`
    // of a pixel is then the same numbers as in a render with spp samples.
    const auto sampler = make_sampler(m_settings.sampler, m_settings.spp, m_settings.seed);
    stats.rays +=
        for_each_pixel(film, *sampler, progress, nullptr, [&](Vec2i pixel, Worker& worker) {
            render_pixel(scene, film, pixel, worker, pass, 1);
            return uint64_t{1};
        });
    stats.samples = static_cast<uint64_t>(film.width()) * film.height();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

RenderStats TileIntegrator::render_samples(const Scene& scene, Film& film, int first, int end,
                                           Progress& progress) {
    if (first < 0 || first > end || end > m_settings.spp) {
        throw Error(
            fmt::format("samples [{}, {}) are outside the {} samples per pixel of the sampler",
                        first, end, m_settings.spp));
    }
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    stats.rays = prepare(scene);
    m_prepared = false;
    // Made exactly as render_uniform makes it, for all spp samples: sample i of a pixel is
    // then the same numbers as in the whole render.
    const auto sampler = make_sampler(m_settings.sampler, m_settings.spp, m_settings.seed);
    const int count = end - first;
    if (count > 0) {
        stats.rays +=
            for_each_pixel(film, *sampler, progress, nullptr, [&](Vec2i pixel, Worker& worker) {
                render_pixel(scene, film, pixel, worker, first, count);
                return static_cast<uint64_t>(count);
            });
    }
    stats.samples = static_cast<uint64_t>(film.width()) * film.height() * count;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

void TileIntegrator::scene_changed(SceneChange change) {
    // Photon maps live in world space: a camera move keeps them.
    if (change == SceneChange::lights_or_objects) m_prepared = false;
}

void TileIntegrator::render_window(const Scene& scene, Film& film, Progress& progress,
                                   RenderStats& stats) const {
    if (m_settings.adaptive == "sobel")
        render_edge_adaptive(scene, film, progress, stats);
    else if (m_settings.adaptive == "variance")
        render_variance_adaptive(scene, film, progress, stats);
    else
        render_uniform(scene, film, progress, stats);
}

int TileIntegrator::adaptive_reach() const {
    // sobel: the edge mask at a pixel depends on the preview's 3 x 3 Sobel neighbourhood,
    // dilated by edge_radius.
    if (m_settings.adaptive == "sobel") return 1 + m_settings.edge_radius;
    if (m_settings.adaptive != "variance") return 0;
    // variance: each round's decision looks at the 8 neighbours, whose counts came from
    // the rounds before: one pixel further per round. Rounds: spp, then doubling to the cap.
    const int cap =
        m_settings.max_spp > 0 ? std::max(m_settings.max_spp, m_settings.spp) : 8 * m_settings.spp;
    int rounds = 1;
    for (int64_t taken = m_settings.spp; taken < cap; taken *= 2) ++rounds;
    return rounds + 1;
}

template <typename Work>
uint64_t TileIntegrator::for_each_pixel(const Film& film, const Sampler& prototype,
                                        Progress& progress, const std::vector<uint8_t>* wanted,
                                        Work&& work) const {
    const int width = film.width(), height = film.height();
    const Vec2i origin = film.origin();
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = (height + kTileSize - 1) / kTileSize;
    std::atomic<uint64_t> total_rays{0};
    // Each pixel is rendered by exactly one task and its random numbers depend only on
    // (seed, pixel, sample index), so the image does not depend on scheduling.
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, tiles_y, 1, 0, tiles_x, 1),
        [&](const tbb::blocked_range2d<int>& range) {
            const std::unique_ptr<Worker> worker_owner = make_worker(prototype);
            Worker& worker = *worker_owner;
            for (int ty = range.rows().begin(); ty < range.rows().end(); ++ty) {
                for (int tx = range.cols().begin(); tx < range.cols().end(); ++tx) {
                    const int x0 = tx * kTileSize, y0 = ty * kTileSize;
                    const int x1 = std::min(x0 + kTileSize, width),
                              y1 = std::min(y0 + kTileSize, height);
                    uint64_t samples = 0;
                    for (int y = y0; y < y1; ++y) {
                        // A tile of thousands of samples per pixel takes seconds: a signal
                        // is looked at per row, not only per tile (Progress::advance).
                        throw_if_cancelled();
                        for (int x = x0; x < x1; ++x) {
                            if (wanted && !(*wanted)[static_cast<size_t>(y) * width + x]) continue;
                            samples += work(origin + Vec2i(x, y), worker);
                        }
                    }
                    progress.advance(samples);
                }
            }
            total_rays += worker.counter.rays;
        });
    return total_rays.load();
}

void TileIntegrator::render_uniform(const Scene& scene, Film& film, Progress& progress,
                                    RenderStats& stats) const {
    const auto sampler = make_sampler(m_settings.sampler, m_settings.spp, m_settings.seed);
    const int spp = m_settings.spp;
    stats.rays =
        for_each_pixel(film, *sampler, progress, nullptr, [&](Vec2i pixel, Worker& worker) {
            render_pixel(scene, film, pixel, worker, 0, spp);
            return static_cast<uint64_t>(spp);
        });
    stats.samples = static_cast<uint64_t>(film.width()) * film.height() * spp;
}

// Adaptive supersampling: one sample per pixel, Sobel edges on its luminance, then N x N
// stratified samples only in the (dilated) edge pixels; flat pixels keep their one sample.
void TileIntegrator::render_edge_adaptive(const Scene& scene, Film& film, Progress& progress,
                                          RenderStats& stats) const {
    const int w = film.width(), h = film.height();
    Film preview(w, h, film.has_aovs(), film.origin());
    const auto single = make_sampler("stratified", 1, m_settings.seed);
    stats.rays =
        for_each_pixel(preview, *single, progress, nullptr, [&](Vec2i pixel, Worker& worker) {
            render_pixel(scene, preview, pixel, worker, 0, 1);
            return uint64_t{1};
        });
    const std::vector<uint8_t> mask =
        sobel_edge_mask(preview.resolve(), m_settings.edge_threshold, m_settings.edge_radius);

    const int n = m_settings.supersample;
    const auto grid = make_sampler("stratified", n * n, m_settings.seed);
    stats.rays += for_each_pixel(film, *grid, progress, &mask, [&](Vec2i pixel, Worker& worker) {
        render_pixel(scene, film, pixel, worker, 0, n * n);
        return static_cast<uint64_t>(n * n);
    });
    std::vector<uint8_t> flat(mask.size());
    for (size_t i = 0; i < mask.size(); ++i) flat[i] = !mask[i];
    stats.rays += for_each_pixel(film, *single, progress, &flat, [&](Vec2i pixel, Worker& worker) {
        render_pixel(scene, film, pixel, worker, 0, 1);
        return uint64_t{1};
    });

    ExtraChannel edges{"edges.Y", std::vector<float>(mask.begin(), mask.end())};
    ExtraChannel counts{"samples.Y", {}};
    for (uint8_t marked : mask) counts.values.push_back(marked ? static_cast<float>(n * n) : 1.0f);
    for (float c : counts.values) stats.samples += static_cast<uint64_t>(c);
    stats.channels = {std::move(edges), std::move(counts)};
}

// Adaptive sampling by error estimate: every pixel gets `spp` samples, then its count
// doubles while the standard error of its mean luminance exceeds target_error times the
// mean, up to max_spp. Decisions are made between rounds from finished pixels only, so
// they do not depend on the thread count.
void TileIntegrator::render_variance_adaptive(const Scene& scene, Film& film, Progress& progress,
                                              RenderStats& stats) const {
    const int w = film.width(), h = film.height();
    const int cap =
        m_settings.max_spp > 0 ? std::max(m_settings.max_spp, m_settings.spp) : 8 * m_settings.spp;
    // Strata over the cap, so any prefix of a pixel's samples is an unbiased estimate.
    const auto sampler = make_sampler(m_settings.sampler, cap, m_settings.seed);
    std::vector<PixelMoments> moments(static_cast<size_t>(w) * h);
    std::vector<int> taken(moments.size(), 0);
    std::vector<uint8_t> active(moments.size(), 1);

    auto converged = [&](size_t i) {
        const double n = taken[i];
        const double mean = moments[i].sum / n;
        const double variance =
            std::max(0.0, moments[i].sum_squares / n - mean * mean) * n / std::max(1.0, n - 1.0);
        const double standard_error = std::sqrt(variance / n);
        // Relative to the mean, regularised like glint compare's relative MSE (r^2 + 0.01),
        // so dark pixels are not chased to a precision nobody can see.
        return standard_error <= m_settings.target_error * std::sqrt(mean * mean + 0.01);
    };

    for (bool any = true; any;) {
        stats.rays +=
            for_each_pixel(film, *sampler, progress, &active, [&](Vec2i pixel, Worker& worker) {
                const Vec2i local = pixel - film.origin();
                const size_t i = static_cast<size_t>(local.y) * w + local.x;
                // Doubling keeps sample counts at powers of two times spp, where the Sobol
                // sampler's prefixes are best stratified.
                const int count =
                    std::min(taken[i] == 0 ? m_settings.spp : taken[i], cap - taken[i]);
                const PixelMoments m = render_pixel(scene, film, pixel, worker, taken[i], count);
                moments[i].sum += m.sum;
                moments[i].sum_squares += m.sum_squares;
                taken[i] += count;
                return static_cast<uint64_t>(count);
            });
        // Between rounds: a pixel stops only when it and its 8 neighbours all look
        // converged. A few samples can miss a pixel's rare bright paths and understate its
        // error; its neighbours, which see the same light, catch that.
        std::vector<uint8_t> looks_converged(active.size());
        for (size_t i = 0; i < active.size(); ++i) looks_converged[i] = converged(i);
        any = false;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const size_t i = static_cast<size_t>(y) * w + x;
                bool neighbourhood_converged = true;
                for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny) {
                    for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) {
                        neighbourhood_converged &=
                            looks_converged[static_cast<size_t>(ny) * w + nx] != 0;
                    }
                }
                active[i] = taken[i] < cap && !neighbourhood_converged;
                any |= active[i] != 0;
            }
        }
    }
    ExtraChannel counts{"samples.Y", {}};
    for (int n : taken) {
        counts.values.push_back(static_cast<float>(n));
        stats.samples += static_cast<uint64_t>(n);
    }
    stats.channels = {std::move(counts)};
}

std::unique_ptr<TileIntegrator::Worker> TileIntegrator::make_worker(
    const Sampler& prototype) const {
    auto worker = std::make_unique<Worker>();
    worker->sampler = prototype.clone();
    return worker;
}

TileIntegrator::PixelMoments TileIntegrator::render_pixel(const Scene& scene, Film& film,
                                                          Vec2i pixel, Worker& worker, int first,
                                                          int count) const {
    PixelMoments moments;
    Sampler& sampler = *worker.sampler;
    const WavelengthSets* sets = m_settings.spectral ? wavelength_sets() : nullptr;
    for (int index = first; index < first + count; ++index) {
        const auto wavelengths =
            sets != nullptr
                ? PathWavelengths(&(*sets)[sets->set_of_sample(m_settings.seed, pixel, index)])
                : PathWavelengths(m_settings.spectral,
                                  detail::pixel_sample_key(m_settings.seed, pixel, index));
        const CameraSample sample = start_camera_sample(scene, pixel, index, sampler);
        AovSample aov{};
        AovSample* features = film.has_aovs() ? &aov : nullptr;
        worker.arena.reset();
        const Spectrum L = li(sample.ray, scene, sampler, worker.arena, worker.counter, features);
        record_sample(film, pixel, index, L, sample.filter.weight, features, moments);
    }
    return moments;
}

IntegratorCapabilities TileIntegrator::capabilities() const {
    return {.crop_windows = true,
            .adaptive_sampling = true,
            .film_halves = true,
            .motion_blur = true,
            .spectral = true,
            .debug_views = {{"edges", "--adaptive sobel"}}};
}

}  // namespace glint
