#include <glint/core/arena.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/core/sampler.h>
#include <glint/integrator/integrator.h>

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <fmt/format.h>

#include <chrono>

namespace glint {

namespace {
constexpr int kTileSize = 16;
}

TileIntegrator::TileIntegrator(const RenderSettings& settings) : m_settings(settings) {
    // Check the names now, before any scene is built, and say where they came from.
    try {
        m_filter = make_filter(settings.filter, settings.filter_radius);
        make_sampler(settings.sampler, settings.spp, settings.seed);
    } catch (const Error& e) {
        throw Error(fmt::format("{}: {}", settings.where, e.what()));
    }
}

RenderStats TileIntegrator::render(const Scene& scene, Film& film, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const auto prototype = make_sampler(m_settings.sampler, m_settings.spp, m_settings.seed);
    const int tiles_x = (film.width() + kTileSize - 1) / kTileSize;
    const int tiles_y = (film.height() + kTileSize - 1) / kTileSize;
    std::atomic<uint64_t> total_rays{0};

    // Each pixel is rendered by exactly one task and its random numbers depend only on
    // (seed, pixel, sample index), so the image does not depend on scheduling.
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, tiles_y, 1, 0, tiles_x, 1),
        [&](const tbb::blocked_range2d<int>& range) {
            auto sampler = prototype->clone();
            Arena arena;
            RayCounter counter;
            for (int ty = range.rows().begin(); ty < range.rows().end(); ++ty) {
                for (int tx = range.cols().begin(); tx < range.cols().end(); ++tx) {
                    const int x0 = tx * kTileSize, y0 = ty * kTileSize;
                    const int x1 = std::min(x0 + kTileSize, film.width());
                    const int y1 = std::min(y0 + kTileSize, film.height());
                    for (int y = y0; y < y1; ++y) {
                        for (int x = x0; x < x1; ++x) {
                            render_pixel(scene, film, Vec2i(x, y), *sampler, arena, counter);
                        }
                    }
                    progress.advance(static_cast<uint64_t>(x1 - x0) * (y1 - y0) * m_settings.spp);
                }
            }
            total_rays += counter.rays;
        });

    RenderStats stats;
    stats.samples = static_cast<uint64_t>(film.width()) * film.height() * m_settings.spp;
    stats.rays = total_rays.load();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

void TileIntegrator::render_pixel(const Scene& scene, Film& film, Vec2i pixel, Sampler& sampler,
                                  Arena& arena, RayCounter& counter) const {
    const bool want_aovs = film.has_aovs();
    for (int index = 0; index < m_settings.spp; ++index) {
        sampler.start_pixel_sample(pixel, index);
        const FilterSample fs = m_filter->sample(sampler.get_pixel_2d());
        const Vec2 film_point = Vec2(pixel) + Vec2(0.5f) + fs.offset;
        const Ray ray = scene.camera().generate_ray(film_point, sampler.get_2d());
        AovSample aov{};
        arena.reset();
        const Spectrum L = li(ray, scene, sampler, arena, counter, want_aovs ? &aov : nullptr);
        film.add_sample(pixel, L, fs.weight, want_aovs ? &aov : nullptr);
    }
}

}  // namespace glint
