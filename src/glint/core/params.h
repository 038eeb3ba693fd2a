#pragma once
// Named parameters of one scene object (a material, shape, light, ...), with the script
// location they came from. Every read is recorded so that a misspelt or unknown name is
// reported as an error instead of being silently ignored.
#include <glint/core/rgb.h>
#include <glint/math/transform.h>

#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace glint {

// A handle to another scene object, e.g. a material used by a shape.
struct ObjectRef {
    std::string kind;  // "material", "group", ...
    int index = -1;
};

using ParamValue =
    std::variant<bool, double, std::string, std::vector<double>, std::vector<std::vector<double>>,
                 std::vector<std::string>, Transform, ObjectRef>;

// A vector or colour as the list of numbers a Params value holds (for set()).
inline std::vector<double> numbers_of(const Vec3& v) {
    return {v.x, v.y, v.z};
}
inline std::vector<double> numbers_of(const Rgb& c) {
    return {c.r, c.g, c.b};
}

class Params {
public:
    Params() = default;
    Params(std::string type, std::string where)
        : m_type(std::move(type)), m_where(std::move(where)) {}

    void set(const std::string& name, ParamValue value) { m_values[name] = std::move(value); }
    // Sets `name` from somewhere other than the table itself (e.g. a command-line flag):
    // errors about this value name `where` instead of the table's location.
    void set(const std::string& name, ParamValue value, std::string where) {
        m_values[name] = std::move(value);
        m_key_where[name] = std::move(where);
    }
    bool has(const std::string& name) const;
    // Whether `name` was given as a handle of this kind (e.g. a "texture").
    bool is_ref(const std::string& name, const std::string& kind) const;
    // Whether `name` holds a number or a list of numbers; a string.
    bool is_number_or_numbers(const std::string& name) const;
    bool is_string(const std::string& name) const;

    float get_float(const std::string& name, float fallback) const;
    float get_float(const std::string& name) const;
    int get_int(const std::string& name, int fallback) const;
    bool get_bool(const std::string& name, bool fallback) const;
    std::string get_string(const std::string& name, const std::string& fallback) const;
    std::string get_string(const std::string& name) const;
    // A colour is a number (grey) or a list of three numbers (linear RGB).
    Rgb get_rgb(const std::string& name, const Rgb& fallback) const;
    Rgb get_rgb(const std::string& name) const;
    Vec3 get_vec3(const std::string& name, const Vec3& fallback) const;
    Vec3 get_vec3(const std::string& name) const;
    std::vector<double> get_numbers(const std::string& name) const;
    std::vector<Vec3> get_vec3_list(const std::string& name) const;
    std::vector<Vec2> get_vec2_list(const std::string& name) const;
    /// A list of lists of numbers, each of any length (empty when absent).
    std::vector<std::vector<double>> get_rows(const std::string& name) const;
    // A single string or a list of strings.
    std::vector<std::string> get_strings(const std::string& name) const;
    Transform get_transform(const std::string& name) const;  // identity when absent
    ObjectRef get_ref(const std::string& name, const std::string& kind) const;

    // Throws when a parameter was given that no get_* asked for.
    void check_all_used() const;
    // The names given that no get_* (or has) asked for, in name order.
    std::vector<std::string> unused() const;
    // Every name asked for so far, given or not.
    const std::set<std::string>& asked() const { return m_asked; }
    [[noreturn]] void fail(const std::string& message) const;
    // Fails with the location the value of `name` came from (see set() with `where`).
    [[noreturn]] void fail_at(const std::string& name, const std::string& message) const;

    const std::string& type() const { return m_type; }
    const std::string& where() const { return m_where; }
    // Where the value of `name` came from: its own location if set with one, else the table's.
    const std::string& where_of(const std::string& name) const;

private:
    const ParamValue* lookup(const std::string& name) const;
    [[noreturn]] void wrong_type(const std::string& name, const char* expected) const;

    std::string m_type;
    std::string m_where;
    std::map<std::string, ParamValue> m_values;
    std::map<std::string, std::string> m_key_where;  // values set from elsewhere (flags)
    mutable std::set<std::string> m_asked;
};

// Human-readable name of the type held, for error messages.
const char* param_type_name(const ParamValue& value);

}  // namespace glint
