#include <glint/core/error.h>
#include <glint/integrator/bidirectional/bdpt.h>
#include <glint/integrator/bidirectional/light_tracer.h>
#include <glint/integrator/bidirectional/mlt.h>
#include <glint/integrator/path/path.h>
#include <glint/integrator/photon/photon.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/radiosity/radiosity.h>
#include <glint/integrator/photon/sppm.h>
#include <glint/integrator/bidirectional/vcm.h>
#include <glint/integrator/path/whitted.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <set>

namespace glint {
namespace {

template <DirectLighting Strategy>
std::unique_ptr<Integrator> create_path(const RenderSettings& settings, const Params&) {
    return std::make_unique<PathIntegrator>(settings, Strategy);
}

// Name -> create(). An integrator with settings of its own reads them in its create();
// adding one is one row here.
const std::map<std::string, IntegratorCreate>& factories() {
    static const std::map<std::string, IntegratorCreate> table = {
        {"bdpt", BdptIntegrator::create},
        {"light", LightTracer::create},
        {"mlt", MltIntegrator::create},
        {"path", create_path<DirectLighting::kMis>},
        {"path_light", create_path<DirectLighting::kLightOnly>},
        {"path_bsdf", create_path<DirectLighting::kBsdfOnly>},
        {"photon", PhotonIntegrator::create},
        {"preview", PreviewIntegrator::create},
        {"radiosity", RadiosityIntegrator::create},
        {"sppm", SppmIntegrator::create},
        {"vcm", VcmIntegrator::create},
        {"whitted", WhittedIntegrator::create},
    };
    return table;
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const RenderSettings& settings,
                                            std::vector<std::string>* warnings) {
    auto it = factories().find(settings.integrator);
    if (it == factories().end()) {
        std::string known;
        for (const auto& [name, create] : factories()) known += (known.empty() ? "" : ", ") + name;
        throw Error(fmt::format("{}: unknown integrator '{}' (known: {})",
                                settings.where_of("integrator"), settings.integrator, known));
    }
    // Only the integrators whose pixels do not depend on the others render a window alone:
    // the tile integrators, and sppm (its photons do not depend on the window, and each
    // pixel sums their flux in photon order). Light paths (light, bdpt, vcm, mlt) splat
    // anywhere on the film, so a crop window would need the whole film rendered anyway. A
    // new integrator is refused until it says so.
    static const std::set<std::string> kCropIntegrators = {"path",    "path_light", "path_bsdf",
                                                           "whitted", "photon",     "sppm"};
    if (settings.has_crop() && !kCropIntegrators.contains(settings.integrator)) {
        throw Error(fmt::format(
            "{}: integrator '{}' does not support 'crop'; crop works with path, path_light, "
            "path_bsdf, whitted, photon and sppm",
            settings.where_of("crop"), settings.integrator));
    }
    // A copy, so that it records only what this integrator reads.
    Params params = settings.params;
    std::unique_ptr<Integrator> integrator = it->second(settings, params);
    const std::vector<std::string> unread = params.unused();
    if (unread.empty()) return integrator;

    // Which keys the other integrators read: each reads all of its keys unconditionally, so
    // creating it from an empty table asks for every one of them.
    std::set<std::string> foreign_keys;
    for (const auto& [name, create] : factories()) {
        if (name == settings.integrator) continue;
        const Params empty(params.type(), params.where());
        create(settings, empty);
        foreign_keys.insert(empty.asked().begin(), empty.asked().end());
    }
    std::vector<std::string> foreign;
    for (const std::string& key : unread) {
        if (foreign_keys.count(key)) {
            foreign.push_back(key);
            params.has(key);  // known: not an error below
        }
    }
    params.check_all_used();  // a key no integrator reads is a mistake
    if (warnings) {
        std::vector<std::string> named;  // a key set by a flag says which
        for (const std::string& key : foreign) {
            const std::string& where = params.where_of(key);
            named.push_back(where == params.where() ? fmt::format("'{}'", key)
                                                    : fmt::format("'{}' ({})", key, where));
        }
        warnings->push_back(fmt::format("{}: {}: {} {} not used by integrator '{}' (ignored)",
                                        params.where(), params.type(), fmt::join(named, ", "),
                                        named.size() == 1 ? "is" : "are", settings.integrator));
    }
    return integrator;
}

std::vector<std::string> integrator_names() {
    std::vector<std::string> names;
    for (const auto& [name, create] : factories()) names.push_back(name);
    return names;
}

Image final_image(const Film& film, const RenderStats& stats) {
    Image image = film.resolve();
    for (const ExtraChannel& channel : stats.channels)
        image = with_channel(image, channel.name, channel.values);
    return image;
}

}  // namespace glint
