#include <glint/core/error.h>
#include <glint/scene/import/obj.h>

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <filesystem>
#include <map>
#include <tuple>

namespace glint {

MeshData load_obj(const std::string& path) {
    if (!std::filesystem::is_regular_file(path))
        throw Error(fmt::format("cannot open OBJ file '{}'", path));
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = std::filesystem::path(path).parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        throw Error(fmt::format("cannot read OBJ file '{}': {}", path, reader.Error()));
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    MeshData mesh;
    bool has_normals = !attrib.normals.empty();
    bool has_uvs = !attrib.texcoords.empty();
    // OBJ indexes positions, normals and uvs separately; one glint vertex per distinct triple.
    std::map<std::tuple<int, int, int>, uint32_t> vertex_of;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& index : shape.mesh.indices) {
            if (index.normal_index < 0) has_normals = false;
            if (index.texcoord_index < 0) has_uvs = false;
            const auto key =
                std::make_tuple(index.vertex_index, index.normal_index, index.texcoord_index);
            auto [it, inserted] =
                vertex_of.try_emplace(key, static_cast<uint32_t>(mesh.positions.size()));
            if (inserted) {
                const float* p = &attrib.vertices[3 * static_cast<size_t>(index.vertex_index)];
                mesh.positions.emplace_back(p[0], p[1], p[2]);
                if (index.normal_index >= 0) {
                    const float* n = &attrib.normals[3 * static_cast<size_t>(index.normal_index)];
                    mesh.normals.emplace_back(n[0], n[1], n[2]);
                } else {
                    mesh.normals.emplace_back(0.0f);
                }
                if (index.texcoord_index >= 0) {
                    const float* t =
                        &attrib.texcoords[2 * static_cast<size_t>(index.texcoord_index)];
                    mesh.uvs.emplace_back(t[0], t[1]);
                } else {
                    mesh.uvs.emplace_back(0.0f);
                }
            }
            mesh.indices.push_back(it->second);
        }
    }
    // Attributes only some corners have would give garbage; keep them only when complete.
    if (!has_normals) mesh.normals.clear();
    if (!has_uvs) mesh.uvs.clear();
    if (mesh.indices.empty()) throw Error(fmt::format("OBJ file '{}' contains no faces", path));
    return mesh;
}

}  // namespace glint
