// Writes examples/gltf/: a small glTF 2.0 scene of glint's own making (nothing downloaded),
// scene.gltf with its buffer scene.bin and four PNG textures. A textured floor, a sphere
// with a metallic-roughness texture, a glass sphere (KHR_materials_transmission, _ior)
// sharing the sphere's vertex data, a normal-mapped cube placed three times (instanced), an
// emissive panel (KHR_materials_emissive_strength), a camera, a sun and a point light
// (KHR_lights_punctual). Run by scripts/make-example-gltf.sh; the output is committed.
#include <glint/film/image.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// The stored values as they are (no sRGB encoding on top: `rgb` is already what the file
// must hold).
void write_png(const std::string& path, int n, const std::vector<uint8_t>& rgb) {
    glint::Image image = glint::make_image(n, n, {"R", "G", "B"});
    for (size_t i = 0; i < rgb.size(); ++i) image.pixels[i] = rgb[i] / 255.0f;
    glint::WriteOptions raw;
    raw.srgb = false;
    glint::write_image(path, image, raw);
}

// Stored values (sRGB-encoded for the colour maps, linear for the data maps), row 0 at the
// top as PNG and glTF have it.
std::vector<uint8_t> image(int n, auto&& pixel) {
    std::vector<uint8_t> rgb(static_cast<size_t>(n) * n * 3);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const auto [r, g, b] = pixel((x + 0.5) / n, (y + 0.5) / n);
            uint8_t* p = &rgb[(static_cast<size_t>(y) * n + x) * 3];
            p[0] = static_cast<uint8_t>(std::lround(std::clamp(r, 0.0, 1.0) * 255));
            p[1] = static_cast<uint8_t>(std::lround(std::clamp(g, 0.0, 1.0) * 255));
            p[2] = static_cast<uint8_t>(std::lround(std::clamp(b, 0.0, 1.0) * 255));
        }
    }
    return rgb;
}

struct Rgb {
    double r, g, b;
};

void write_textures(const std::filesystem::path& dir) {
    // Floor: warm and cool tiles with a thin grout line.
    write_png((dir / "floor.png").string(), 256, image(256, [](double s, double t) {
                  const int cell = (static_cast<int>(s * 4) + static_cast<int>(t * 4)) % 2;
                  const bool grout = std::fmod(s * 4, 1.0) < 0.03 || std::fmod(t * 4, 1.0) < 0.03;
                  if (grout) return Rgb{0.25, 0.25, 0.25};
                  return cell ? Rgb{0.85, 0.78, 0.66} : Rgb{0.45, 0.55, 0.65};
              }));
    // Cube: a hue ramp in 4 x 4 squares with a white mark at uv (0, 0).
    write_png((dir / "grid.png").string(), 256, image(256, [](double s, double t) {
                  const int cx = static_cast<int>(s * 4), cy = static_cast<int>((1 - t) * 4);
                  const double h = (cx + 4 * cy) / 16.0;
                  Rgb c{0.5 + 0.45 * std::cos(2 * kPi * h),
                        0.5 + 0.45 * std::cos(2 * kPi * (h - 1.0 / 3)),
                        0.5 + 0.45 * std::cos(2 * kPi * (h - 2.0 / 3))};
                  if (cx == 0 && cy == 0 && s > 0.08 && s < 0.17 && t > 0.83 && t < 0.92)
                      c = {1, 1, 1};
                  return c;
              }));
    // Sphere: bands that alternate metal (B = 1) and dielectric, roughness (G) rising
    // along the bands.
    write_png((dir / "metal-rough.png").string(), 256, image(256, [](double s, double t) {
                  const bool metal = static_cast<int>(t * 8) % 2 == 0;
                  return Rgb{0.0, 0.1 + 0.6 * s, metal ? 1.0 : 0.0};
              }));
    // Cube: rounded bumps, as a tangent-space normal map (OpenGL convention, +y up).
    write_png((dir / "bumps-normal.png").string(), 256, image(256, [](double s, double t) {
                  const double u = std::fmod(s * 4, 1.0) - 0.5, v = 0.5 - std::fmod(t * 4, 1.0);
                  const double r2 = u * u + v * v;
                  double nx = 0, ny = 0, nz = 1;
                  if (r2 < 0.16) {
                      nx = u * 1.6;
                      ny = v * 1.6;
                      nz = std::sqrt(std::max(0.0, 1 - nx * nx - ny * ny));
                  }
                  return Rgb{0.5 + 0.5 * nx, 0.5 + 0.5 * ny, 0.5 + 0.5 * nz};
              }));
}

// The binary buffer: accessors appended one after another, each 4-byte aligned.
struct Buffer {
    std::string bytes;
    std::vector<std::string> views, accessors;

    int add(const void* data, size_t size, int count, const char* type, int component,
            const std::string& extra = "") {
        while (bytes.size() % 4) bytes += '\0';
        views.push_back(fmt::format(R"({{"buffer": 0, "byteOffset": {}, "byteLength": {}}})",
                                    bytes.size(), size));
        bytes.append(static_cast<const char*>(data), size);
        accessors.push_back(
            fmt::format(R"({{"bufferView": {}, "componentType": {}, "count": {}, "type": "{}"{}}})",
                        views.size() - 1, component, count, type, extra));
        return static_cast<int>(accessors.size()) - 1;
    }
};

struct Mesh {
    std::vector<float> p, n, uv;
    std::vector<uint16_t> index;
};

// Positions accessor with the min and max glTF asks of POSITION.
int add_mesh(Buffer& buffer, const Mesh& m, int* normal, int* uv, int* index) {
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (size_t i = 0; i < m.p.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], m.p[i]);
        hi[i % 3] = std::max(hi[i % 3], m.p[i]);
    }
    const int count = static_cast<int>(m.p.size() / 3);
    const int position = buffer.add(m.p.data(), m.p.size() * 4, count, "VEC3", 5126,
                                    fmt::format(R"(, "min": [{}, {}, {}], "max": [{}, {}, {}])",
                                                lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]));
    *normal = buffer.add(m.n.data(), m.n.size() * 4, count, "VEC3", 5126);
    *uv = buffer.add(m.uv.data(), m.uv.size() * 4, count, "VEC2", 5126);
    *index = buffer.add(m.index.data(), m.index.size() * 2, static_cast<int>(m.index.size()),
                        "SCALAR", 5123);
    return position;
}

Mesh quad(float half, float uv_repeat) {
    Mesh m;
    m.p = {-half, 0, half, half, 0, half, half, 0, -half, -half, 0, -half};
    m.n = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    m.uv = {0, uv_repeat, uv_repeat, uv_repeat, uv_repeat, 0, 0, 0};  // glTF: v = 0 at the top
    m.index = {0, 1, 2, 0, 2, 3};
    return m;
}

Mesh sphere(float radius, int rings, int segments) {
    Mesh m;
    for (int i = 0; i <= rings; ++i) {
        const double theta = kPi * i / rings;
        for (int j = 0; j <= segments; ++j) {
            const double phi = 2 * kPi * j / segments;
            const double x = std::sin(theta) * std::cos(phi), y = std::cos(theta),
                         z = -std::sin(theta) * std::sin(phi);
            m.p.insert(m.p.end(), {float(radius * x), float(radius * y), float(radius * z)});
            m.n.insert(m.n.end(), {float(x), float(y), float(z)});
            m.uv.insert(m.uv.end(), {float(double(j) / segments), float(double(i) / rings)});
        }
    }
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
            const auto a = static_cast<uint16_t>(i * (segments + 1) + j);
            const auto b = static_cast<uint16_t>(a + segments + 1);
            m.index.insert(m.index.end(), {a, b, static_cast<uint16_t>(b + 1)});
            m.index.insert(m.index.end(),
                           {a, static_cast<uint16_t>(b + 1), static_cast<uint16_t>(a + 1)});
        }
    }
    return m;
}

Mesh cube(float h) {
    Mesh m;
    const float faces[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& f : faces) {
        // Two tangent axes making (u, v, n) right-handed.
        const float n[3] = {f[0], f[1], f[2]};
        const float u[3] = {n[1] != 0 ? 1.0f : -n[2], 0.0f, n[1] != 0 ? 0.0f : n[0]};
        const float v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2],
                            n[0] * u[1] - n[1] * u[0]};
        const auto base = static_cast<uint16_t>(m.p.size() / 3);
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            for (int k = 0; k < 3; ++k) m.p.push_back(h * (n[k] + c[0] * u[k] + c[1] * v[k]));
            m.n.insert(m.n.end(), {n[0], n[1], n[2]});
            m.uv.insert(m.uv.end(), {0.5f * (c[0] + 1), 1 - 0.5f * (c[1] + 1)});
        }
        m.index.insert(m.index.end(),
                       {base, static_cast<uint16_t>(base + 1), static_cast<uint16_t>(base + 2),
                        base, static_cast<uint16_t>(base + 2), static_cast<uint16_t>(base + 3)});
    }
    return m;
}

std::string primitive(int position, int normal, int uv, int index, int material) {
    return fmt::format(R"({{"primitives": [{{"attributes": {{"POSITION": {}, "NORMAL": {}, )"
                       R"("TEXCOORD_0": {}}}, "indices": {}, "material": {}}}]}})",
                       position, normal, uv, index, material);
}

std::string join(const std::vector<std::string>& parts) {
    std::string out;
    for (size_t i = 0; i < parts.size(); ++i) out += (i ? ",\n    " : "    ") + parts[i];
    return out;
}

void write_scene(const std::filesystem::path& dir) {
    Buffer buffer;
    int n, uv, idx;
    std::vector<std::string> meshes;
    const int floor = add_mesh(buffer, quad(4, 3), &n, &uv, &idx);
    meshes.push_back(primitive(floor, n, uv, idx, 0));
    const int ball = add_mesh(buffer, sphere(0.6f, 24, 48), &n, &uv, &idx);
    meshes.push_back(primitive(ball, n, uv, idx, 1));
    meshes.push_back(primitive(ball, n, uv, idx, 2));  // the glass ball: same vertex data
    const int box = add_mesh(buffer, cube(0.3f), &n, &uv, &idx);
    meshes.push_back(primitive(box, n, uv, idx, 3));
    const int panel = add_mesh(buffer, quad(0.5f, 1), &n, &uv, &idx);
    meshes.push_back(primitive(panel, n, uv, idx, 4));

    const std::string json =
        fmt::format(R"({{
  "asset": {{"version": "2.0", "generator": "glint examples/gltf/make_gltf.cpp"}},
  "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_transmission", "KHR_materials_ior",
                     "KHR_materials_emissive_strength"],
  "scene": 0,
  "scenes": [{{"nodes": [0, 1, 2, 3, 7, 8, 9, 10]}}],
  "nodes": [
    {{"name": "floor", "mesh": 0}},
    {{"name": "metal ball", "mesh": 1, "translation": [-1.1, 0.6, -0.3]}},
    {{"name": "glass ball", "mesh": 2, "translation": [0.3, 0.6, 0.6]}},
    {{"name": "boxes", "translation": [1.4, 0, -0.6], "children": [4, 5, 6]}},
    {{"mesh": 3, "translation": [0, 0.3, 0], "rotation": [0, 0.2588190, 0, 0.9659258]}},
    {{"mesh": 3, "translation": [0.1, 0.9, 0.05], "rotation": [0, -0.1305262, 0, 0.9914449]}},
    {{"mesh": 3, "translation": [-0.5, 0.3, 0.9], "rotation": [0, 0.3826834, 0, 0.9238795],
      "scale": [0.8, 0.8, 0.8]}},
    {{"name": "lamp panel", "mesh": 4, "translation": [0, 2.8, -1.5],
      "rotation": [0.9238795, 0, 0, 0.3826834]}},
    {{"name": "camera", "camera": 0, "translation": [0, 1.6, 4.6],
      "rotation": [-0.1305262, 0, 0, 0.9914449]}},
    {{"name": "sun", "rotation": [-0.4304593, 0.3265056, 0.1958520, 0.8195975],
      "extensions": {{"KHR_lights_punctual": {{"light": 0}}}}}},
    {{"name": "bulb", "translation": [2, 2.2, 2],
      "extensions": {{"KHR_lights_punctual": {{"light": 1}}}}}}
  ],
  "cameras": [{{"type": "perspective", "perspective": {{"yfov": 0.6, "znear": 0.05}}}}],
  "extensions": {{"KHR_lights_punctual": {{"lights": [
    {{"type": "directional", "color": [1.0, 0.95, 0.85], "intensity": 1707.5}},
    {{"type": "point", "color": [1.0, 0.85, 0.7], "intensity": 4098}}]}}}},
  "meshes": [
{}
  ],
  "materials": [
    {{"name": "tiles", "pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}},
      "metallicFactor": 0, "roughnessFactor": 0.6}}}},
    {{"name": "banded metal", "pbrMetallicRoughness": {{"baseColorFactor": [0.95, 0.7, 0.35, 1],
      "metallicFactor": 1, "roughnessFactor": 1, "metallicRoughnessTexture": {{"index": 1}}}}}},
    {{"name": "glass", "pbrMetallicRoughness": {{"baseColorFactor": [1, 1, 1, 1],
      "metallicFactor": 0, "roughnessFactor": 0}},
      "extensions": {{"KHR_materials_transmission": {{"transmissionFactor": 1}},
                      "KHR_materials_ior": {{"ior": 1.5}}}}}},
    {{"name": "bumpy boxes", "pbrMetallicRoughness": {{"baseColorTexture": {{"index": 2}},
      "metallicFactor": 0, "roughnessFactor": 0.4}}, "normalTexture": {{"index": 3}}}},
    {{"name": "lamp", "pbrMetallicRoughness": {{"baseColorFactor": [0.1, 0.1, 0.1, 1]}},
      "emissiveFactor": [1, 0.9, 0.75],
      "extensions": {{"KHR_materials_emissive_strength": {{"emissiveStrength": 6}}}}}}
  ],
  "textures": [{{"source": 0}}, {{"source": 1}}, {{"source": 2}}, {{"source": 3}}],
  "images": [{{"uri": "floor.png"}}, {{"uri": "metal-rough.png"}}, {{"uri": "grid.png"}},
             {{"uri": "bumps-normal.png"}}],
  "buffers": [{{"uri": "scene.bin", "byteLength": {}}}],
  "bufferViews": [
{}
  ],
  "accessors": [
{}
  ]
}}
)",
                    join(meshes), buffer.bytes.size(), join(buffer.views), join(buffer.accessors));
    std::ofstream(dir / "scene.gltf", std::ios::binary) << json;
    std::ofstream(dir / "scene.bin", std::ios::binary) << buffer.bytes;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        write_textures(dir);
        write_scene(dir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
