#include <glint/core/error.h>
#include <glint/film/denoise.h>
#include <glint/render/denoise_step.h>

#include <fmt/format.h>

namespace glint {

void check_denoise(const RenderSettings& settings, const IntegratorCapabilities& capabilities) {
    if (!settings.denoise) return;
    const std::string& where = settings.where_of("denoise");
    if (!capabilities.film_halves) {
        throw Error(fmt::format(
            "{}: the denoiser needs an integrator that renders pixel by pixel (path, whitted, "
            "photon); '{}' adds light paths to the image, which it cannot split into halves",
            where, settings.integrator));
    }
    if (settings.adaptive == "sobel") {
        throw Error(
            fmt::format("{}: the denoiser cannot use --adaptive sobel (its flat pixels "
                        "get one sample, which cannot be split into two halves)",
                        where));
    }
    if (settings.spp < 2)
        throw Error(fmt::format("{}: the denoiser needs at least 2 samples per pixel", where));
}

bool film_needs_halves(const RenderSettings& settings) {
    return settings.denoise;
}

Image denoise_film(const Film& film, const RenderSettings&, const RenderControl&) {
    return denoise(film);
}

}  // namespace glint
