#include <glint/core/error.h>
#include <glint/integrator/path.h>

#include <fmt/format.h>

#include <map>

namespace glint {
namespace {

using IntegratorFactory = std::unique_ptr<Integrator> (*)(const RenderSettings&);

const std::map<std::string, IntegratorFactory>& factories() {
    static const std::map<std::string, IntegratorFactory> table = {
        {"path",
         [](const RenderSettings& s) -> std::unique_ptr<Integrator> {
             return std::make_unique<PathIntegrator>(s, DirectLighting::kMis);
         }},
        {"path_light",
         [](const RenderSettings& s) -> std::unique_ptr<Integrator> {
             return std::make_unique<PathIntegrator>(s, DirectLighting::kLightOnly);
         }},
        {"path_bsdf",
         [](const RenderSettings& s) -> std::unique_ptr<Integrator> {
             return std::make_unique<PathIntegrator>(s, DirectLighting::kBsdfOnly);
         }},
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

}  // namespace glint
