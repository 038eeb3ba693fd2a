// Writes one torus, tessellated into about TRIANGLES triangles, as an OBJ (with uvs and
// normals), a binary PLY and a GLB, for bench/large_mesh.sh: large meshes made here, never
// downloaded. Usage: glint_bench_make_mesh OUT_DIR [TRIANGLES]
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Torus {
    std::vector<float> p, n, uv;  // 3, 3 and 2 per vertex
    std::vector<uint32_t> tri;    // 3 per triangle
};

// A torus of n x m quads (two triangles each) around the y axis; the seam repeats its
// vertices so that uvs run from 0 to 1.
Torus make_torus(int n, int m) {
    Torus t;
    const double kTau = 6.283185307179586;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= m; ++j) {
            const double a = kTau * i / n, b = kTau * j / m;
            const double nx = std::cos(b) * std::cos(a), ny = std::sin(b),
                         nz = std::cos(b) * std::sin(a);
            t.p.insert(t.p.end(), {float(std::cos(a) + 0.35 * nx), float(0.35 * ny),
                                   float(std::sin(a) + 0.35 * nz)});
            t.n.insert(t.n.end(), {float(nx), float(ny), float(nz)});
            t.uv.insert(t.uv.end(), {float(double(i) / n), float(double(j) / m)});
        }
    }
    auto id = [&](int i, int j) { return static_cast<uint32_t>(i * (m + 1) + j); };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < m; ++j) {
            t.tri.insert(t.tri.end(), {id(i, j), id(i, j + 1), id(i + 1, j + 1)});
            t.tri.insert(t.tri.end(), {id(i, j), id(i + 1, j + 1), id(i + 1, j)});
        }
    }
    return t;
}

void write_obj(const Torus& t, const std::string& path) {
    std::string out;
    const size_t vertices = t.p.size() / 3;
    for (size_t v = 0; v < vertices; ++v)
        out += fmt::format("v {:.6f} {:.6f} {:.6f}\n", t.p[3 * v], t.p[3 * v + 1], t.p[3 * v + 2]);
    for (size_t v = 0; v < vertices; ++v)
        out += fmt::format("vt {:.6f} {:.6f}\n", t.uv[2 * v], t.uv[2 * v + 1]);
    for (size_t v = 0; v < vertices; ++v)
        out += fmt::format("vn {:.6f} {:.6f} {:.6f}\n", t.n[3 * v], t.n[3 * v + 1], t.n[3 * v + 2]);
    for (size_t f = 0; f < t.tri.size(); f += 3) {
        const uint32_t a = t.tri[f] + 1, b = t.tri[f + 1] + 1, c = t.tri[f + 2] + 1;
        out += fmt::format("f {0}/{0}/{0} {1}/{1}/{1} {2}/{2}/{2}\n", a, b, c);
    }
    std::ofstream(path, std::ios::binary) << out;
}

template <typename T>
void put(std::string& out, T v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));  // little endian hosts
}

void write_ply(const Torus& t, const std::string& path) {
    const size_t vertices = t.p.size() / 3;
    std::string out = fmt::format(
        "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty float x\n"
        "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
        "property float nz\nproperty float u\nproperty float v\nelement face {}\n"
        "property list uchar uint vertex_indices\nend_header\n",
        vertices, t.tri.size() / 3);
    for (size_t v = 0; v < vertices; ++v) {
        for (int k = 0; k < 3; ++k) put(out, t.p[3 * v + k]);
        for (int k = 0; k < 3; ++k) put(out, t.n[3 * v + k]);
        for (int k = 0; k < 2; ++k) put(out, t.uv[2 * v + k]);
    }
    for (size_t f = 0; f < t.tri.size(); f += 3) {
        put<uint8_t>(out, 3);
        for (int k = 0; k < 3; ++k) put(out, t.tri[f + k]);
    }
    std::ofstream(path, std::ios::binary) << out;
}

void write_glb(const Torus& t, const std::string& path) {
    std::string bin;
    auto append = [&](const void* data, size_t bytes) {
        bin.append(static_cast<const char*>(data), bytes);
    };
    const size_t vertices = t.p.size() / 3;
    append(t.p.data(), t.p.size() * 4);
    append(t.n.data(), t.n.size() * 4);
    std::vector<float> uv = t.uv;
    for (size_t v = 0; v < vertices; ++v) uv[2 * v + 1] = 1.0f - uv[2 * v + 1];  // glTF: top = 0
    append(uv.data(), uv.size() * 4);
    append(t.tri.data(), t.tri.size() * 4);
    const size_t p_bytes = t.p.size() * 4, uv_bytes = uv.size() * 4, i_bytes = t.tri.size() * 4;
    std::string json = fmt::format(
        R"({{"asset": {{"version": "2.0", "generator": "glint bench/make_mesh"}},
"buffers": [{{"byteLength": {total}}}],
"bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": {p}}},
 {{"buffer": 0, "byteOffset": {p}, "byteLength": {p}}},
 {{"buffer": 0, "byteOffset": {p2}, "byteLength": {uv}}},
 {{"buffer": 0, "byteOffset": {iofs}, "byteLength": {i}}}],
"accessors": [
 {{"bufferView": 0, "componentType": 5126, "count": {n}, "type": "VEC3", "min": [-1.35, -0.35, -1.35], "max": [1.35, 0.35, 1.35]}},
 {{"bufferView": 1, "componentType": 5126, "count": {n}, "type": "VEC3"}},
 {{"bufferView": 2, "componentType": 5126, "count": {n}, "type": "VEC2"}},
 {{"bufferView": 3, "componentType": 5125, "count": {k}, "type": "SCALAR"}}],
"meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}, "indices": 3}}]}}],
"nodes": [{{"mesh": 0}}], "scenes": [{{"nodes": [0]}}], "scene": 0}})",
        fmt::arg("total", bin.size()), fmt::arg("p", p_bytes), fmt::arg("p2", 2 * p_bytes),
        fmt::arg("uv", uv_bytes), fmt::arg("iofs", 2 * p_bytes + uv_bytes), fmt::arg("i", i_bytes),
        fmt::arg("n", vertices), fmt::arg("k", t.tri.size()));
    while (json.size() % 4) json += ' ';
    std::string out;
    put<uint32_t>(out, 0x46546C67);
    put<uint32_t>(out, 2);
    put<uint32_t>(out, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    put<uint32_t>(out, static_cast<uint32_t>(json.size()));
    put<uint32_t>(out, 0x4E4F534A);
    out += json;
    put<uint32_t>(out, static_cast<uint32_t>(bin.size()));
    put<uint32_t>(out, 0x004E4942);
    out += bin;
    std::ofstream(path, std::ios::binary) << out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUT_DIR [TRIANGLES]\n", argv[0]);
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    const double triangles = argc > 2 ? std::atof(argv[2]) : 1e6;
    // 2 n m triangles with n = 2 m: m = sqrt(triangles / 4).
    const int m = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
    const Torus torus = make_torus(2 * m, m);
    std::filesystem::create_directories(dir);
    write_obj(torus, (dir / "torus.obj").string());
    write_ply(torus, (dir / "torus.ply").string());
    write_glb(torus, (dir / "torus.glb").string());
    std::printf("%zu triangles, %zu vertices in %s/torus.{obj,ply,glb}\n", torus.tri.size() / 3,
                torus.p.size() / 3, dir.string().c_str());
    return 0;
}
