#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/core/strings.h>
#include <glint/scene/import/gltf.h>
#include <glint/scene/import/import.h>
#include <glint/scene/import/mtl.h>
#include <glint/scene/import/obj.h>
#include <glint/scene/import/pbrt/translator.h>
#include <glint/scene/import/ply.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

namespace glint {
namespace {

Bounds3 bounds_of(const MeshData& mesh) {
    Bounds3 b;
    for (const Vec3& p : mesh.positions) b.expand(p);
    return b;
}

// A default material for geometry the file gives none: glint's default diffuse grey.
ObjectRef default_material(SceneDesc& desc, const std::string& where) {
    desc.materials.emplace_back("diffuse", where);
    return ObjectRef{"material", static_cast<int>(desc.materials.size()) - 1};
}

Bounds3 import_ply(SceneDesc& desc, const ImportTarget& target) {
    PlyMesh ply = load_ply(target.path);
    if (!ply.colors.empty()) {
        desc.warnings.push_back(fmt::format(
            "{}: {}: vertex colours are read but not used (glint has no vertex-colour input yet)",
            target.where, target.path));
    }
    const ObjectRef material =
        target.material ? *target.material : default_material(desc, target.where);
    const Bounds3 bounds = bounds_of(ply.mesh).transformed(target.transform);
    add_mesh_shape(desc, 0, std::move(ply.mesh), material, target.transform, target.where);
    return bounds;
}

Bounds3 import_obj(SceneDesc& desc, const ImportTarget& target) {
    if (target.material) {
        MeshData mesh = load_obj(target.path);
        const Bounds3 bounds = bounds_of(mesh).transformed(target.transform);
        add_mesh_shape(desc, 0, std::move(mesh), *target.material, target.transform, target.where);
        return bounds;
    }
    ObjScene scene = load_obj_scene(target.path);
    const std::filesystem::path directory = std::filesystem::path(target.path).parent_path();
    // Material name -> its MTL block; the first library that defines a name wins, as later
    // definitions in one file replace nothing in OBJ readers either.
    std::map<std::string, MtlMaterial> library;
    for (const std::string& name : scene.material_libraries) {
        const std::string file = (directory / name).string();
        if (target.confine_references &&
            !is_inside_folder(directory.empty() ? "." : directory.string(), file)) {
            throw Error(fmt::format(
                "{}: {}: material library '{}' lies outside the OBJ file's folder, where the "
                "files it refers to must be (glint render --trusted-scene lifts this)",
                target.where, target.path, name));
        }
        if (!std::filesystem::is_regular_file(file)) {
            desc.warnings.push_back(fmt::format(
                "{}: {}: material library '{}' not found; its materials are grey diffuse",
                target.where, target.path, file));
            continue;
        }
        for (MtlMaterial& m : load_mtl(file)) library.try_emplace(m.name, std::move(m));
    }
    std::map<std::string, ObjectRef> made;
    Bounds3 bounds;
    for (ObjScene::Part& part : scene.parts) {
        auto it = made.find(part.material);
        if (it == made.end()) {
            ObjectRef ref;
            auto m = library.find(part.material);
            if (m != library.end()) {
                MtlMaterial material = m->second;
                // Errors in building it name the script line and the .mtl line.
                material.where = fmt::format("{}: {}", target.where, material.where);
                desc.materials.push_back(
                    mtl_to_params(material, directory.string(), desc.textures, desc.warnings));
                ref = ObjectRef{"material", static_cast<int>(desc.materials.size()) - 1};
            } else {
                if (!part.material.empty()) {
                    desc.warnings.push_back(fmt::format(
                        "{}: {}:{}: material '{}' is not in any material library; it is grey "
                        "diffuse",
                        target.where, target.path, part.line, part.material));
                }
                ref = default_material(desc, target.where);
            }
            it = made.emplace(part.material, ref).first;
        }
        bounds.expand(bounds_of(part.mesh).transformed(target.transform));
        add_mesh_shape(desc, 0, std::move(part.mesh), it->second, target.transform, target.where);
    }
    return bounds;
}

}  // namespace

void add_mesh_shape(SceneDesc& desc, int group, MeshData mesh, const ObjectRef& material,
                    const Transform& transform, const std::string& where) {
    desc.meshes.push_back(std::make_shared<const MeshData>(std::move(mesh)));
    Params shape("mesh", where);
    shape.set("data", ObjectRef{"mesh_data", static_cast<int>(desc.meshes.size()) - 1});
    shape.set("material", material);
    if (!transform.is_identity()) shape.set("transform", transform);
    desc.groups.at(group).shapes.push_back(std::move(shape));
}

Bounds3 import_file(SceneDesc& desc, const ImportTarget& target) {
    const std::string ext = lower_extension(target.path);
    if (ext == ".obj") return import_obj(desc, target);
    if (ext == ".ply") return import_ply(desc, target);
    if (ext == ".gltf" || ext == ".glb") return import_gltf(desc, target);
    if (ext == ".pbrt") return import_pbrt(desc, target);
    throw Error(
        fmt::format("cannot import '{}': unknown file type '{}' (expected .obj, .ply, "
                    ".gltf, .glb or .pbrt)",
                    target.path, ext));
}

void import_into(SceneDesc& desc, const Params& params) {
    ImportTarget target;
    std::filesystem::path path = params.get_string("file");
    if (path.is_relative()) path = std::filesystem::path(desc.directory) / path;
    target.path = path.string();
    target.transform = params.get_transform("transform");
    if (params.has("material")) target.material = params.get_ref("material", "material");
    if (params.has("light_scale")) {
        target.light_scale = params.get_float("light_scale");
        if (!(*target.light_scale >= 0.0f) || !std::isfinite(*target.light_scale))
            params.fail("'light_scale' must be a finite number >= 0");
    }
    target.emission_scale = params.get_float("emission_scale", 1.0f);
    if (!(target.emission_scale >= 0.0f) || !std::isfinite(target.emission_scale))
        params.fail("'emission_scale' must be a finite number >= 0");
    if (params.has("animation")) {
        const std::vector<double> times = params.get_numbers("animation");
        const bool finite =
            std::all_of(times.begin(), times.end(), [](double t) { return std::isfinite(t); });
        if (times.empty() || times.size() > 2 || !finite || times.front() > times.back())
            params.fail_at("animation",
                           "'animation' must be {start, end} in seconds of the file's "
                           "animation (start <= end), or one time for a still pose");
        target.animation = std::array<float, 2>{static_cast<float>(times.front()),
                                                static_cast<float>(times.back())};
        const std::string ext = lower_extension(target.path);
        if (ext != ".gltf" && ext != ".glb")
            params.fail_at("animation", "'animation' applies to glTF files (.gltf, .glb) only");
    }
    target.where = params.where();
    target.confine_references = !desc.trusted;
    params.check_all_used();
    try {
        import_file(desc, target);
    } catch (const Error& e) {
        params.fail(e.what());
    }
}

MeshData load_mesh_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".obj") return load_obj(path);
    if (ext == ".ply") return load_ply(path).mesh;
    throw Error(
        fmt::format("mesh file '{}': unknown type '{}' (glint.mesh reads .obj and .ply; "
                    "glint.import also reads .gltf and .glb with their materials)",
                    path, ext));
}

bool is_model_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb" || ext == ".pbrt";
}

SceneDesc load_model_scene(const std::string& path) {
    SceneDesc desc;
    desc.directory = std::filesystem::path(path).parent_path().string();
    if (desc.directory.empty()) desc.directory = ".";
    ImportTarget target;
    target.path = path;
    target.where = path;
    const Bounds3 bounds = import_file(desc, target);
    if (!desc.camera && !bounds.is_empty()) {
        // A three-quarter view from the front, right and above, the bounding sphere filling
        // the 40-degree vertical field of view.
        const float fov = 40.0f;
        const Vec3 center = bounds.center();
        const float radius = std::max(1e-3f, 0.5f * glm::length(bounds.extent()));
        const float distance = radius / std::sin(glm::radians(0.5f * fov));
        const Vec3 eye = center + distance * glm::normalize(Vec3(0.35f, 0.3f, 1.0f));
        Params camera("camera", fmt::format("{} (default camera)", path));
        camera.set("eye", std::vector<double>{eye.x, eye.y, eye.z});
        camera.set("look_at", std::vector<double>{center.x, center.y, center.z});
        camera.set("fov", static_cast<double>(fov));
        desc.camera = std::move(camera);
    }
    if (desc.camera_aspect) {
        // The file's camera says its aspect ratio: the image keeps the default height and
        // takes the width that ratio gives (--res still decides, see the docs).
        const double width = std::clamp(std::round(512.0 * *desc.camera_aspect), 1.0, 65536.0);
        Params render("render", fmt::format("{} (camera aspect ratio)", path));
        render.set("width", width);
        render.set("height", 512.0);
        desc.render = std::move(render);
    }
    // A pbrt file is a whole scene: without lights it is dark, as pbrt renders it.
    if (desc.lights.empty() && !desc.background && lower_extension(path) != ".pbrt") {
        Params background("background", fmt::format("{} (default background)", path));
        background.set("radiance", 1.0);
        desc.background = std::move(background);
    }
    return desc;
}

}  // namespace glint
