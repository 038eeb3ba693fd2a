#include <glint/core/error.h>
#include <glint/scene/import/file_bytes.h>
#include <glint/scene/import/pbrt/parser.h>
#include <glint/scene/import/pbrt/tokenizer.h>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <memory>

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxIncludeDepth = 64;

// What AttributeBegin saves and AttributeEnd restores.
struct GraphicsState {
    Mat4 ctm{1.0f};
    bool reverse_orientation = false;
    PbrtMaterialRef material{0, {}};  // pbrt-v4's default: diffuse, reflectance 0.5
    std::optional<PbrtEntity> area_light;
    PbrtLocation where;  // of the AttributeBegin, for an unmatched one
    bool is_object = false;
};

class Parser {
public:
    Parser(std::string directory) { m_scene.directory = std::move(directory); }

    PbrtScene run(std::string text, const std::string& name) {
        // Material 0 is the default material shapes get before any Material directive.
        m_scene.materials.push_back(
            PbrtEntity{"diffuse", PbrtParams(PbrtLocation{name, 0}), PbrtLocation{name, 0}});
        open_file(std::move(text), name, fs::weakly_canonical(name).string());
        while (true) {
            Tok t = next();
            if (t.token.kind == PbrtToken::Kind::End) break;
            if (t.token.kind != PbrtToken::Kind::Word)
                fail(t, fmt::format("expected a directive, got {}", describe(t.token)));
            directive(t);
        }
        if (m_stack.size() > 0) {
            warn(m_stack.back().where, "AttributeBegin",
                 "not closed by AttributeEnd before the end of the file");
        }
        return std::move(m_scene);
    }

private:
    // A token and the file it came from (a name in m_names, which outlives every token:
    // a directive's token is still used after an include it ends has been closed).
    struct Tok {
        PbrtToken token;
        const std::string* name;
        const std::string& file() const { return *name; }
    };

    static std::string describe(const PbrtToken& t) {
        switch (t.kind) {
            case PbrtToken::Kind::End:
                return "the end of the file";
            case PbrtToken::Kind::Open:
                return "'['";
            case PbrtToken::Kind::Close:
                return "']'";
            case PbrtToken::Kind::String:
                return fmt::format("the string \"{}\"", t.text);
            default:
                return fmt::format("'{}'", t.text);
        }
    }

    [[noreturn]] void fail(const Tok& at, const std::string& what) const {
        throw Error(fmt::format("{}:{}: {}", at.file(), at.token.line, what));
    }

    void warn(const PbrtLocation& where, const std::string& directive, const std::string& what) {
        m_scene.warnings.push_back(fmt::format("{}: {}: {}", where.str(), directive, what));
    }

    // The next token, across the end of included files.
    Tok next() {
        if (m_peeked) {
            Tok t = std::move(*m_peeked);
            m_peeked.reset();
            return t;
        }
        while (true) {
            PbrtTokenizer& file = *m_files.back();
            PbrtToken t = file.next();
            if (t.kind != PbrtToken::Kind::End || m_files.size() == 1)
                return Tok{t, m_file_names.back()};
            m_files.pop_back();
            m_open.pop_back();
            m_file_names.pop_back();
        }
    }

    const Tok& peek() {
        if (!m_peeked) m_peeked = next();
        return *m_peeked;
    }

    Tok expect_string(const Tok& directive) {
        Tok t = next();
        if (t.token.kind != PbrtToken::Kind::String)
            fail(t, fmt::format("{}: expected a quoted string, got {}", directive.token.text,
                                describe(t.token)));
        return t;
    }

    double to_number(const Tok& t) const {
        if (t.token.kind != PbrtToken::Kind::Word)
            fail(t, fmt::format("expected a number, got {}", describe(t.token)));
        const char* begin = t.token.text.c_str();
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(begin, &end);
        if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(value))
            fail(t, fmt::format("'{}' is not a finite number", t.token.text));
        return value;
    }

    std::vector<double> numbers(const Tok& directive, size_t count) {
        std::vector<double> v;
        for (size_t i = 0; i < count; ++i) {
            Tok t = next();
            if (t.token.kind != PbrtToken::Kind::Word)
                fail(directive, fmt::format("{}: expected {} numbers, got {} before {}",
                                            directive.token.text, count, i, describe(t.token)));
            v.push_back(to_number(t));
        }
        return v;
    }

    // 16 numbers, bracketed or not (pbrt accepts both).
    Mat4 matrix_argument(const Tok& directive) {
        const bool bracketed = peek().token.kind == PbrtToken::Kind::Open;
        if (bracketed) next();
        std::vector<double> v;
        while (true) {
            const Tok& t = peek();
            if (t.token.kind != PbrtToken::Kind::Word) break;
            if (!bracketed && v.size() == 16) break;
            v.push_back(to_number(next()));
        }
        if (bracketed) {
            Tok close = next();
            if (close.token.kind != PbrtToken::Kind::Close)
                fail(close, fmt::format("{}: expected ']' after the numbers, got {}",
                                        directive.token.text, describe(close.token)));
        }
        if (v.size() != 16)
            fail(directive,
                 fmt::format("{}: expected 16 numbers, got {}", directive.token.text, v.size()));
        // pbrt-v4 reads the 16 numbers row by row and transposes: they are the matrix's
        // columns one after the other (the translation is numbers 13-15), which is glm's order.
        float f[16];
        for (int i = 0; i < 16; ++i) f[i] = static_cast<float>(v[i]);
        return glm::make_mat4(f);
    }

    // A parameter's values: one token or a bracketed list.
    // A parameter's values, one token or a bracketed list, each passed to `take` as it is
    // read (a mesh's millions of numbers are never held as tokens). Returns their count.
    template <typename Take>
    size_t values(const Tok& declaration, Take&& take) {
        if (peek().token.kind != PbrtToken::Kind::Open) {
            Tok t = next();
            if (t.token.kind != PbrtToken::Kind::Word && t.token.kind != PbrtToken::Kind::String)
                fail(t, fmt::format("parameter \"{}\": expected a value, got {}",
                                    declaration.token.text, describe(t.token)));
            take(t);
            return 1;
        }
        const Tok open = next();
        for (size_t count = 0;; ++count) {
            Tok t = next();
            if (t.token.kind == PbrtToken::Kind::Close) return count;
            if (t.token.kind == PbrtToken::Kind::End || t.token.kind == PbrtToken::Kind::Open)
                fail(open, fmt::format("parameter \"{}\": '[' is not closed by ']' (found {})",
                                       declaration.token.text, describe(t.token)));
            take(t);
        }
    }

    PbrtParam parameter(const Tok& declaration) {
        PbrtParam p;
        p.where = PbrtLocation{declaration.file(), declaration.token.line};
        std::vector<std::string> words;
        std::string word;
        for (char c : declaration.token.text + " ") {
            if (c == ' ' || c == '\t') {
                if (!word.empty()) words.push_back(std::move(word));
                word.clear();
            } else {
                word.push_back(c);
            }
        }
        if (words.size() != 2)
            fail(declaration,
                 fmt::format("parameter \"{}\": expected \"TYPE NAME\"", declaration.token.text));
        p.type = words[0];
        p.name = words[1];
        if (!is_pbrt_param_type(p.type))
            fail(declaration, fmt::format("parameter \"{}\": unknown type '{}'",
                                          declaration.token.text, p.type));
        if (p.type == "point") p.type = "point3";
        if (p.type == "vector") p.type = "vector3";
        if (p.type == "normal") p.type = "normal3";
        if (p.type == "color") p.type = "rgb";
        // A spectrum is named (a string) or given by numbers: its first value decides.
        std::optional<bool> stringy;
        if (p.type == "string" || p.type == "texture") stringy = true;
        const size_t count = values(declaration, [&](const Tok& v) {
            if (!stringy) stringy = p.type == "spectrum" && v.token.kind == PbrtToken::Kind::String;
            if (p.type == "bool") {
                const std::string& s = v.token.text;
                if (s != "true" && s != "false")
                    fail(v, fmt::format("parameter \"{}\": '{}' is not true or false",
                                        declaration.token.text, s));
                p.bools.push_back(s == "true");
            } else if (*stringy) {
                if (v.token.kind != PbrtToken::Kind::String)
                    fail(v, fmt::format("parameter \"{}\": expected a quoted string, got {}",
                                        declaration.token.text, describe(v.token)));
                p.strings.push_back(v.token.text);
            } else {
                p.numbers.push_back(to_number(v));
            }
        });
        if (count == 0)
            fail(declaration,
                 fmt::format("parameter \"{}\" has no values", declaration.token.text));
        check_count(declaration, p);
        return p;
    }

    void check_count(const Tok& declaration, const PbrtParam& p) const {
        const size_t n = p.numbers.size();
        auto need = [&](bool ok, const char* what) {
            if (!ok)
                fail(declaration, fmt::format("parameter \"{}\": {} values, expected {}",
                                              declaration.token.text, n, what));
        };
        if (p.type == "point3" || p.type == "vector3" || p.type == "normal3")
            need(n % 3 == 0, "a multiple of 3");
        if (p.type == "point2" || p.type == "vector2") need(n % 2 == 0, "a multiple of 2");
        if (p.type == "rgb") need(n == 3, "3");
        if (p.type == "blackbody") need(n == 1 || n == 2, "1 (the temperature in kelvin)");
        if (p.type == "spectrum" && p.strings.empty())
            need(n >= 2 && n % 2 == 0, "pairs of wavelength (nm) and value");
        if (p.type == "integer")
            for (double v : p.numbers)
                if (v != std::floor(v))
                    fail(declaration, fmt::format("parameter \"{}\": {} is not an integer",
                                                  declaration.token.text, v));
        if ((p.type == "string" || p.type == "texture") && p.strings.size() != 1 &&
            p.type == "texture")
            fail(declaration, fmt::format("parameter \"{}\": expected one texture name",
                                          declaration.token.text));
        if (p.type == "spectrum" && p.strings.size() > 1)
            fail(declaration, fmt::format("parameter \"{}\": expected one spectrum name",
                                          declaration.token.text));
    }

    PbrtParams parameters(const Tok& directive) {
        PbrtParams params(PbrtLocation{directive.file(), directive.token.line});
        while (peek().token.kind == PbrtToken::Kind::String)
            params.add(parameter(next()), m_scene.warnings);
        return params;
    }

    PbrtEntity entity(const Tok& directive, const std::string& type) {
        PbrtEntity e;
        e.type = type;
        e.where = PbrtLocation{directive.file(), directive.token.line};
        e.params = parameters(directive);
        return e;
    }

    void apply(const Mat4& m) {
        if (m_ignore_transforms) return;
        m_state.ctm = m_state.ctm * m;
    }

    // pbrt-v4's LookAt: the camera (or light) space whose +z looks from `eye` at `target`
    // with +y towards `up` and +x = up x dir (left-handed); the matrix maps world to it.
    Mat4 look_at(const Tok& at, const Vec3& eye, const Vec3& target, const Vec3& up) const {
        const Vec3 d = target - eye;
        if (glm::length(d) == 0.0f) fail(at, "LookAt: the eye and the look-at point are the same");
        const Vec3 dir = glm::normalize(d);
        if (glm::length(up) == 0.0f) fail(at, "LookAt: the up vector is zero");
        const Vec3 r = glm::cross(glm::normalize(up), dir);
        if (glm::length(r) < 1e-6f)
            fail(at, "LookAt: the up vector and the viewing direction are parallel");
        const Vec3 right = glm::normalize(r);
        const Vec3 new_up = glm::cross(dir, right);
        Mat4 world_from_camera(1.0f);
        world_from_camera[0] = Vec4(right, 0.0f);
        world_from_camera[1] = Vec4(new_up, 0.0f);
        world_from_camera[2] = Vec4(dir, 0.0f);
        world_from_camera[3] = Vec4(eye, 1.0f);
        return glm::inverse(world_from_camera);
    }

    void include(const Tok& directive) {
        const Tok name = expect_string(directive);
        fs::path path = name.token.text;
        if (path.is_relative()) path = fs::path(m_scene.directory) / path;
        if (m_files.size() >= kMaxIncludeDepth)
            fail(name, fmt::format("{}: files included more than {} deep", directive.token.text,
                                   kMaxIncludeDepth));
        const std::string canonical = fs::weakly_canonical(path).string();
        for (const std::string& open : m_open)
            if (open == canonical)
                fail(name,
                     fmt::format("{}: '{}' includes itself", directive.token.text, path.string()));
        std::string text;
        try {
            text = read_file_bytes(path.string(), "pbrt");
        } catch (const Error& e) {
            fail(name, fmt::format("{}: {}", directive.token.text, e.what()));
        }
        m_peeked.reset();  // nothing was peeked past the file name (it is the last argument)
        open_file(std::move(text), path.string(), canonical);
    }

    void open_file(std::string text, const std::string& name, const std::string& canonical) {
        m_names.push_back(name);
        m_file_names.push_back(&m_names.back());
        m_files.push_back(std::make_unique<PbrtTokenizer>(std::move(text), name));
        m_open.push_back(canonical);
    }

    void shape(const Tok& directive) {
        PbrtShape s;
        s.entity = entity(directive, expect_string(directive).token.text);
        s.to_world = m_state.ctm;
        s.material = m_state.material;
        s.area_light = m_state.area_light;
        s.reverse_orientation = m_state.reverse_orientation;
        if (glm::abs(glm::determinant(Mat3(s.to_world))) < 1e-30f)
            fail(directive, "Shape: the current transform is not invertible (a zero scale?)");
        if (m_object >= 0)
            m_scene.objects[static_cast<size_t>(m_object)].shapes.push_back(std::move(s));
        else
            m_scene.shapes.push_back(std::move(s));
    }

    void attribute_end(const Tok& directive, bool object_end) {
        if (m_stack.empty())
            fail(directive, fmt::format("{} without a matching {}", directive.token.text,
                                        object_end ? "ObjectBegin" : "AttributeBegin"));
        if (m_stack.back().is_object != object_end)
            fail(directive, fmt::format("{} closes the {} at {}", directive.token.text,
                                        m_stack.back().is_object ? "ObjectBegin" : "AttributeBegin",
                                        m_stack.back().where.str()));
        m_state = m_stack.back();
        m_stack.pop_back();
        if (object_end) m_object = -1;
    }

    void attribute_begin(const Tok& directive, bool object) {
        GraphicsState saved = m_state;
        saved.where = PbrtLocation{directive.file(), directive.token.line};
        saved.is_object = object;
        m_stack.push_back(std::move(saved));
    }

    void directive(const Tok& d) {
        const std::string& name = d.token.text;
        const PbrtLocation where{d.file(), d.token.line};
        ++m_scene.directive_counts[name];
        if (name == "Include" || name == "Import") {
            include(d);
        } else if (name == "Identity") {
            if (!m_ignore_transforms) m_state.ctm = Mat4(1.0f);
        } else if (name == "Translate") {
            const auto v = numbers(d, 3);
            apply(glm::translate(Mat4(1.0f), Vec3(v[0], v[1], v[2])));
        } else if (name == "Scale") {
            const auto v = numbers(d, 3);
            apply(glm::scale(Mat4(1.0f), Vec3(v[0], v[1], v[2])));
        } else if (name == "Rotate") {
            const auto v = numbers(d, 4);
            const Vec3 axis(v[1], v[2], v[3]);
            if (glm::length(axis) == 0.0f) fail(d, "Rotate: the axis is zero");
            apply(glm::rotate(Mat4(1.0f), glm::radians(static_cast<float>(v[0])),
                              glm::normalize(axis)));
        } else if (name == "LookAt") {
            const auto v = numbers(d, 9);
            apply(
                look_at(d, Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), Vec3(v[6], v[7], v[8])));
        } else if (name == "Transform") {
            const Mat4 m = matrix_argument(d);
            if (!m_ignore_transforms) m_state.ctm = m;
        } else if (name == "ConcatTransform") {
            apply(matrix_argument(d));
        } else if (name == "CoordinateSystem") {
            m_named_spaces[expect_string(d).token.text] = m_state.ctm;
        } else if (name == "CoordSysTransform") {
            const Tok n = expect_string(d);
            auto it = m_named_spaces.find(n.token.text);
            if (it == m_named_spaces.end())
                warn(where, name,
                     fmt::format("unknown coordinate system \"{}\" (ignored)", n.token.text));
            else
                m_state.ctm = it->second;
        } else if (name == "ReverseOrientation") {
            m_state.reverse_orientation = !m_state.reverse_orientation;
        } else if (name == "AttributeBegin" || name == "TransformBegin") {
            attribute_begin(d, false);
        } else if (name == "AttributeEnd" || name == "TransformEnd") {
            if (name == "TransformEnd" && !m_stack.empty() && !m_stack.back().is_object) {
                // TransformBegin/End (pbrt-v3) keep only the transform.
                const Mat4 ctm = m_stack.back().ctm;
                attribute_end(d, false);
                m_state.ctm = ctm;
            } else {
                attribute_end(d, false);
            }
        } else if (name == "ObjectBegin") {
            const Tok n = expect_string(d);
            if (m_object >= 0)
                fail(d, fmt::format("ObjectBegin \"{}\" inside the definition of \"{}\"",
                                    n.token.text, m_scene.objects[m_object].name));
            attribute_begin(d, true);
            m_scene.objects.push_back(PbrtObject{n.token.text, where, {}});
            m_object = static_cast<int>(m_scene.objects.size()) - 1;
        } else if (name == "ObjectEnd") {
            attribute_end(d, true);
        } else if (name == "ObjectInstance") {
            const Tok n = expect_string(d);
            if (m_object >= 0) fail(d, "ObjectInstance inside an object definition");
            m_scene.instances.push_back(PbrtInstance{n.token.text, m_state.ctm, where});
        } else if (name == "WorldBegin") {
            m_state.ctm = Mat4(1.0f);
            m_named_spaces["world"] = Mat4(1.0f);
        } else if (name == "WorldEnd") {
            // pbrt-v3's end of the scene; pbrt-v4 ends at the end of the file.
        } else if (name == "ActiveTransform") {
            const Tok which = next();
            if (which.token.text == "EndTime") {
                warn(where, name, "motion blur is not supported: end-time transforms are ignored");
                m_ignore_transforms = true;
            } else if (which.token.text == "StartTime" || which.token.text == "All") {
                m_ignore_transforms = false;
            } else {
                fail(which,
                     fmt::format("ActiveTransform: expected StartTime, EndTime or All, got {}",
                                 describe(which.token)));
            }
        } else if (name == "TransformTimes") {
            numbers(d, 2);
            warn(where, name, "motion blur is not supported (ignored)");
        } else if (name == "Camera") {
            PbrtCamera c;
            c.entity = entity(d, expect_string(d).token.text);
            const float det = glm::determinant(Mat3(m_state.ctm));
            if (std::abs(det) < 1e-30f) fail(d, "Camera: the current transform is not invertible");
            c.camera_to_world = glm::inverse(m_state.ctm);
            m_named_spaces["camera"] = c.camera_to_world;
            m_scene.camera = std::move(c);
        } else if (name == "Film" || name == "Sampler" || name == "Integrator" ||
                   name == "PixelFilter") {
            PbrtEntity e = entity(d, expect_string(d).token.text);
            auto& slot = name == "Film"         ? m_scene.film
                         : name == "Sampler"    ? m_scene.sampler
                         : name == "Integrator" ? m_scene.integrator
                                                : m_scene.filter;
            slot = std::move(e);
        } else if (name == "Accelerator" || name == "Option" || name == "ColorSpace") {
            other(d, name);
        } else if (name == "Shape") {
            shape(d);
        } else if (name == "Material") {
            m_scene.materials.push_back(entity(d, expect_string(d).token.text));
            m_state.material = PbrtMaterialRef{static_cast<int>(m_scene.materials.size()) - 1, {}};
        } else if (name == "MakeNamedMaterial") {
            const Tok n = expect_string(d);
            PbrtEntity e = entity(d, "");
            e.type = e.params.get_string("type", "");
            if (e.type.empty()) fail(d, "MakeNamedMaterial: no \"string type\" parameter");
            if (m_scene.named_materials.count(n.token.text))
                warn(where, name,
                     fmt::format("material \"{}\" is defined again; the last "
                                 "definition is used",
                                 n.token.text));
            m_scene.named_materials[n.token.text] = std::move(e);
        } else if (name == "NamedMaterial") {
            m_state.material = PbrtMaterialRef{-1, expect_string(d).token.text};
        } else if (name == "Texture") {
            PbrtTexture t;
            t.name = expect_string(d).token.text;
            t.value_kind = expect_string(d).token.text;
            if (t.value_kind == "color" || t.value_kind == "rgb") t.value_kind = "spectrum";
            if (t.value_kind != "float" && t.value_kind != "spectrum")
                fail(d, fmt::format("Texture \"{}\": type \"{}\", expected \"float\" or "
                                    "\"spectrum\"",
                                    t.name, t.value_kind));
            t.entity = entity(d, expect_string(d).token.text);
            t.to_world = m_state.ctm;
            m_scene.textures.push_back(std::move(t));
        } else if (name == "LightSource") {
            PbrtLight l{entity(d, expect_string(d).token.text), m_state.ctm};
            if (m_object >= 0)
                warn(where, name, "a light inside an object definition is not supported (ignored)");
            else
                m_scene.lights.push_back(std::move(l));
        } else if (name == "AreaLightSource") {
            m_state.area_light = entity(d, expect_string(d).token.text);
        } else if (name == "MakeNamedMedium") {
            const Tok n = expect_string(d);
            entity(d, "");
            warn(where, name,
                 fmt::format("participating media are not supported yet: medium "
                             "\"{}\" is ignored",
                             n.token.text));
        } else if (name == "MediumInterface") {
            medium_interface(d);
        } else if (name == "Attribute") {
            const Tok target = expect_string(d);
            entity(d, "");
            warn(where, name,
                 fmt::format("default parameters for \"{}\" are not supported "
                             "(ignored)",
                             target.token.text));
        } else {
            fail(d, fmt::format("unknown directive '{}'", name));
        }
    }

    void other(const Tok& d, const std::string& name) {
        const PbrtLocation where{d.file(), d.token.line};
        if (name == "Option") {
            const Tok n = expect_string(d);
            values(n, [](const Tok&) {});
            warn(where, name, fmt::format("option \"{}\" is ignored", n.token.text));
            return;
        }
        const Tok type = expect_string(d);
        entity(d, type.token.text);
        if (name == "ColorSpace" && type.token.text == "srgb") return;
        if (name == "ColorSpace")
            warn(where, name,
                 fmt::format("colour space \"{}\" is not supported: colours are "
                             "read as linear sRGB",
                             type.token.text));
        else
            warn(where, name, "ignored (glint builds its own BVH with Embree)");
    }

    void medium_interface(const Tok& d) {
        const Tok inside = expect_string(d);
        std::string outside = inside.token.text;
        if (peek().token.kind == PbrtToken::Kind::String) outside = next().token.text;
        if (!inside.token.text.empty() || !outside.empty())
            warn(PbrtLocation{d.file(), d.token.line}, "MediumInterface",
                 "participating media are not supported yet (ignored)");
    }

    PbrtScene m_scene;
    std::vector<std::unique_ptr<PbrtTokenizer>> m_files;  // the include stack
    std::vector<std::string> m_open;                      // their canonical paths
    std::vector<const std::string*> m_file_names;         // their names, in m_names
    std::deque<std::string> m_names;  // every file opened (stable addresses for tokens)
    std::optional<Tok> m_peeked;
    GraphicsState m_state;
    std::vector<GraphicsState> m_stack;
    std::map<std::string, Mat4> m_named_spaces;
    int m_object = -1;  // the object being defined
    bool m_ignore_transforms = false;
};

}  // namespace

PbrtScene parse_pbrt_text(std::string text, const std::string& name, const std::string& directory) {
    return Parser(directory).run(std::move(text), name);
}

PbrtScene parse_pbrt_file(const std::string& path) {
    std::string directory = fs::path(path).parent_path().string();
    if (directory.empty()) directory = ".";
    return parse_pbrt_text(read_file_bytes(path, "pbrt"), path, directory);
}

}  // namespace glint
