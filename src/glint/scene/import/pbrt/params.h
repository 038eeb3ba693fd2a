#pragma once
// The parameter lists of pbrt-v4 directives ("float radius" [1], "rgb L" [1 1 1], ...): each
// parameter checked for its type and count when read, and every lookup recorded, so that
// what the importer does not read becomes a warning naming the file and line.
#include <glint/math/vector.h>

#include <optional>
#include <string>
#include <vector>

namespace glint {

/// Where in which file something was written.
struct PbrtLocation {
    std::string file;
    int line = 0;
    std::string str() const;  ///< "file:line"
};

/// One parameter: its declared type ("float", "rgb", "spectrum", ...), its name and values.
struct PbrtParam {
    std::string type;
    std::string name;
    std::vector<double> numbers;       ///< numeric types, spectrum pairs, blackbody
    std::vector<std::string> strings;  ///< string, texture, a named or file spectrum
    std::vector<bool> bools;
    PbrtLocation where;
    mutable bool used = false;
};

/// The types a parameter may be declared with; "point" and "vector" mean the 3D ones,
/// "normal" is "normal3" and "color" is "rgb", as in pbrt-v4.
bool is_pbrt_param_type(const std::string& type);

/// A directive's parameter list. Getters with a type mismatch throw glint::Error naming the
/// parameter's file and line.
class PbrtParams {
public:
    PbrtParams() = default;
    explicit PbrtParams(PbrtLocation where) : m_where(std::move(where)) {}

    /// Adds a parameter; a repeated name replaces the earlier one (pbrt-v4 warns; so do we).
    void add(PbrtParam param, std::vector<std::string>& warnings);

    /// The parameter `name` (marked as read), or nullptr.
    const PbrtParam* find(const std::string& name) const;
    bool has(const std::string& name) const { return find(name) != nullptr; }

    double get_float(const std::string& name, double fallback) const;
    int get_int(const std::string& name, int fallback) const;
    bool get_bool(const std::string& name, bool fallback) const;
    std::string get_string(const std::string& name, const std::string& fallback) const;
    std::vector<double> get_floats(const std::string& name) const;
    std::vector<int> get_ints(const std::string& name) const;
    std::vector<Vec3> get_vec3s(const std::string& name) const;  ///< point3, vector3, normal
    std::vector<Vec2> get_vec2s(const std::string& name) const;  ///< point2, vector2
    Vec3 get_vec3(const std::string& name, const Vec3& fallback) const;
    /// The name of a texture given as "texture NAME", or nothing.
    std::optional<std::string> get_texture(const std::string& name) const;

    /// Parameters given that nothing read, in the order given.
    std::vector<const PbrtParam*> unused() const;
    const std::vector<PbrtParam>& all() const { return m_params; }
    const PbrtLocation& where() const { return m_where; }

    /// Throws glint::Error "file:line: message" at the parameter's location.
    [[noreturn]] static void fail(const PbrtParam& param, const std::string& message);

private:
    const PbrtParam* find_typed(const std::string& name, std::initializer_list<const char*> types,
                                const char* expected) const;

    std::vector<PbrtParam> m_params;
    PbrtLocation m_where;
};

}  // namespace glint
