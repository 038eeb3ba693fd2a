#include <glint/core/error.h>
#include <glint/integrator/light_tracer.h>
#include <glint/integrator/path.h>
#include <glint/integrator/photon.h>
#include <glint/integrator/sppm.h>
#include <glint/integrator/whitted.h>

#include <fmt/format.h>

#include <map>

namespace glint {
namespace {

using IntegratorFactory = std::unique_ptr<Integrator> (*)(const RenderSettings&);

template <DirectLighting Strategy>
std::unique_ptr<Integrator> make_path(const RenderSettings& settings) {
    return std::make_unique<PathIntegrator>(settings, Strategy);
}

std::unique_ptr<Integrator> make_light(const RenderSettings& settings) {
    return std::make_unique<LightTracer>(settings);
}

std::unique_ptr<Integrator> make_photon(const RenderSettings& settings) {
    return std::make_unique<PhotonIntegrator>(settings);
}

std::unique_ptr<Integrator> make_sppm(const RenderSettings& settings) {
    return std::make_unique<SppmIntegrator>(settings);
}

std::unique_ptr<Integrator> make_whitted(const RenderSettings& settings) {
    return std::make_unique<WhittedIntegrator>(settings);
}

const std::map<std::string, IntegratorFactory>& factories() {
    static const std::map<std::string, IntegratorFactory> table = {
        {"light", make_light},
        {"path", make_path<DirectLighting::kMis>},
        {"path_light", make_path<DirectLighting::kLightOnly>},
        {"path_bsdf", make_path<DirectLighting::kBsdfOnly>},
        {"photon", make_photon},
        {"sppm", make_sppm},
        {"whitted", make_whitted},
    };
    return table;
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const RenderSettings& settings) {
    auto it = factories().find(settings.integrator);
    if (it != factories().end()) return it->second(settings);
    std::string known;
    for (const auto& [name, factory] : factories()) known += (known.empty() ? "" : ", ") + name;
    throw Error(fmt::format("{}: unknown integrator '{}' (known: {})", settings.where,
                            settings.integrator, known));
}

Image final_image(const Film& film, const RenderStats& stats) {
    Image image = film.resolve();
    for (const ExtraChannel& channel : stats.channels)
        image = with_channel(image, channel.name, channel.values);
    return image;
}

}  // namespace glint
