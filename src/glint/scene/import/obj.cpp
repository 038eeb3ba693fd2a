#include <glint/core/error.h>
#include <glint/scene/import/file_bytes.h>
#include <glint/scene/import/obj.h>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <limits>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace glint {
namespace {

// One corner of a face as written: 0 where the element is absent, else the file's
// (1-based or negative) index.
struct Corner {
    int64_t v = 0, vt = 0, vn = 0;
};

class ObjParser {
public:
    // With `split` false, usemtl is ignored and every face goes into one part.
    ObjParser(std::string name, bool split) : m_name(std::move(name)), m_split(split) {
        m_scene.parts.emplace_back();
        m_states.emplace_back();
    }

    void parse_line(std::string_view line, uint64_t number) {
        m_line = number;
        std::string_view rest = line;
        const std::string_view keyword = next_token(rest);
        if (keyword.empty() || keyword.front() == '#') return;
        float x[7];
        if (keyword == "v") {
            numbers(rest, x, 3, 7, "'v' (x y z [w])");
            m_positions.emplace_back(x[0], x[1], x[2]);
        } else if (keyword == "vn") {
            numbers(rest, x, 3, 3, "'vn' (x y z)");
            m_normals.emplace_back(x[0], x[1], x[2]);
        } else if (keyword == "vt") {
            x[1] = 0.0f;
            numbers(rest, x, 1, 3, "'vt' (u [v [w]])");
            m_uvs.emplace_back(x[0], x[1]);
        } else if (keyword == "f") {
            parse_face(rest);
        } else if (m_split && keyword == "usemtl") {
            use_material(trimmed(rest));
        } else if (m_split && keyword == "mtllib") {
            // Names with spaces are rare; mtllib lists several files separated by spaces.
            for (std::string_view t = next_token(rest); !t.empty(); t = next_token(rest))
                m_scene.material_libraries.emplace_back(t);
        }
        // Everything else (o, g, s, l, p, curves) carries nothing a triangle mesh can use.
    }

    ObjScene finish() {
        std::vector<ObjScene::Part> kept;
        for (size_t i = 0; i < m_scene.parts.size(); ++i) {
            ObjScene::Part& part = m_scene.parts[i];
            if (part.mesh.indices.empty()) continue;
            if (!m_states[i].all_normals) part.mesh.normals.clear();
            if (!m_states[i].all_uvs) part.mesh.uvs.clear();
            kept.push_back(std::move(part));
        }
        if (kept.empty()) throw Error(fmt::format("OBJ file '{}' contains no faces", m_name));
        m_scene.parts = std::move(kept);
        return std::move(m_scene);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(fmt::format("{}:{}: {}", m_name, m_line, what));
    }

    static std::string_view next_token(std::string_view& rest) {
        size_t begin = 0;
        while (begin < rest.size() &&
               (rest[begin] == ' ' || rest[begin] == '\t' || rest[begin] == '\r'))
            ++begin;
        size_t end = begin;
        while (end < rest.size() && rest[end] != ' ' && rest[end] != '\t' && rest[end] != '\r')
            ++end;
        const std::string_view token = rest.substr(begin, end - begin);
        rest.remove_prefix(end);
        return token;
    }

    static std::string_view trimmed(std::string_view text) {
        while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
            text.remove_prefix(1);
        while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
            text.remove_suffix(1);
        return text;
    }

    void use_material(std::string_view name) {
        const auto [it, inserted] = m_part_of.try_emplace(std::string(name), m_scene.parts.size());
        if (inserted) {
            m_scene.parts.push_back({std::string(name), m_line, {}});
            m_states.emplace_back();
        }
        m_part = it->second;
    }

    // Reads min to max numbers into `values` (a fixed array: no allocation per line).
    void numbers(std::string_view rest, float* values, size_t min, size_t max,
                 const char* statement) const {
        size_t count = 0;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
            if (token.front() == '#') break;
            float value = 0.0f;
            const char* end = token.data() + token.size();
            // from_chars takes no leading '+'; OBJ writers sometimes emit one.
            const char* begin = token.front() == '+' ? token.data() + 1 : token.data();
            const auto [ptr, ec] = std::from_chars(begin, end, value);
            if (ec == std::errc::result_out_of_range)
                fail(fmt::format("'{}' is out of the range of a float", token));
            if (ec != std::errc() || ptr != end)
                fail(fmt::format("'{}' is not a number in {}", token, statement));
            if (!std::isfinite(value))
                fail(fmt::format("'{}' is not a finite number in {}", token, statement));
            if (count < max) values[count] = value;
            ++count;
        }
        if (count < min || count > max) {
            fail(fmt::format("{} needs {}{} numbers, found {}", statement, min,
                             max > min ? fmt::format(" to {}", max) : "", count));
        }
    }

    // An index as written: a non-zero integer that fits in 64 bits (no wrap-around).
    int64_t parse_index(std::string_view text, const char* what) const {
        int64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec == std::errc::result_out_of_range)
            fail(fmt::format("{} index '{}' is too large", what, text));
        if (ec != std::errc() || ptr != end)
            fail(fmt::format("'{}' is not an integer {} index", text, what));
        if (value == 0) fail(fmt::format("{} index 0: OBJ indices start at 1", what));
        return value;
    }

    // The 0-based element `index` refers to among `count` defined so far.
    uint64_t resolve(int64_t index, size_t count, const char* what, const char* plural) const {
        const auto n = static_cast<int64_t>(count);
        const int64_t resolved = index > 0 ? index - 1 : n + index;
        if (resolved < 0 || resolved >= n) {
            fail(fmt::format(
                "face refers to {} {}, but {} {} defined before it", what, index, count,
                count == 1 ? fmt::format("{} is", what) : fmt::format("{} are", plural)));
        }
        return static_cast<uint64_t>(resolved);
    }

    Corner parse_corner(std::string_view token) const {
        Corner corner;
        const size_t slash1 = token.find('/');
        corner.v = parse_index(token.substr(0, slash1), "vertex");
        if (slash1 == std::string_view::npos) return corner;
        const std::string_view after = token.substr(slash1 + 1);
        const size_t slash2 = after.find('/');
        const std::string_view vt = after.substr(0, slash2);
        if (!vt.empty()) corner.vt = parse_index(vt, "uv");
        if (slash2 != std::string_view::npos)
            corner.vn = parse_index(after.substr(slash2 + 1), "normal");
        return corner;
    }

    // The glint vertex of a corner: OBJ indexes positions, uvs and normals separately, so
    // there is one glint vertex per distinct triple.
    uint32_t vertex_of(const Corner& c) {
        const uint64_t v = resolve(c.v, m_positions.size(), "vertex", "vertices");
        const uint64_t vt = c.vt != 0 ? resolve(c.vt, m_uvs.size(), "uv", "uvs") + 1 : 0;
        const uint64_t vn =
            c.vn != 0 ? resolve(c.vn, m_normals.size(), "normal", "normals") + 1 : 0;
        PartState& state = m_states[m_part];
        MeshData& mesh = m_scene.parts[m_part].mesh;
        if (vt == 0) state.all_uvs = false;
        if (vn == 0) state.all_normals = false;
        // Most files pair each position with one uv and one normal throughout: the first
        // corner that uses a position is remembered beside it, and only corners that differ
        // from it go through the hash map (which took a fifth of the time of a large file).
        if (m_first_use.size() < m_positions.size()) m_first_use.resize(m_positions.size());
        FirstUse& first = m_first_use[v];
        const auto part = static_cast<uint32_t>(m_part);
        if (first.part == part && first.vt == vt && first.vn == vn) return first.index;
        const auto next = static_cast<uint32_t>(mesh.positions.size());
        bool inserted = true;
        uint32_t index = next;
        if (first.part == kUnused) {
            first = {vt, vn, next, part};
        } else {
            const auto [it, added] = state.vertex_of.try_emplace(Key{v, vt, vn}, next);
            inserted = added;
            index = it->second;
        }
        if (inserted) {
            if (mesh.positions.size() >= std::numeric_limits<uint32_t>::max())
                fail("more than 2^32 - 1 distinct vertices");
            mesh.positions.push_back(m_positions[v]);
            mesh.normals.push_back(vn != 0 ? m_normals[vn - 1] : Vec3(0.0f));
            mesh.uvs.push_back(vt != 0 ? m_uvs[vt - 1] : Vec2(0.0f));
        }
        return index;
    }

    void parse_face(std::string_view rest) {
        m_face.clear();
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
            if (token.front() == '#') break;
            m_face.push_back(vertex_of(parse_corner(token)));
        }
        if (m_face.size() < 3)
            fail(fmt::format("a face needs at least 3 corners, found {}", m_face.size()));
        // A fan around the first corner: right for the convex polygons OBJ describes, and
        // linear in the corner count (ear clipping is quadratic: a 200 000-corner face
        // would take minutes).
        std::vector<uint32_t>& indices = m_scene.parts[m_part].mesh.indices;
        for (size_t i = 1; i + 1 < m_face.size(); ++i) {
            indices.push_back(m_face[0]);
            indices.push_back(m_face[i]);
            indices.push_back(m_face[i + 1]);
        }
    }

    struct Key {
        uint64_t v, vt, vn;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            uint64_t h = k.v * 0x9E3779B97F4A7C15ull;
            h ^= k.vt + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
            h ^= k.vn + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
            return static_cast<size_t>(h);
        }
    };

    std::string m_name;
    uint64_t m_line = 0;
    std::vector<Vec3> m_positions, m_normals;
    std::vector<Vec2> m_uvs;
    // Per part: one glint vertex per distinct corner triple, and whether every corner had
    // a normal (a uv).
    struct PartState {
        std::unordered_map<Key, uint32_t, KeyHash> vertex_of;
        bool all_normals = true, all_uvs = true;
    };
    // Per position: the part, uv and normal of the first corner that used it, and the glint
    // vertex made for it.
    static constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
    struct FirstUse {
        uint64_t vt = 0, vn = 0;
        uint32_t index = 0;
        uint32_t part = kUnused;
    };
    std::vector<FirstUse> m_first_use;
    std::vector<uint32_t> m_face;  // reused from face to face
    bool m_split;
    ObjScene m_scene;
    std::vector<PartState> m_states;  // parallel to m_scene.parts
    std::unordered_map<std::string, size_t> m_part_of;
    size_t m_part = 0;
};

ObjScene parse_text(std::string_view text, const std::string& name, bool split) {
    ObjParser parser(name, split);
    for_each_line(text,
                  [&](std::string_view line, uint64_t number) { parser.parse_line(line, number); });
    return parser.finish();
}

}  // namespace

MeshData parse_obj(std::istream& in, const std::string& name) {
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error(fmt::format("cannot read OBJ file '{}': read error", name));
    return std::move(parse_text(text, name, false).parts.front().mesh);
}

MeshData load_obj(const std::string& path) {
    const std::string text = read_file_bytes(path, "OBJ");
    return std::move(parse_text(text, path, false).parts.front().mesh);
}

ObjScene parse_obj_scene(std::string_view text, const std::string& name) {
    return parse_text(text, name, true);
}

ObjScene load_obj_scene(const std::string& path) {
    const std::string text = read_file_bytes(path, "OBJ");
    return parse_text(text, path, true);
}

}  // namespace glint
