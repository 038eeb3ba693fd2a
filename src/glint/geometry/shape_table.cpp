#include <glint/core/error.h>
#include <glint/geometry/mesh.h>
#include <glint/geometry/shape_table.h>
#include <glint/geometry/sphere.h>

#include <fmt/format.h>

#include <filesystem>
#include <map>

namespace glint {
namespace {

using ShapeFactory = std::unique_ptr<Shape> (*)(const Params&, const ShapeSources&);

std::unique_ptr<Shape> mesh_shape(const Params& params, std::string name, MeshData data) {
    transform_mesh(data, params.get_transform("transform"));
    try {
        return std::make_unique<TriangleMesh>(std::move(name), std::move(data));
    } catch (const Error& e) {
        params.fail(e.what());
    }
}

// Deformation blur: `vertex_keys`, the vertices at later times, each key a flat list
// {x1, y1, z1, x2, ...} of as many vertices as `vertices` (the first key).
std::vector<std::vector<Vec3>> read_vertex_keys(const Params& params, size_t vertex_count) {
    std::vector<std::vector<Vec3>> keys;
    if (!params.has("vertex_keys")) return keys;
    // The same limit as motion keys (2 to 129 in all, with `vertices`).
    constexpr size_t kMaxLaterKeys = 128;
    const std::vector<std::vector<double>> rows = params.get_rows("vertex_keys");
    if (rows.empty() || rows.size() > kMaxLaterKeys) {
        params.fail_at("vertex_keys", fmt::format("'vertex_keys' must list 1 to {} keys, each the "
                                                  "vertices at a later time as a flat list "
                                                  "{{x1, y1, z1, x2, ...}}",
                                                  kMaxLaterKeys));
    }
    for (size_t k = 0; k < rows.size(); ++k) {
        if (rows[k].size() != 3 * vertex_count) {
            params.fail_at("vertex_keys",
                           fmt::format("key {} of 'vertex_keys' holds {} numbers; the mesh's {} "
                                       "vertices need {}",
                                       k + 1, rows[k].size(), vertex_count, 3 * vertex_count));
        }
        std::vector<Vec3>& key = keys.emplace_back(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i) {
            key[i] =
                Vec3(static_cast<float>(rows[k][3 * i]), static_cast<float>(rows[k][3 * i + 1]),
                     static_cast<float>(rows[k][3 * i + 2]));
        }
    }
    return keys;
}

std::unique_ptr<Shape> make_sphere(const Params& params, const ShapeSources&) {
    const SphereParams sphere = read_sphere(params);
    return std::make_unique<Sphere>(sphere.center, sphere.radius,
                                    params.get_transform("transform"));
}

std::unique_ptr<Shape> make_box(const Params& params, const ShapeSources&) {
    const BoxParams box = read_box(params);
    return mesh_shape(params, "box", make_box_mesh(box.lo, box.hi));
}

std::unique_ptr<Shape> make_quad(const Params& params, const ShapeSources&) {
    const std::vector<Vec3> v = params.get_vec3_list("vertices");
    if (v.size() != 4) params.fail("'vertices' must list exactly 4 corners");
    return mesh_shape(params, "quad", make_quad_mesh(v[0], v[1], v[2], v[3]));
}

std::unique_ptr<Shape> make_mesh(const Params& params, const ShapeSources& sources) {
    if (params.has("data")) {
        // Imported geometry (glint.import), shared with the description: copied once here,
        // where the transform is applied to it.
        const ObjectRef ref = params.get_ref("data", "mesh_data");
        return mesh_shape(params, "mesh", *sources.meshes->at(static_cast<size_t>(ref.index)));
    }
    if (params.has("file")) {
        std::filesystem::path path = params.get_string("file");
        if (path.is_relative()) path = std::filesystem::path(sources.directory) / path;
        MeshData data;
        try {
            data = sources.load_mesh_file(path.string());
        } catch (const Error& e) {
            params.fail(e.what());
        }
        return mesh_shape(params, path.filename().string(), std::move(data));
    }
    MeshData data;
    data.positions = params.get_vec3_list("vertices");
    data.normals = params.get_vec3_list("normals");
    data.uvs = params.get_vec2_list("uvs");
    for (double i : params.get_numbers("indices")) {
        // 1-based, as everything in Lua.
        // Checked before the conversion: a double past 2^32 does not fit a uint32_t.
        if (!(i >= 1 && i <= static_cast<double>(data.positions.size())) || i != std::floor(i)) {
            params.fail(fmt::format("'indices' must be integers from 1 to the {} vertices",
                                    data.positions.size()));
        }
        data.indices.push_back(static_cast<uint32_t>(i) - 1);
    }
    if (data.positions.empty() || data.indices.empty()) {
        params.fail("a mesh needs 'file', or 'vertices' and 'indices'");
    }
    data.position_keys = read_vertex_keys(params, data.positions.size());
    return mesh_shape(params, "mesh", std::move(data));
}

const std::map<std::string, ShapeFactory>& factories() {
    static const std::map<std::string, ShapeFactory> table = {
        {"sphere", make_sphere},
        {"box", make_box},
        {"quad", make_quad},
        {"mesh", make_mesh},
    };
    return table;
}

}  // namespace

std::vector<std::string> shape_types() {
    std::vector<std::string> names;
    for (const auto& [name, factory] : factories()) names.push_back(name);
    return names;
}

std::unique_ptr<Shape> make_shape(const Params& params, const ShapeSources& sources) {
    auto it = factories().find(params.type());
    if (it == factories().end()) params.fail("unknown shape type");
    auto shape = it->second(params, sources);
    params.check_all_used();
    return shape;
}

SphereParams read_sphere(const Params& params) {
    const Vec3 center = params.get_vec3("center", Vec3(0.0f));
    const float radius = params.get_float("radius", 1.0f);
    // The intersection squares the radius, in float: past 1e12 that is no longer finite.
    if (!(radius > 0.0f && radius <= 1e12f)) params.fail("'radius' must be in (0, 1e12]");
    return {center, radius};
}

BoxParams read_box(const Params& params) {
    const Vec3 lo = params.get_vec3("min", Vec3(-1.0f));
    const Vec3 hi = params.get_vec3("max", Vec3(1.0f));
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        params.fail("'min' must be below 'max' on every axis");
    return {lo, hi};
}

}  // namespace glint
