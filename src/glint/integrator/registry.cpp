#include <glint/core/error.h>
#include <glint/integrator/bidirectional/bdpt.h>
#include <glint/integrator/bidirectional/light_tracer.h>
#include <glint/integrator/bidirectional/mlt.h>
#include <glint/integrator/bidirectional/vcm.h>
#include <glint/integrator/path/path.h>
#include <glint/integrator/path/volpath.h>
#include <glint/integrator/path/whitted.h>
#include <glint/integrator/photon/photon.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/photon/sppm.h>
#include <glint/integrator/radiosity/radiosity.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>
#include <vector>

namespace glint {
namespace {

template <DirectLighting Strategy>
std::unique_ptr<Integrator> create_path(const RenderSettings& settings, const Params&) {
    return std::make_unique<PathIntegrator>(settings, Strategy);
}

struct Factory {
    std::string name;
    IntegratorCreate create;
};

// Name -> create(). An integrator with settings of its own reads them in its create(),
// and states what it can do in capabilities(); adding one is one row here. Listed by
// family, the order in which messages name them.
const std::vector<Factory>& factories() {
    static const std::vector<Factory> table = {
        {"path", create_path<DirectLighting::kMis>},
        {"path_light", create_path<DirectLighting::kLightOnly>},
        {"path_bsdf", create_path<DirectLighting::kBsdfOnly>},
        {"volpath", VolPathIntegrator::create},
        {"whitted", WhittedIntegrator::create},
        {"photon", PhotonIntegrator::create},
        {"sppm", SppmIntegrator::create},
        {"preview", PreviewIntegrator::create},
        {"radiosity", RadiosityIntegrator::create},
        {"light", LightTracer::create},
        {"bdpt", BdptIntegrator::create},
        {"vcm", VcmIntegrator::create},
        {"mlt", MltIntegrator::create},
    };
    return table;
}

const Factory* find_factory(const std::string& name) {
    for (const Factory& factory : factories()) {
        if (factory.name == name) return &factory;
    }
    return nullptr;
}

// "a, b and c"
std::string spoken_list(const std::vector<std::string>& names) {
    std::string text;
    for (size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return text;
}

// A crop window is refused unless the integrator renders one alone (its capabilities).
void check_crop(const RenderSettings& settings, const Integrator& integrator) {
    if (!settings.has_crop() || integrator.capabilities().crop_windows) return;
    std::vector<std::string> able;
    for (const Factory& factory : factories()) {
        if (integrator_capabilities(factory.name).crop_windows) able.push_back(factory.name);
    }
    throw Error(fmt::format("{}: integrator '{}' does not support 'crop'; crop works with {}",
                            settings.where_of("crop"), settings.integrator, spoken_list(able)));
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const RenderSettings& settings,
                                            std::vector<std::string>* warnings) {
    const Factory* factory = find_factory(settings.integrator);
    if (!factory) {
        throw Error(fmt::format("{}: unknown integrator '{}' (known: {})",
                                settings.where_of("integrator"), settings.integrator,
                                fmt::join(integrator_names(), ", ")));
    }
    // A copy, so that it records only what this integrator reads.
    Params params = settings.params;
    std::unique_ptr<Integrator> integrator = factory->create(settings, params);
    check_crop(settings, *integrator);
    const std::vector<std::string> unread = params.unused();
    if (unread.empty()) return integrator;

    // Which keys the other integrators read: each reads all of its keys unconditionally, so
    // creating it from an empty table asks for every one of them.
    std::set<std::string> foreign_keys;
    for (const Factory& other : factories()) {
        if (other.name == settings.integrator) continue;
        const Params empty(params.type(), params.where());
        other.create(settings, empty);
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
    for (const Factory& factory : factories()) names.push_back(factory.name);
    std::sort(names.begin(), names.end());
    return names;
}

IntegratorCapabilities integrator_capabilities(const std::string& name) {
    const Factory* factory = find_factory(name);
    if (!factory) throw Error(fmt::format("unknown integrator '{}'", name));
    const RenderSettings defaults;
    const Params empty("render", "default settings");
    return factory->create(defaults, empty)->capabilities();
}

bool IntegratorCapabilities::has_debug_view(const std::string& name) const {
    return std::any_of(debug_views.begin(), debug_views.end(),
                       [&](const DebugView& view) { return view.name == name; });
}

Image final_image(const Film& film, const RenderStats& stats) {
    Image image = film.resolve();
    for (const ExtraChannel& channel : stats.channels)
        image = with_channel(image, channel.name, channel.values);
    return image;
}

}  // namespace glint
