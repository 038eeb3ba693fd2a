#include <glint/material/texture/image_texture.h>
#include <glint/material/texture/registry.h>

#include <map>

namespace glint {
namespace {

using TextureFactory = std::unique_ptr<Texture> (*)(const Params&, TextureTable&);

const std::map<std::string, TextureFactory>& factories() {
    static const std::map<std::string, TextureFactory> table = {
        {"image", make_image_texture},
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
