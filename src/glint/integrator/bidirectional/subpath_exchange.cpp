#include <glint/core/error.h>
#include <glint/integrator/bidirectional/subpath_exchange.h>
#include <glint/material/material.h>

#include <cstring>
#include <type_traits>

namespace glint {
namespace {

// The vertex's surface travels as its bytes, its two pointers replaced by indices.
static_assert(std::is_trivially_copyable_v<SurfaceInteraction>);
static_assert(std::is_trivially_copyable_v<Splat>);
static_assert(std::is_trivially_copyable_v<Spectrum>);

template <typename T>
void put(std::vector<uint8_t>& out, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

template <typename T>
T take(const std::vector<uint8_t>& bytes, size_t& at) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (bytes.size() - at < sizeof(T) || at > bytes.size())
        throw Error("exchanged light subpaths end early (a rank sent a damaged message)");
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

struct VertexHeader {
    uint8_t kind;
    uint8_t delta;
    uint8_t infinite;
    uint8_t has_bsdf;
    int32_t light;       // Light::index, -1 for none
    int32_t material;    // into Scene::materials(), -1 for none
    int32_t area_light;  // Light::index of si.area_light, -1 for none
    float pdf_fwd, pdf_rev;
    Vec3 p, ng, w_sky;
    Spectrum beta;  // as it is held (every wavelength in spectral mode)
    Spectrum r_u;
    int32_t medium;  // into Scene::media(), -1 for none
    float sigma_t;
};

int32_t index_of(const Light* light) {
    return light ? static_cast<int32_t>(light->index()) : -1;
}

}  // namespace

SubpathCodec::SubpathCodec(const Scene& scene) : m_scene(scene) {
    const auto& materials = scene.materials();
    for (size_t i = 0; i < materials.size(); ++i)
        m_material_index.emplace(materials[i].get(), static_cast<int32_t>(i));
}

int32_t SubpathCodec::index_of_medium(const Medium* medium) const {
    if (!medium) return -1;
    const auto& media = m_scene.media();
    for (size_t i = 0; i < media.size(); ++i) {
        if (media[i].get() == medium) return static_cast<int32_t>(i);
    }
    throw Error("a light subpath met a medium the scene does not list");
}

int32_t SubpathCodec::index_of_material(const Material* material) const {
    if (!material) return -1;
    const auto it = m_material_index.find(material);
    if (it == m_material_index.end())
        throw Error("a light subpath met a material the scene does not list");
    return it->second;
}

void SubpathCodec::write(const std::vector<PathVertex>& path, float time,
                         std::vector<uint8_t>& out) const {
    put(out, static_cast<uint32_t>(path.size()));
    put(out, time);
    for (const PathVertex& v : path) {
        VertexHeader h{};
        h.kind = static_cast<uint8_t>(v.kind);
        h.delta = v.delta;
        h.infinite = v.infinite;
        h.has_bsdf = v.bsdf != nullptr;
        h.light = index_of(v.light);
        h.material = index_of_material(v.si.material);
        h.area_light = index_of(v.si.area_light);
        h.pdf_fwd = v.pdf_fwd;
        h.pdf_rev = v.pdf_rev;
        h.p = v.p;
        h.ng = v.ng;
        h.w_sky = v.w_sky;
        h.beta = v.beta;
        h.r_u = v.r_u;
        h.sigma_t = v.sigma_t;
        h.medium = index_of_medium(v.medium);
        put(out, h);
        SurfaceInteraction si = v.si;
        si.material = nullptr;
        si.area_light = nullptr;
        put(out, si);
    }
}

void SubpathCodec::read(const std::vector<uint8_t>& bytes, size_t& at,
                        std::vector<PathVertex>& path, float& time, Arena& arena) const {
    const auto count = take<uint32_t>(bytes, at);
    time = take<float>(bytes, at);
    path.clear();
    path.reserve(count);
    const auto& lights = m_scene.lights();
    const auto& materials = m_scene.materials();
    const auto light_at = [&](int32_t i) -> const Light* {
        if (i < 0) return nullptr;
        if (static_cast<size_t>(i) >= lights.size())
            throw Error("exchanged light subpaths name a light the scene does not have");
        return lights[static_cast<size_t>(i)].get();
    };
    for (uint32_t k = 0; k < count; ++k) {
        const auto h = take<VertexHeader>(bytes, at);
        PathVertex& v = path.emplace_back();
        v.kind = static_cast<PathVertex::Kind>(h.kind);
        v.delta = h.delta != 0;
        v.infinite = h.infinite != 0;
        v.light = light_at(h.light);
        v.pdf_fwd = h.pdf_fwd;
        v.pdf_rev = h.pdf_rev;
        v.p = h.p;
        v.ng = h.ng;
        v.w_sky = h.w_sky;
        v.beta = h.beta;
        v.r_u = h.r_u;
        v.sigma_t = h.sigma_t;
        if (h.kind > static_cast<uint8_t>(PathVertex::Kind::kMedium))
            throw Error("exchanged light subpaths hold a vertex of no known kind");
        if (h.medium >= 0) {
            if (static_cast<size_t>(h.medium) >= m_scene.media().size())
                throw Error("exchanged light subpaths name a medium the scene does not have");
            v.medium = m_scene.media()[static_cast<size_t>(h.medium)].get();
        }
        v.si = take<SurfaceInteraction>(bytes, at);
        if (h.material >= 0) {
            if (static_cast<size_t>(h.material) >= materials.size())
                throw Error("exchanged light subpaths name a material the scene does not have");
            v.si.material = materials[static_cast<size_t>(h.material)].get();
        }
        v.si.area_light = light_at(h.area_light);
        // The shading frame came final (bump applied): the BSDF alone is made again.
        if (h.has_bsdf && v.si.material) v.bsdf = v.si.material->bsdf(v.si, arena);
    }
}

void SubpathCodec::write_splats(const std::vector<Splat>& splats, std::vector<uint8_t>& out) {
    put(out, static_cast<uint64_t>(splats.size()));
    for (const Splat& s : splats) put(out, s);
}

void SubpathCodec::read_splats(const std::vector<uint8_t>& bytes, size_t& at,
                               std::vector<Splat>& splats) {
    const auto count = take<uint64_t>(bytes, at);
    if (count > (bytes.size() - at) / sizeof(Splat))
        throw Error("exchanged splats end early (a rank sent a damaged message)");
    for (uint64_t i = 0; i < count; ++i) splats.push_back(take<Splat>(bytes, at));
}

}  // namespace glint
