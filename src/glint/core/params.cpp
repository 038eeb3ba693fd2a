#include <glint/core/error.h>
#include <glint/core/params.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace glint {

const char* param_type_name(const ParamValue& value) {
    switch (value.index()) {
        case 0:
            return "a boolean";
        case 1:
            return "a number";
        case 2:
            return "a string";
        case 3:
            return "a list of numbers";
        case 4:
            return "a list of lists of numbers";
        case 5:
            return "a list of strings";
        case 6:
            return "a transform";
        default:
            return std::get<ObjectRef>(value).kind.c_str();
    }
}

bool Params::has(const std::string& name) const {
    m_asked.insert(name);
    return m_values.count(name) != 0;
}

bool Params::is_ref(const std::string& name, const std::string& kind) const {
    auto it = m_values.find(name);
    if (it == m_values.end()) return false;
    auto ref = std::get_if<ObjectRef>(&it->second);
    return ref && ref->kind == kind;
}

bool Params::is_number_or_numbers(const std::string& name) const {
    auto it = m_values.find(name);
    return it != m_values.end() && (std::holds_alternative<double>(it->second) ||
                                    std::holds_alternative<std::vector<double>>(it->second));
}

bool Params::is_string(const std::string& name) const {
    auto it = m_values.find(name);
    return it != m_values.end() && std::holds_alternative<std::string>(it->second);
}

const ParamValue* Params::lookup(const std::string& name) const {
    m_asked.insert(name);
    auto it = m_values.find(name);
    return it == m_values.end() ? nullptr : &it->second;
}

void Params::fail(const std::string& message) const {
    throw Error(fmt::format("{}: {}: {}", m_where, m_type, message));
}

void Params::fail_at(const std::string& name, const std::string& message) const {
    throw Error(fmt::format("{}: {}: {}", where_of(name), m_type, message));
}

const std::string& Params::where_of(const std::string& name) const {
    auto it = m_key_where.find(name);
    return it == m_key_where.end() ? m_where : it->second;
}

void Params::wrong_type(const std::string& name, const char* expected) const {
    fail_at(name, fmt::format("parameter '{}' must be {}, got {}", name, expected,
                              param_type_name(*lookup(name))));
}

float Params::get_float(const std::string& name, float fallback) const {
    const ParamValue* v = lookup(name);
    if (!v) return fallback;
    if (auto d = std::get_if<double>(v)) {
        // Finite as a double is not enough: 1e39 becomes an infinite float.
        if (!std::isfinite(static_cast<float>(*d)))
            fail_at(name, fmt::format("parameter '{}' must be finite", name));
        return static_cast<float>(*d);
    }
    wrong_type(name, "a number");
}

float Params::get_float(const std::string& name) const {
    if (!has(name)) fail(fmt::format("missing required parameter '{}' (a number)", name));
    return get_float(name, 0.0f);
}

int Params::get_int(const std::string& name, int fallback) const {
    const ParamValue* v = lookup(name);
    if (!v) return fallback;
    auto d = std::get_if<double>(v);
    if (!d || *d != std::floor(*d)) wrong_type(name, "an integer");
    // Whole numbers past what an int holds are out of range, not "not an integer".
    if (*d > std::numeric_limits<int>::max() || *d < std::numeric_limits<int>::min())
        fail_at(name, fmt::format("'{}' is {:.0f}, beyond the integers glint holds (-2^31 to "
                                  "2^31 - 1)",
                                  name, *d));
    return static_cast<int>(*d);
}

bool Params::get_bool(const std::string& name, bool fallback) const {
    const ParamValue* v = lookup(name);
    if (!v) return fallback;
    if (auto b = std::get_if<bool>(v)) return *b;
    wrong_type(name, "a boolean");
}

std::string Params::get_string(const std::string& name, const std::string& fallback) const {
    const ParamValue* v = lookup(name);
    if (!v) return fallback;
    if (auto s = std::get_if<std::string>(v)) return *s;
    wrong_type(name, "a string");
}

std::string Params::get_string(const std::string& name) const {
    if (!has(name)) fail(fmt::format("missing required parameter '{}' (a string)", name));
    return get_string(name, "");
}

Rgb Params::get_rgb(const std::string& name, const Rgb& fallback) const {
    const ParamValue* v = lookup(name);
    if (!v) return fallback;
    if (auto d = std::get_if<double>(v)) {
        if (!std::isfinite(*d)) fail_at(name, fmt::format("parameter '{}' must be finite", name));
        return Rgb(static_cast<float>(*d));
    }
    auto list = std::get_if<std::vector<double>>(v);
    if (!list || list->size() != 3) wrong_type(name, "a number or a list of 3 numbers");
    const Rgb rgb(static_cast<float>((*list)[0]), static_cast<float>((*list)[1]),
                  static_cast<float>((*list)[2]));
    if (!rgb.is_finite()) fail_at(name, fmt::format("parameter '{}' must be finite", name));
    return rgb;
}

Rgb Params::get_rgb(const std::string& name) const {
    if (!has(name)) fail(fmt::format("missing required parameter '{}' (a colour)", name));
    return get_rgb(name, Rgb());
}

Vec3 Params::get_vec3(const std::string& name, const Vec3& fallback) const {
    const ParamValue* v = lookup(name);
    if (!v) return fallback;
    auto list = std::get_if<std::vector<double>>(v);
    if (!list || list->size() != 3) wrong_type(name, "a list of 3 numbers");
    const Vec3 result((*list)[0], (*list)[1], (*list)[2]);
    if (!is_finite(result)) fail_at(name, fmt::format("parameter '{}' must be finite", name));
    return result;
}

Vec3 Params::get_vec3(const std::string& name) const {
    if (!has(name))
        fail(fmt::format("missing required parameter '{}' (a list of 3 numbers)", name));
    return get_vec3(name, Vec3(0.0f));
}

std::vector<double> Params::get_numbers(const std::string& name) const {
    const ParamValue* v = lookup(name);
    if (!v) return {};
    if (auto list = std::get_if<std::vector<double>>(v)) return *list;
    if (auto number = std::get_if<double>(v)) return {*number};
    wrong_type(name, "a list of numbers");
}

namespace {
template <int N>
std::vector<glm::vec<N, float>> to_vectors(const Params& params, const std::string& name,
                                           const std::vector<std::vector<double>>& rows) {
    std::vector<glm::vec<N, float>> result;
    result.reserve(rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].size() != N) {
            params.fail(fmt::format("entry {} of '{}' has {} numbers, expected {}", i + 1, name,
                                    rows[i].size(), N));
        }
        glm::vec<N, float> v;
        for (int k = 0; k < N; ++k) {
            v[k] = static_cast<float>(rows[i][k]);
            if (!std::isfinite(v[k]))
                params.fail(fmt::format("entry {} of '{}' is not finite", i + 1, name));
        }
        result.push_back(v);
    }
    return result;
}
}  // namespace

std::vector<Vec3> Params::get_vec3_list(const std::string& name) const {
    const ParamValue* v = lookup(name);
    if (!v) return {};
    if (auto rows = std::get_if<std::vector<std::vector<double>>>(v))
        return to_vectors<3>(*this, name, *rows);
    wrong_type(name, "a list of {x, y, z} points");
}

std::vector<Vec2> Params::get_vec2_list(const std::string& name) const {
    const ParamValue* v = lookup(name);
    if (!v) return {};
    if (auto rows = std::get_if<std::vector<std::vector<double>>>(v))
        return to_vectors<2>(*this, name, *rows);
    wrong_type(name, "a list of {u, v} pairs");
}

std::vector<std::vector<double>> Params::get_rows(const std::string& name) const {
    const ParamValue* v = lookup(name);
    if (!v) return {};
    if (auto rows = std::get_if<std::vector<std::vector<double>>>(v)) return *rows;
    wrong_type(name, "a list of lists of numbers");
}

std::vector<std::string> Params::get_strings(const std::string& name) const {
    const ParamValue* v = lookup(name);
    if (!v) return {};
    if (auto s = std::get_if<std::string>(v)) return {*s};
    if (auto list = std::get_if<std::vector<std::string>>(v)) return *list;
    wrong_type(name, "a string or a list of strings");
}

Transform Params::get_transform(const std::string& name) const {
    const ParamValue* v = lookup(name);
    if (!v) return Transform();
    if (auto xf = std::get_if<Transform>(v)) return *xf;
    wrong_type(name, "a transform (glint.translate, glint.rotate, glint.scale, glint.matrix)");
}

ObjectRef Params::get_ref(const std::string& name, const std::string& kind) const {
    const ParamValue* v = lookup(name);
    if (!v) fail(fmt::format("missing required parameter '{}' (a {})", name, kind));
    auto ref = std::get_if<ObjectRef>(v);
    if (!ref || ref->kind != kind) wrong_type(name, fmt::format("a {}", kind).c_str());
    return *ref;
}

std::vector<std::string> Params::unused() const {
    std::vector<std::string> names;
    for (const auto& [name, value] : m_values) {
        if (!m_asked.count(name)) names.push_back(name);
    }
    return names;
}

void Params::check_all_used() const {
    for (const auto& [name, value] : m_values) {
        if (m_asked.count(name)) continue;
        std::string known;
        for (const auto& asked : m_asked) known += (known.empty() ? "" : ", ") + asked;
        fail(fmt::format("unknown parameter '{}' (known parameters: {})", name,
                         known.empty() ? "none" : known));
    }
}

}  // namespace glint
