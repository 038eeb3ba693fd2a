#include <glint/light/environment_light.h>
#include <glint/light/point_light.h>
#include <glint/light/registry.h>

#include <map>

namespace glint {
namespace {

using LightFactory = std::unique_ptr<Light> (*)(const Params&, const std::string& directory);

// Lights that read no files ignore the directory.
template <std::unique_ptr<Light> (*make)(const Params&)>
std::unique_ptr<Light> without_files(const Params& params, const std::string&) {
    return make(params);
}

const std::map<std::string, LightFactory>& factories() {
    static const std::map<std::string, LightFactory> table = {
        {"directional_light", without_files<make_directional_light>},
        {"environment", make_environment_light},
        {"point_light", without_files<make_point_light>},
        {"spot_light", without_files<make_spot_light>},
    };
    return table;
}

}  // namespace

std::vector<std::string> light_types() {
    std::vector<std::string> names;
    for (const auto& [name, factory] : factories()) names.push_back(name);
    return names;
}

std::unique_ptr<Light> make_light(const Params& params, const std::string& directory) {
    auto it = factories().find(params.type());
    if (it == factories().end()) params.fail("unknown light type");
    auto light = it->second(params, directory);
    params.check_all_used();
    return light;
}

}  // namespace glint
