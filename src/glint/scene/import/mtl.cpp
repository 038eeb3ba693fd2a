#include <glint/core/error.h>
#include <glint/scene/import/file_bytes.h>
#include <glint/scene/import/mtl.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace glint {
namespace {

std::string_view next_token(std::string_view& rest) {
    size_t begin = 0;
    while (begin < rest.size() && (rest[begin] == ' ' || rest[begin] == '\t')) ++begin;
    size_t end = begin;
    while (end < rest.size() && rest[end] != ' ' && rest[end] != '\t') ++end;
    const std::string_view token = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return token;
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

bool to_float(std::string_view token, float& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && ptr == token.data() + token.size() && std::isfinite(value);
}

class MtlParser {
public:
    explicit MtlParser(std::string name) : m_name(std::move(name)) {}

    void parse_line(std::string_view line, uint64_t line_number) {
        m_line = line_number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        std::string_view rest = line;
        const std::string_view keyword = next_token(rest);
        if (keyword.empty() || keyword.front() == '#') return;
        if (keyword == "newmtl") {
            const std::string_view name = trimmed(rest);
            if (name.empty()) fail("'newmtl' needs a name");
            m_materials.push_back({});
            m_materials.back().name = std::string(name);
            m_materials.back().where = fmt::format("{}:{}", m_name, m_line);
            return;
        }
        if (m_materials.empty()) {
            fail(fmt::format("{} before any 'newmtl' (is this an MTL file?)",
                             keyword_shown(keyword)));
        }
        MtlMaterial& m = m_materials.back();
        if (keyword == "Kd") {
            m.kd = colour(rest, keyword);
        } else if (keyword == "Ks") {
            m.ks = colour(rest, keyword);
        } else if (keyword == "Ke") {
            m.ke = colour(rest, keyword);
        } else if (keyword == "Ns") {
            m.ns = number(rest, keyword, 0.0f, 1e5f);
        } else if (keyword == "Ni") {
            m.ni = number(rest, keyword, 0.0f, 100.0f);
        } else if (keyword == "d") {
            // "d -halo f" is a rarely written variant: the halo is ignored, the factor kept.
            std::string_view probe = rest;
            if (next_token(probe) == "-halo") rest = probe;
            m.d = number(rest, keyword, 0.0f, 1.0f);
        } else if (keyword == "Tr") {
            m.d = 1.0f - number(rest, keyword, 0.0f, 1.0f);
        } else if (keyword == "illum") {
            m.illum = static_cast<int>(number(rest, keyword, 0.0f, 10.0f));
        } else if (keyword == "map_Kd") {
            m.map_kd = map(rest, keyword);
        } else if (keyword == "map_Ks") {
            m.map_ks = map(rest, keyword);
        } else if (keyword == "map_Ke") {
            m.map_ke = map(rest, keyword);
        } else if (keyword == "map_Bump" || keyword == "map_bump" || keyword == "bump") {
            m.map_bump = map(rest, keyword);
        } else if (keyword == "norm") {
            m.norm = map(rest, keyword);
        } else if (keyword == "map_d") {
            m.map_d = map(rest, keyword);
        } else if (keyword == "Ka" || keyword == "map_Ka" || keyword == "Tf") {
            // Ambient light and transmission filters have no counterpart in a physically
            // based renderer: read and dropped without a warning (every exporter writes Ka).
        } else {
            m.ignored.emplace_back(keyword_shown(keyword));
        }
    }

    std::vector<MtlMaterial> finish() { return std::move(m_materials); }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(fmt::format("{}:{}: {}", m_name, m_line, what));
    }

    // A keyword quoted in a message only when it looks like one (a short word): a file that
    // is no MTL file (a model can name any file as its library) must not have its content
    // printed.
    static std::string keyword_shown(std::string_view keyword) {
        const bool word =
            keyword.size() <= 16 && std::all_of(keyword.begin(), keyword.end(), [](char c) {
                return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
            });
        return word ? fmt::format("'{}'", keyword) : std::string("a statement that is not MTL");
    }

    float number(std::string_view& rest, std::string_view keyword, float lo, float hi) const {
        const std::string_view token = next_token(rest);
        float value = 0.0f;
        if (!to_float(token, value))
            fail(fmt::format("'{}' needs a number, found '{}'", keyword, token));
        if (!(value >= lo && value <= hi))
            fail(fmt::format("'{}' {} is outside [{:g}, {:g}]", keyword, value, lo, hi));
        return value;
    }

    // "Kd r g b", or "Kd r" for grey; "Kd spectral ..." and "Kd xyz ..." are refused.
    Vec3 colour(std::string_view rest, std::string_view keyword) const {
        float c[3];
        int n = 0;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
            if (token.front() == '#') break;
            if (n == 3 || !to_float(token, c[n]))
                fail(fmt::format("'{}' needs one or three numbers (r g b)", keyword));
            if (c[n] < 0.0f) fail(fmt::format("'{}' must not be negative", keyword));
            ++n;
        }
        if (n == 1) return Vec3(c[0]);
        if (n != 3) fail(fmt::format("'{}' needs one or three numbers (r g b)", keyword));
        return Vec3(c[0], c[1], c[2]);
    }

    // Options come before the file name; the name is the rest of the line (it may hold
    // spaces).
    MtlMap map(std::string_view rest, std::string_view keyword) const {
        MtlMap result;
        for (;;) {
            std::string_view probe = rest;
            const std::string_view option = next_token(probe);
            if (option.empty() || option.front() != '-') break;
            rest = probe;
            auto numbers = [&](int most) {
                std::vector<float> values;
                for (;;) {
                    std::string_view look = rest;
                    float v = 0.0f;
                    if (static_cast<int>(values.size()) == most || !to_float(next_token(look), v))
                        break;
                    values.push_back(v);
                    rest = look;
                }
                if (values.empty())
                    fail(fmt::format("'{}' option '{}' needs a number", keyword, option));
                return values;
            };
            if (option == "-bm") {
                result.bump_multiplier = numbers(1)[0];
            } else if (option == "-s" || option == "-o") {
                const std::vector<float> v = numbers(3);
                const Vec2 uv(v[0], v.size() > 1 ? v[1] : (option == "-s" ? 1.0f : 0.0f));
                (option == "-s" ? result.scale : result.offset) = uv;
            } else if (option == "-t" || option == "-mm") {
                numbers(3);
            } else if (option == "-clamp" || option == "-blendu" || option == "-blendv" ||
                       option == "-cc" || option == "-imfchan" || option == "-type" ||
                       option == "-texres" || option == "-boost") {
                const std::string_view value = next_token(rest);
                if (value.empty())
                    fail(fmt::format("'{}' option '{}' needs a value", keyword, option));
                if (option == "-clamp") result.clamp = value == "on";
            } else {
                fail(fmt::format("'{}': unknown option '{}'", keyword, option));
            }
        }
        const std::string_view file = trimmed(rest);
        if (file.empty()) fail(fmt::format("'{}' needs a file name", keyword));
        result.file = std::string(file);
        return result;
    }

    std::string m_name;
    uint64_t m_line = 0;
    std::vector<MtlMaterial> m_materials;
};

// An image texture for a map, its file made absolute so that the scene's own directory
// (where the Lua script lives) does not change what it names.
ObjectRef add_map(const MtlMap& map, const MtlMaterial& material, const std::string& directory,
                  bool colour, std::vector<Params>& textures) {
    Params texture("image", material.where);
    std::filesystem::path file(map.file);
    if (file.is_relative())
        file = std::filesystem::absolute(std::filesystem::path(directory) / file);
    texture.set("file", file.lexically_normal().string());
    texture.set("encoding", std::string(colour ? "auto" : "linear"));
    if (map.clamp) texture.set("wrap", std::string("clamp"));
    if (map.scale != Vec2(1.0f))
        texture.set("scale", std::vector<double>{map.scale.x, map.scale.y});
    if (map.offset != Vec2(0.0f))
        texture.set("offset", std::vector<double>{map.offset.x, map.offset.y});
    textures.push_back(std::move(texture));
    return ObjectRef{"texture", static_cast<int>(textures.size()) - 1};
}

}  // namespace

std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& name) {
    MtlParser parser(name);
    for_each_line(text,
                  [&](std::string_view line, uint64_t number) { parser.parse_line(line, number); });
    return parser.finish();
}

std::vector<MtlMaterial> load_mtl(const std::string& path) {
    return parse_mtl(read_file_bytes(path, "MTL"), path);
}

Params mtl_to_params(const MtlMaterial& m, const std::string& directory,
                     std::vector<Params>& textures, std::vector<std::string>& warnings) {
    auto warn = [&](const std::string& what) {
        warnings.push_back(fmt::format("{}: material '{}': {}", m.where, m.name, what));
    };
    const Vec3 kd = m.kd.value_or(Vec3(0.8f));
    const Vec3 ks = m.ks.value_or(Vec3(0.0f));
    const int illum = m.illum.value_or(2);
    const float d = m.d.value_or(1.0f);
    auto max_of = [](const Vec3& v) { return std::max({v.x, v.y, v.z}); };
    Params params;
    if (m.ke && max_of(*m.ke) > 0.0f) {
        // An emitter: glint's emissive surfaces do not also reflect, so Kd and Ks go.
        params = Params("emissive", m.where);
        params.set("radiance", numbers_of(*m.ke));
        if (m.map_ke) warn("'map_Ke' is not supported (the emission is Ke, uniform)");
    } else if (illum == 4 || illum == 6 || illum == 7 || illum == 9 || d < 1.0f) {
        // Transparent: the glass of illum 4/6/7/9, or any dissolve below 1 (which in a
        // physically based renderer means a transmitting surface, not a see-through alpha).
        params = Params("dielectric", m.where);
        params.set("ior", static_cast<double>(m.ni && *m.ni >= 1.0f ? *m.ni : 1.5f));
    } else if (illum == 3 || illum == 5) {
        // Ray-traced reflection: a mirror tinted by Ks (1 where Ks is not given).
        params = Params("mirror", m.where);
        params.set("tint", numbers_of(m.ks ? glm::min(ks, Vec3(1.0f)) : Vec3(1.0f)));
    } else if (illum != 0 && illum != 1 && max_of(ks) > 0.0f) {
        // Kd + Ks with exponent Ns: the Phong model OBJ itself describes. glint's Phong
        // keeps Kd + Ks <= 1 so that the surface creates no energy: both are scaled down
        // together where the file's sum exceeds 1.
        params = Params("phong", m.where);
        Vec3 diffuse = glm::min(kd, Vec3(1.0f));
        Vec3 specular = glm::min(ks, Vec3(1.0f));
        const float sum = max_of(diffuse + specular);
        if (sum > 1.0f) {
            diffuse /= sum;
            specular /= sum;
            warn(fmt::format("Kd + Ks = {:.3g} exceeds 1; both scaled by {:.3g}", sum, 1.0f / sum));
        }
        if (m.map_kd)
            params.set("diffuse", add_map(*m.map_kd, m, directory, true, textures));
        else
            params.set("diffuse", numbers_of(diffuse));
        params.set("specular", numbers_of(specular));
        params.set("exponent", static_cast<double>(m.ns.value_or(10.0f)));
        if (m.map_ks) warn("'map_Ks' is not supported by the phong material (Ks is uniform)");
    } else {
        params = Params("diffuse", m.where);
        if (m.map_kd)
            params.set("reflectance", add_map(*m.map_kd, m, directory, true, textures));
        else
            params.set("reflectance", numbers_of(glm::min(kd, Vec3(1.0f))));
    }
    if (params.type() == "diffuse" || params.type() == "phong" || params.type() == "mirror" ||
        params.type() == "dielectric") {
        if (m.norm) {
            params.set("normal_map", add_map(*m.norm, m, directory, false, textures));
        } else if (m.map_bump) {
            params.set("bump", add_map(*m.map_bump, m, directory, false, textures));
            params.set("bump_scale", static_cast<double>(m.map_bump->bump_multiplier));
        }
    }
    if (m.map_d) warn("'map_d' (alpha cut-outs) is not supported; the surface is opaque");
    for (const std::string& statement : m.ignored)
        warn(fmt::format("'{}' is not understood", statement));
    return params;
}

}  // namespace glint
