#include <glint/core/error.h>
#include <glint/scene/import/file_bytes.h>
#include <glint/scene/import/ply.h>

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace glint {
namespace {

enum class Scalar { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

size_t size_of(Scalar s) {
    switch (s) {
        case Scalar::kInt8:
        case Scalar::kUint8:
            return 1;
        case Scalar::kInt16:
        case Scalar::kUint16:
            return 2;
        case Scalar::kInt32:
        case Scalar::kUint32:
        case Scalar::kFloat32:
            return 4;
        case Scalar::kFloat64:
            return 8;
    }
    return 0;
}

bool is_integer(Scalar s) {
    return s != Scalar::kFloat32 && s != Scalar::kFloat64;
}

// Both spellings the format allows: the original names and the sized ones.
bool parse_scalar(std::string_view name, Scalar& s) {
    static constexpr std::pair<const char*, Scalar> kNames[] = {
        {"char", Scalar::kInt8},       {"int8", Scalar::kInt8},       {"uchar", Scalar::kUint8},
        {"uint8", Scalar::kUint8},     {"short", Scalar::kInt16},     {"int16", Scalar::kInt16},
        {"ushort", Scalar::kUint16},   {"uint16", Scalar::kUint16},   {"int", Scalar::kInt32},
        {"int32", Scalar::kInt32},     {"uint", Scalar::kUint32},     {"uint32", Scalar::kUint32},
        {"float", Scalar::kFloat32},   {"float32", Scalar::kFloat32}, {"double", Scalar::kFloat64},
        {"float64", Scalar::kFloat64},
    };
    for (const auto& [text, scalar] : kNames) {
        if (name == text) {
            s = scalar;
            return true;
        }
    }
    return false;
}

// What a vertex property means to glint.
enum class Role { kNone, kX, kY, kZ, kNx, kNy, kNz, kU, kV, kRed, kGreen, kBlue };

Role role_of(std::string_view name) {
    static constexpr std::pair<const char*, Role> kRoles[] = {
        {"x", Role::kX},         {"y", Role::kY},         {"z", Role::kZ},
        {"nx", Role::kNx},       {"ny", Role::kNy},       {"nz", Role::kNz},
        {"u", Role::kU},         {"v", Role::kV},         {"s", Role::kU},
        {"t", Role::kV},         {"texture_u", Role::kU}, {"texture_v", Role::kV},
        {"texture_s", Role::kU}, {"texture_t", Role::kV}, {"red", Role::kRed},
        {"green", Role::kGreen}, {"blue", Role::kBlue},
    };
    for (const auto& [text, role] : kRoles) {
        if (name == text) return role;
    }
    return Role::kNone;
}

struct Property {
    std::string name;
    Scalar type = Scalar::kFloat32;  // of the items, for a list
    bool list = false;
    Scalar count_type = Scalar::kUint8;
    Role role = Role::kNone;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

enum class Format { kAscii, kLittleEndian, kBigEndian };

std::string_view next_word(std::string_view& rest) {
    size_t begin = 0;
    while (begin < rest.size() && (rest[begin] == ' ' || rest[begin] == '\t')) ++begin;
    size_t end = begin;
    while (end < rest.size() && rest[end] != ' ' && rest[end] != '\t') ++end;
    const std::string_view word = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return word;
}

class PlyReader {
public:
    PlyReader(std::string_view bytes, std::string name) : m_bytes(bytes), m_name(std::move(name)) {}

    PlyMesh read() {
        read_header();
        for (size_t e = 0; e < m_elements.size(); ++e) read_element(m_elements[e]);
        return finish();
    }

private:
    [[noreturn]] void fail_at_line(uint64_t line, const std::string& what) const {
        throw Error(fmt::format("{}:{}: {}", m_name, line, what));
    }

    // Where the body reader stands: the line of ASCII text, the byte offset of binary data.
    [[noreturn]] void fail(const std::string& what) const {
        if (m_format == Format::kAscii) fail_at_line(m_line, what);
        throw Error(fmt::format("{}: byte {}: {}", m_name, m_pos, what));
    }

    void read_header() {
        uint64_t line_number = 0;
        bool has_format = false;
        auto next_line = [&]() -> std::string_view {
            if (m_pos >= m_bytes.size()) {
                fail_at_line(line_number + 1,
                             line_number == 0 ? "the file is empty (expected a PLY header)"
                                              : "the header has no 'end_header' line (truncated?)");
            }
            const size_t end = m_bytes.find('\n', m_pos);
            std::string_view line = m_bytes.substr(
                m_pos, (end == std::string_view::npos ? m_bytes.size() : end) - m_pos);
            m_pos = end == std::string_view::npos ? m_bytes.size() : end + 1;
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            ++line_number;
            return line;
        };
        if (next_line() != "ply") fail_at_line(1, "not a PLY file: the first line must be 'ply'");
        for (;;) {
            std::string_view rest = next_line();
            const std::string_view keyword = next_word(rest);
            if (keyword == "end_header") break;
            if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
            if (keyword == "format") {
                const std::string_view format = next_word(rest);
                const std::string_view version = next_word(rest);
                if (format == "ascii")
                    m_format = Format::kAscii;
                else if (format == "binary_little_endian")
                    m_format = Format::kLittleEndian;
                else if (format == "binary_big_endian")
                    m_format = Format::kBigEndian;
                else
                    fail_at_line(line_number,
                                 fmt::format("unknown format '{}' (expected ascii, "
                                             "binary_little_endian or binary_big_endian)",
                                             format));
                if (version != "1.0")
                    fail_at_line(line_number, fmt::format("unknown PLY version '{}'", version));
                has_format = true;
            } else if (keyword == "element") {
                Element element;
                element.name = std::string(next_word(rest));
                const std::string_view count = next_word(rest);
                const auto [ptr, ec] =
                    std::from_chars(count.data(), count.data() + count.size(), element.count);
                if (element.name.empty() || ec != std::errc() ||
                    ptr != count.data() + count.size()) {
                    fail_at_line(line_number, "expected 'element NAME COUNT'");
                }
                m_elements.push_back(std::move(element));
            } else if (keyword == "property") {
                if (m_elements.empty())
                    fail_at_line(line_number, "a property before any 'element'");
                Property property;
                std::string_view type = next_word(rest);
                if (type == "list") {
                    property.list = true;
                    const std::string_view count_type = next_word(rest);
                    if (!parse_scalar(count_type, property.count_type) ||
                        !is_integer(property.count_type)) {
                        fail_at_line(line_number,
                                     fmt::format("a list's count type must be an integer type, "
                                                 "not '{}'",
                                                 count_type));
                    }
                    type = next_word(rest);
                }
                if (!parse_scalar(type, property.type))
                    fail_at_line(line_number, fmt::format("unknown property type '{}'", type));
                property.name = std::string(next_word(rest));
                if (property.name.empty()) fail_at_line(line_number, "a property needs a name");
                Element& element = m_elements.back();
                if (element.name == "vertex" && !property.list)
                    property.role = role_of(property.name);
                if (element.name == "face" && property.list &&
                    (property.name == "vertex_indices" || property.name == "vertex_index")) {
                    if (!is_integer(property.type)) {
                        fail_at_line(line_number,
                                     fmt::format("face indices must be of an integer type, not "
                                                 "'{}'",
                                                 type));
                    }
                    m_face_list = true;
                }
                element.properties.push_back(std::move(property));
            } else {
                fail_at_line(line_number, fmt::format("unknown header keyword '{}'", keyword));
            }
        }
        if (!has_format) fail_at_line(2, "the header has no 'format' line");
        m_line = line_number + 1;
    }

    // Binary data: a scalar read at the cursor, in the file's byte order.
    template <typename T>
    T load() {
        if (m_bytes.size() - m_pos < sizeof(T)) truncated();
        T value;
        std::memcpy(&value, m_bytes.data() + m_pos, sizeof(T));
        m_pos += sizeof(T);
        const bool file_is_little = m_format == Format::kLittleEndian;
        if constexpr (sizeof(T) > 1) {
            if (file_is_little != (std::endian::native == std::endian::little)) {
                unsigned char b[sizeof(T)];
                std::memcpy(b, &value, sizeof(T));
                std::reverse(b, b + sizeof(T));
                std::memcpy(&value, b, sizeof(T));
            }
        }
        return value;
    }

    // ASCII data: the next whitespace-separated token, counting lines.
    std::string_view token() {
        while (m_pos < m_bytes.size()) {
            const char c = m_bytes[m_pos];
            if (c == '\n') {
                ++m_line;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                break;
            }
            ++m_pos;
        }
        if (m_pos >= m_bytes.size()) truncated();
        const size_t begin = m_pos;
        while (m_pos < m_bytes.size() && m_bytes[m_pos] != ' ' && m_bytes[m_pos] != '\t' &&
               m_bytes[m_pos] != '\r' && m_bytes[m_pos] != '\n')
            ++m_pos;
        return m_bytes.substr(begin, m_pos - begin);
    }

    [[noreturn]] void truncated() const {
        fail(fmt::format("the file ends inside element '{}' {} of {} (truncated?)", m_element->name,
                         m_item, m_element->count));
    }

    double real(Scalar type) {
        if (m_format == Format::kAscii) {
            std::string_view text = token();
            if (!text.empty() && text.front() == '+') text.remove_prefix(1);
            double value = 0.0;
            const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (ec != std::errc() || ptr != text.data() + text.size())
                fail(fmt::format("'{}' is not a number", text));
            return value;
        }
        switch (type) {
            case Scalar::kInt8:
                return load<int8_t>();
            case Scalar::kUint8:
                return load<uint8_t>();
            case Scalar::kInt16:
                return load<int16_t>();
            case Scalar::kUint16:
                return load<uint16_t>();
            case Scalar::kInt32:
                return load<int32_t>();
            case Scalar::kUint32:
                return load<uint32_t>();
            case Scalar::kFloat32:
                return load<float>();
            case Scalar::kFloat64:
                return load<double>();
        }
        return 0.0;
    }

    int64_t integer(Scalar type) {
        if (m_format == Format::kAscii) {
            const std::string_view text = token();
            int64_t value = 0;
            const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (ec != std::errc() || ptr != text.data() + text.size())
                fail(fmt::format("'{}' is not an integer", text));
            return value;
        }
        switch (type) {
            case Scalar::kInt8:
                return load<int8_t>();
            case Scalar::kUint8:
                return load<uint8_t>();
            case Scalar::kInt16:
                return load<int16_t>();
            case Scalar::kUint16:
                return load<uint16_t>();
            case Scalar::kInt32:
                return load<int32_t>();
            case Scalar::kUint32:
                return load<uint32_t>();
            default:
                break;
        }
        fail("expected an integer");  // excluded by the header checks
    }

    // A list's item count, checked so that a garbage count is an error, not a huge loop.
    uint64_t list_count(const Property& p) {
        const int64_t n = integer(p.count_type);
        if (n < 0) fail(fmt::format("list '{}' has a negative length {}", p.name, n));
        const size_t least_bytes = m_format == Format::kAscii ? 2 : size_of(p.type);
        if (static_cast<uint64_t>(n) > (m_bytes.size() - m_pos) / least_bytes + 1) truncated();
        return static_cast<uint64_t>(n);
    }

    void skip(const Property& p) {
        if (!p.list) {
            real(p.type);
            return;
        }
        const uint64_t n = list_count(p);
        if (m_format != Format::kAscii) {
            const uint64_t bytes = n * size_of(p.type);
            if (m_bytes.size() - m_pos < bytes) truncated();
            m_pos += bytes;
            return;
        }
        for (uint64_t i = 0; i < n; ++i) real(p.type);
    }

    void read_element(const Element& element) {
        m_element = &element;
        m_item = 0;
        if (element.properties.empty()) return;
        // Each item takes at least a byte per property (a digit, in ASCII, or a list count):
        // a count beyond that is a lie, refused before anything is allocated for it.
        const uint64_t remaining = m_bytes.size() - m_pos;
        uint64_t least = 0;
        for (const Property& p : element.properties)
            least +=
                m_format == Format::kAscii ? 2 : (p.list ? size_of(p.count_type) : size_of(p.type));
        if (element.count > remaining / std::max<uint64_t>(least, 1) + 1) {
            fail(
                fmt::format("element '{}' claims {} items, more than the {} bytes left can hold "
                            "(truncated?)",
                            element.name, element.count, remaining));
        }
        if (element.name == "vertex")
            read_vertices(element);
        else if (element.name == "face" && m_face_list)
            read_faces(element);
        else
            for (m_item = 0; m_item < element.count; ++m_item)
                for (const Property& p : element.properties) skip(p);
    }

    void read_vertices(const Element& element) {
        if (m_has_vertices) fail("a second 'vertex' element");
        m_has_vertices = true;
        bool has[12] = {};
        for (const Property& p : element.properties) has[static_cast<int>(p.role)] = true;
        if (!has[int(Role::kX)] || !has[int(Role::kY)] || !has[int(Role::kZ)])
            fail("element 'vertex' needs properties x, y and z");
        if (element.count > std::numeric_limits<uint32_t>::max())
            fail(fmt::format("{} vertices: glint's meshes hold at most 2^32 - 1", element.count));
        const bool normals = has[int(Role::kNx)] && has[int(Role::kNy)] && has[int(Role::kNz)];
        const bool uvs = has[int(Role::kU)] && has[int(Role::kV)];
        const bool colors = has[int(Role::kRed)] && has[int(Role::kGreen)] && has[int(Role::kBlue)];
        MeshData& mesh = m_result.mesh;
        mesh.positions.resize(element.count);
        if (normals) mesh.normals.resize(element.count);
        if (uvs) mesh.uvs.resize(element.count);
        if (colors) m_result.colors.resize(element.count);
        for (m_item = 0; m_item < element.count; ++m_item) {
            float values[12] = {};
            for (const Property& p : element.properties) {
                if (p.role == Role::kNone || p.list) {
                    skip(p);
                    continue;
                }
                double value = real(p.type);
                if (!(std::abs(value) <= std::numeric_limits<float>::max())) {
                    fail(fmt::format("vertex {}: '{}' = {} is not a finite float", m_item, p.name,
                                     value));
                }
                // Integer colours span their type's range: 255 is full intensity in a uchar.
                if (p.role >= Role::kRed && is_integer(p.type))
                    value /= static_cast<double>((uint64_t{1} << (8 * size_of(p.type))) - 1);
                values[static_cast<int>(p.role)] = static_cast<float>(value);
            }
            const size_t i = m_item;
            mesh.positions[i] = {values[int(Role::kX)], values[int(Role::kY)],
                                 values[int(Role::kZ)]};
            if (normals)
                mesh.normals[i] = {values[int(Role::kNx)], values[int(Role::kNy)],
                                   values[int(Role::kNz)]};
            if (uvs) mesh.uvs[i] = {values[int(Role::kU)], values[int(Role::kV)]};
            if (colors)
                m_result.colors[i] = {values[int(Role::kRed)], values[int(Role::kGreen)],
                                      values[int(Role::kBlue)]};
        }
    }

    void read_faces(const Element& element) {
        std::vector<uint32_t>& indices = m_result.mesh.indices;
        indices.reserve(std::min<uint64_t>(element.count, uint64_t{1} << 26) * 3);
        std::vector<uint32_t> face;
        for (m_item = 0; m_item < element.count; ++m_item) {
            for (const Property& p : element.properties) {
                if (!p.list || (p.name != "vertex_indices" && p.name != "vertex_index")) {
                    skip(p);
                    continue;
                }
                const uint64_t n = list_count(p);
                if (n < 3) fail(fmt::format("face {} has {} corners; a face needs 3", m_item, n));
                face.clear();
                for (uint64_t k = 0; k < n; ++k) {
                    const int64_t index = integer(p.type);
                    if (index < 0 || index >= std::numeric_limits<uint32_t>::max())
                        fail(fmt::format("face {} refers to vertex {}", m_item, index));
                    face.push_back(static_cast<uint32_t>(index));
                }
                // A fan around the first corner, as for OBJ: linear in the corner count.
                for (size_t k = 1; k + 1 < face.size(); ++k) {
                    indices.push_back(face[0]);
                    indices.push_back(face[k]);
                    indices.push_back(face[k + 1]);
                }
            }
        }
    }

    PlyMesh finish() {
        MeshData& mesh = m_result.mesh;
        if (!m_has_vertices)
            throw Error(fmt::format("PLY file '{}' has no 'vertex' element", m_name));
        if (mesh.indices.empty())
            throw Error(fmt::format("PLY file '{}' contains no faces", m_name));
        const size_t count = mesh.positions.size();
        for (size_t i = 0; i < mesh.indices.size(); ++i) {
            if (mesh.indices[i] >= count) {
                throw Error(
                    fmt::format("PLY file '{}': a face refers to vertex {}, but the file "
                                "has {} vertices",
                                m_name, mesh.indices[i], count));
            }
        }
        return std::move(m_result);
    }

    std::string_view m_bytes;
    std::string m_name;
    Format m_format = Format::kAscii;
    std::vector<Element> m_elements;
    bool m_face_list = false;
    size_t m_pos = 0;
    uint64_t m_line = 0;
    const Element* m_element = nullptr;  // the element being read, for messages
    uint64_t m_item = 0;
    bool m_has_vertices = false;
    PlyMesh m_result;
};

}  // namespace

PlyMesh parse_ply(std::string_view bytes, const std::string& name) {
    return PlyReader(bytes, name).read();
}

PlyMesh load_ply(const std::string& path) {
    const std::string bytes = read_file_bytes(path, "PLY");
    return parse_ply(bytes, path);
}

}  // namespace glint
