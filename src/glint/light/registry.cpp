#include <glint/core/error.h>
#include <glint/light/environment_light.h>
#include <glint/light/point_light.h>
#include <glint/light/registry.h>

#include <map>

namespace glint {
namespace {

using LightFactory = std::unique_ptr<Light> (*)(const Params&, const std::string& directory);

struct LightRow {
    LightFactory make;
    LightEditing editing;
};

// Lights that read no files ignore the directory.
template <std::unique_ptr<Light> (*make)(const Params&)>
std::unique_ptr<Light> without_files(const Params& params, const std::string&) {
    return make(params);
}

// Name -> factory, and what an editor may change. Adding a light is one row here.
const std::map<std::string, LightRow>& factories() {
    static const std::map<std::string, LightRow> table = {
        {"directional_light", {without_files<make_directional_light>, {"irradiance", {}}}},
        {"environment", {make_environment_light, {"intensity", {}}}},
        {"point_light", {without_files<make_point_light>, {"intensity", {"position"}}}},
        {"spot_light", {without_files<make_spot_light>, {"intensity", {"position", "look_at"}}}},
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
    auto light = it->second.make(params, directory);
    params.check_all_used();
    return light;
}

LightEditing light_editing(const std::string& type) {
    auto it = factories().find(type);
    if (it == factories().end()) throw Error("unknown light type '" + type + "'");
    return it->second.editing;
}

}  // namespace glint
