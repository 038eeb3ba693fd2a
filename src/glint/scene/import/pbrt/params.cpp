#include <glint/core/error.h>
#include <glint/scene/import/pbrt/params.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

std::string PbrtLocation::str() const {
    return fmt::format("{}:{}", file, line);
}

bool is_pbrt_param_type(const std::string& type) {
    static const char* const kTypes[] = {"integer", "float",  "point2",   "vector2",   "point3",
                                         "vector3", "normal", "normal3",  "point",     "vector",
                                         "rgb",     "color",  "spectrum", "blackbody", "bool",
                                         "string",  "texture"};
    return std::find(std::begin(kTypes), std::end(kTypes), type) != std::end(kTypes);
}

void PbrtParams::add(PbrtParam param, std::vector<std::string>& warnings) {
    for (PbrtParam& p : m_params) {
        if (p.name == param.name) {
            warnings.push_back(fmt::format("{}: parameter '{}' given twice; the last one is used",
                                           param.where.str(), param.name));
            p = std::move(param);
            return;
        }
    }
    m_params.push_back(std::move(param));
}

const PbrtParam* PbrtParams::find(const std::string& name) const {
    for (const PbrtParam& p : m_params) {
        if (p.name == name) {
            p.used = true;
            return &p;
        }
    }
    return nullptr;
}

void PbrtParams::fail(const PbrtParam& param, const std::string& message) {
    throw Error(fmt::format("{}: parameter '{}': {}", param.where.str(), param.name, message));
}

const PbrtParam* PbrtParams::find_typed(const std::string& name,
                                        std::initializer_list<const char*> types,
                                        const char* expected) const {
    const PbrtParam* p = find(name);
    if (!p) return nullptr;
    for (const char* type : types)
        if (p->type == type) return p;
    fail(*p, fmt::format("declared as '{}', expected {}", p->type, expected));
}

double PbrtParams::get_float(const std::string& name, double fallback) const {
    const PbrtParam* p = find_typed(name, {"float"}, "'float'");
    if (!p) return fallback;
    if (p->numbers.size() != 1)
        fail(*p, fmt::format("expected 1 value, got {}", p->numbers.size()));
    return p->numbers[0];
}

int PbrtParams::get_int(const std::string& name, int fallback) const {
    const PbrtParam* p = find_typed(name, {"integer"}, "'integer'");
    if (!p) return fallback;
    if (p->numbers.size() != 1)
        fail(*p, fmt::format("expected 1 value, got {}", p->numbers.size()));
    return static_cast<int>(p->numbers[0]);
}

bool PbrtParams::get_bool(const std::string& name, bool fallback) const {
    const PbrtParam* p = find_typed(name, {"bool"}, "'bool'");
    if (!p) return fallback;
    if (p->bools.size() != 1) fail(*p, fmt::format("expected 1 value, got {}", p->bools.size()));
    return p->bools[0];
}

std::string PbrtParams::get_string(const std::string& name, const std::string& fallback) const {
    const PbrtParam* p = find_typed(name, {"string"}, "'string'");
    if (!p) return fallback;
    if (p->strings.size() != 1)
        fail(*p, fmt::format("expected 1 value, got {}", p->strings.size()));
    return p->strings[0];
}

std::vector<double> PbrtParams::get_floats(const std::string& name) const {
    const PbrtParam* p = find_typed(name, {"float"}, "'float'");
    return p ? p->numbers : std::vector<double>{};
}

std::vector<int> PbrtParams::get_ints(const std::string& name) const {
    const PbrtParam* p = find_typed(name, {"integer"}, "'integer'");
    std::vector<int> out;
    if (p) out.assign(p->numbers.begin(), p->numbers.end());
    return out;
}

std::vector<Vec3> PbrtParams::get_vec3s(const std::string& name) const {
    const PbrtParam* p =
        find_typed(name, {"point3", "vector3", "normal", "normal3", "point", "vector"},
                   "a point3, vector3 or normal");
    std::vector<Vec3> out;
    if (!p) return out;
    out.reserve(p->numbers.size() / 3);
    for (size_t i = 0; i + 2 < p->numbers.size(); i += 3)
        out.emplace_back(p->numbers[i], p->numbers[i + 1], p->numbers[i + 2]);
    return out;
}

std::vector<Vec2> PbrtParams::get_vec2s(const std::string& name) const {
    const PbrtParam* p = find_typed(name, {"point2", "vector2", "float"}, "a point2");
    std::vector<Vec2> out;
    if (!p) return out;
    if (p->numbers.size() % 2 != 0)
        fail(*p, fmt::format("{} values is not a whole number of pairs", p->numbers.size()));
    out.reserve(p->numbers.size() / 2);
    for (size_t i = 0; i + 1 < p->numbers.size(); i += 2)
        out.emplace_back(p->numbers[i], p->numbers[i + 1]);
    return out;
}

Vec3 PbrtParams::get_vec3(const std::string& name, const Vec3& fallback) const {
    const std::vector<Vec3> v = get_vec3s(name);
    if (v.empty()) return fallback;
    if (v.size() != 1) fail(*find(name), fmt::format("expected 1 point, got {}", v.size()));
    return v[0];
}

std::optional<std::string> PbrtParams::get_texture(const std::string& name) const {
    const PbrtParam* p = find(name);
    if (!p || p->type != "texture") return std::nullopt;
    if (p->strings.size() != 1)
        fail(*p, fmt::format("expected 1 value, got {}", p->strings.size()));
    return p->strings[0];
}

std::vector<const PbrtParam*> PbrtParams::unused() const {
    std::vector<const PbrtParam*> out;
    for (const PbrtParam& p : m_params)
        if (!p.used) out.push_back(&p);
    return out;
}

}  // namespace glint
