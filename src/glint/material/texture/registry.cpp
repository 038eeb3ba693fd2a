#include <glint/material/texture/checker_texture.h>
#include <glint/material/texture/image_texture.h>
#include <glint/material/texture/marble_texture.h>
#include <glint/material/texture/noise_texture.h>
#include <glint/material/texture/registry.h>
#include <glint/material/texture/wood_texture.h>

#include <map>

namespace glint {
namespace {

using TextureFactory = std::unique_ptr<Texture> (*)(const Params&, TextureTable&);

const std::map<std::string, TextureFactory>& factories() {
    static const std::map<std::string, TextureFactory> table = {
        {"checker", make_checker_texture}, {"fbm", make_fbm_texture},
        {"image", make_image_texture},     {"marble", make_marble_texture},
        {"noise", make_noise_texture},     {"turbulence", make_turbulence_texture},
        {"wood", make_wood_texture},
    };
    return table;
}

}  // namespace

std::vector<std::string> texture_types() {
    std::vector<std::string> names;
    for (const auto& [name, factory] : factories()) names.push_back(name);
    return names;
}

std::unique_ptr<Texture> make_texture(const Params& params, TextureTable& table) {
    auto it = factories().find(params.type());
    if (it == factories().end()) params.fail("unknown texture type");
    auto texture = it->second(params, table);
    params.check_all_used();
    return texture;
}

}  // namespace glint
