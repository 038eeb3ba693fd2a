#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/denoise/film_denoiser.h>
#include <glint/film/denoise.h>
#include <glint/film/film.h>

#include <fmt/format.h>

namespace glint {

NetworkDenoiseSettings network_denoise_settings(const RenderSettings& settings, int threads) {
    NetworkDenoiseSettings network;
    network.quality =
        parse_denoise_quality(settings.denoise_quality).value_or(DenoiseQuality::Balanced);
    network.clean_aux = settings.denoise_clean_aux;
    network.threads = std::max(threads, 1);
    return network;
}

void check_denoiser_ready(const RenderSettings& settings) {
    if (!settings.denoise || settings.denoiser != "network") return;
    try {
        check_denoise_weights(network_denoise_settings(settings, 1));
    } catch (const Error& e) {
        throw Error(fmt::format("{}: {}", settings.where_of("denoise"), e.what()));
    }
}

int denoise_steps(int width, int height, const RenderSettings& settings) {
    if (settings.denoiser != "network") return 1;
    const NetworkDenoiseSettings network = network_denoise_settings(settings, 1);
    const int passes = network.clean_aux || network.quality == DenoiseQuality::High ? 3 : 1;
    return passes * denoise_network_tiles(width, height, network);
}

Image denoise_film(const Film& film, const RenderSettings& settings, int threads,
                   Progress& progress) {
    if (settings.denoiser != "network") {
        Image image = denoise(film);
        progress.advance(1);
        return image;
    }
    NetworkDenoiseSettings network = network_denoise_settings(settings, threads);
    network.on_progress = [&progress](int, int) { progress.advance(1); };
    return denoise_network(film.resolve(), network);
}

}  // namespace glint
