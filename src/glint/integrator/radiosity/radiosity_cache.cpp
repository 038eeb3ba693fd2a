#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/core/rng.h>
#include <glint/integrator/radiosity/radiosity_cache.h>

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace glint {
namespace {

// The file: magic, version, the mesh's fingerprint, the counts, the ambient term, the
// vertices, elements and patches' unshot radiosity, and a checksum of everything before it.
// Little-endian, as the machines glint runs on.
constexpr char kMagic[8] = {'G', 'L', 'I', 'N', 'T', 'R', 'A', 'D'};
constexpr uint32_t kVersion = 1;
constexpr size_t kHeaderBytes = 8 + 4 + 8 + 8 + 8 + 8 + 12;
constexpr size_t kVertexBytes = 4 * (3 + 3 + 3 + 6 + 6);
constexpr size_t kElementBytes = 4 * (3 + 6 + 1 + 1 + 1);
constexpr size_t kPatchBytes = 4 * 12;

uint64_t checksum(const std::vector<char>& bytes, size_t count) {
    uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a
    for (size_t i = 0; i < count; ++i) {
        h ^= static_cast<unsigned char>(bytes[i]);
        h *= 0x100000001b3ULL;
    }
    return h;
}

class Writer {
public:
    template <typename T>
    void put(T value) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        bytes.insert(bytes.end(), raw, raw + sizeof(T));
    }
    void put(const Vec3& v) {
        put(v.x);
        put(v.y);
        put(v.z);
    }
    void put(const Vec2& v) {
        put(v.x);
        put(v.y);
    }
    void put(const Spectrum& s) {
        for (const float v : s.stored()) put(v);
    }
    std::vector<char> bytes;
};

class Reader {
public:
    Reader(const std::vector<char>& bytes, const std::string& path)
        : m_bytes(bytes), m_path(path) {}
    template <typename T>
    T get() {
        if (m_at + sizeof(T) > m_bytes.size()) fail("it is cut short");
        T value;
        std::memcpy(&value, m_bytes.data() + m_at, sizeof(T));
        m_at += sizeof(T);
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value)) fail("it is damaged");
        }
        return value;
    }
    Vec3 vec3() {
        const float x = get<float>(), y = get<float>(), z = get<float>();
        return Vec3(x, y, z);
    }
    Vec2 vec2() {
        const float x = get<float>(), y = get<float>();
        return Vec2(x, y);
    }
    Spectrum spectrum() {
        std::array<float, Spectrum::kStoredValues> values;
        for (float& v : values) v = get<float>();
        return Spectrum::from_stored(values);
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(fmt::format("{}: not a usable radiosity cache: {}; delete it to solve again",
                                m_path, why));
    }

private:
    const std::vector<char>& m_bytes;
    const std::string& m_path;
    size_t m_at = 0;
};

}  // namespace

void save_radiosity_cache(const RadiosityMesh& mesh, const std::string& path) {
    Writer w;
    w.bytes.insert(w.bytes.end(), kMagic, kMagic + 8);
    w.put(kVersion);
    w.put(mesh.fingerprint_at_build);
    w.put(static_cast<uint64_t>(mesh.vertices.size()));
    w.put(static_cast<uint64_t>(mesh.elements.size()));
    w.put(static_cast<uint64_t>(mesh.patches.size()));
    w.put(mesh.ambient);
    for (const RadiosityVertex& v : mesh.vertices) {
        w.put(v.p);
        w.put(v.n);
        w.put(v.rho);
        for (int s = 0; s < 2; ++s) w.put(v.b[s]);
        for (int s = 0; s < 2; ++s) w.put(v.b_direct[s]);
    }
    for (const RadiosityElement& e : mesh.elements) {
        for (uint32_t v : e.v) w.put(v);
        for (const Vec2& uv : e.uv) w.put(uv);
        w.put(e.first_child);
        w.put(e.patch);
        w.put(e.area);
    }
    for (const RadiosityPatch& p : mesh.patches) {
        for (int s = 0; s < 2; ++s) w.put(p.unshot[s]);
        for (int s = 0; s < 2; ++s) w.put(p.unshot_emission[s]);
    }
    w.put(checksum(w.bytes, w.bytes.size()));

    write_file_atomically(path, std::string(w.bytes.begin(), w.bytes.end()), "the radiosity cache");
}

void load_radiosity_cache(RadiosityMesh& mesh, const std::string& path) {
    const std::string text = read_regular_file(path, "the radiosity cache");
    const std::vector<char> bytes(text.begin(), text.end());
    Reader r(bytes, path);
    if (bytes.size() < kHeaderBytes + 8 || std::memcmp(bytes.data(), kMagic, 8) != 0)
        r.fail("it does not start as one");
    const size_t body = bytes.size() - 8;
    uint64_t stored;
    std::memcpy(&stored, bytes.data() + body, 8);
    if (stored != checksum(bytes, body)) r.fail("its checksum does not match (damaged file)");
    for (int i = 0; i < 8; ++i) r.get<char>();
    if (r.get<uint32_t>() != kVersion) r.fail("another version of glint wrote it");
    if (r.get<uint64_t>() != mesh.fingerprint_at_build) {
        throw Error(fmt::format(
            "{}: the radiosity cache was solved for another scene (other geometry, materials, "
            "lights or radiosity mesh settings); delete it to solve again",
            path));
    }
    const uint64_t vertices = r.get<uint64_t>();
    const uint64_t elements = r.get<uint64_t>();
    const uint64_t patches = r.get<uint64_t>();
    if (patches != mesh.patches.size() || vertices < mesh.vertices.size() ||
        elements < mesh.elements.size())
        r.fail("it is damaged");
    // Checked before anything is allocated: counts a damaged file makes up cannot fit.
    const size_t available = body - kHeaderBytes;
    if (vertices > available / kVertexBytes || elements > available / kElementBytes ||
        vertices * kVertexBytes + elements * kElementBytes + patches * kPatchBytes != available)
        r.fail("it is cut short or damaged");
    const Spectrum ambient = r.spectrum();

    std::vector<RadiosityVertex> vs(vertices);
    for (RadiosityVertex& v : vs) {
        v.p = r.vec3();
        v.n = r.vec3();
        v.rho = r.spectrum();
        for (int s = 0; s < 2; ++s) v.b[s] = r.spectrum();
        for (int s = 0; s < 2; ++s) v.b_direct[s] = r.spectrum();
    }
    std::vector<RadiosityElement> es(elements);
    for (size_t i = 0; i < es.size(); ++i) {
        RadiosityElement& e = es[i];
        for (uint32_t& v : e.v) {
            v = r.get<uint32_t>();
            if (v >= vertices) r.fail("it is damaged");
        }
        for (Vec2& uv : e.uv) uv = r.vec2();
        e.first_child = r.get<int32_t>();
        // Children come after their parent: the lookup's descent then always ends.
        if (e.first_child != -1 && (e.first_child <= static_cast<int64_t>(i) ||
                                    static_cast<uint64_t>(e.first_child) + 4 > elements))
            r.fail("it is damaged");
        e.patch = r.get<uint32_t>();
        if (e.patch >= patches) r.fail("it is damaged");
        e.area = r.get<float>();
    }
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        if (es[i].patch != i || es[i].uv[0] != mesh.elements[i].uv[0]) r.fail("it is damaged");
    }
    std::vector<RadiosityPatch> ps = mesh.patches;
    for (RadiosityPatch& p : ps) {
        for (int s = 0; s < 2; ++s) p.unshot[s] = r.spectrum();
        for (int s = 0; s < 2; ++s) p.unshot_emission[s] = r.spectrum();
    }
    mesh.vertices = std::move(vs);
    mesh.elements = std::move(es);
    mesh.patches = std::move(ps);
    mesh.ambient = ambient;
}

}  // namespace glint
