#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/denoise/film_denoiser.h>
#include <glint/render/denoise_step.h>

#include <fmt/format.h>
#include <tbb/task_arena.h>

namespace glint {

void check_denoise(const RenderSettings& settings, const IntegratorCapabilities& capabilities) {
    if (!settings.denoise) return;
    const std::string& where = settings.where_of("denoise");
    if (!capabilities.film_halves) {
        throw Error(fmt::format(
            "{}: the denoiser needs an integrator that renders pixel by pixel (path, whitted, "
            "photon); '{}' adds light paths to the image, which carry no first-hit features "
            "and cannot be split into halves",
            where, settings.integrator));
    }
    // The network needs only the features; the non-local means filter also two halves.
    if (settings.denoiser == "nlm") {
        if (settings.adaptive == "sobel") {
            throw Error(
                fmt::format("{}: the denoiser cannot use --adaptive sobel (its flat pixels "
                            "get one sample, which cannot be split into two halves)",
                            where));
        }
        if (settings.spp < 2)
            throw Error(fmt::format("{}: the denoiser needs at least 2 samples per pixel", where));
    }
}

bool film_needs_halves(const RenderSettings& settings) {
    return settings.denoise && settings.denoiser == "nlm";
}

Image denoise_film(const Film& film, const RenderSettings& settings, const RenderControl& control) {
    const int threads =
        settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    Progress denoising("denoising",
                       static_cast<uint64_t>(denoise_steps(film.width(), film.height(), settings)),
                       control.quiet, "tiles");
    denoising.set_cancel_flag(control.cancel);
    Image denoised = denoise_film(film, settings, threads, denoising);
    denoising.finish();
    return denoised;
}

}  // namespace glint
