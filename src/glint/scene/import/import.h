#pragma once
// glint.import: brings a model file (.obj with its .mtl, .ply, .gltf, .glb) into a scene
// description, with its meshes, materials and (glTF) node hierarchy, cameras and lights.
#include <glint/scene/scene_desc.h>

#include <array>
#include <optional>
#include <string>

namespace glint {

/// The luminous efficacy that defines the candela: 683 lm/W (at 540 THz).
inline constexpr float kWattsPerLumen = 1.0f / 683.0f;

/// How one file is brought in.
struct ImportTarget {
    std::string path;                   ///< the file, as found (relative to the cwd or absolute)
    Transform transform;                ///< placed at this transform in the world
    std::optional<ObjectRef> material;  ///< replaces every material of the file
    /// Multiplies the file's light intensities; unset, each format's own unit: glTF's candela
    /// and lux become W/sr and W/m^2 (1/683, see the docs), pbrt's are glint's (1).
    std::optional<float> light_scale;
    float emission_scale = 1.0f;  ///< multiplies glTF emission (see the docs)
    /// glTF animation: the file's times in seconds that the scene times 0 and 1 stand for;
    /// the first animation moves the nodes over them (motion keys). Equal times: the pose at
    /// that time, standing still. Unset: every node stands as the file places it.
    std::optional<std::array<float, 2>> animation;
    std::string where;  ///< the script location of the import, for messages
    /// Files the model refers to (MTL libraries, glTF buffers and images) must lie inside
    /// the model's folder; a trusted scene lifts this.
    bool confine_references = true;
};

/// glint.import{ file = ..., transform = ..., material = ..., light_scale = ...,
/// emission_scale = ... }: reads the
/// parameters (file names relative to desc.directory), imports the file into `desc` and
/// checks that every parameter was used. Throws glint::Error naming the script line and
/// the file (with its line or byte offset where the format has one).
void import_into(SceneDesc& desc, const Params& params);

/// Imports `target` into `desc` (what import_into does once the parameters are read).
/// Dispatches on the file's extension, case-insensitively. Returns the world-space bounds
/// of the geometry it placed.
Bounds3 import_file(SceneDesc& desc, const ImportTarget& target);

/// Adds `mesh` to desc.meshes and a "mesh" shape using it to group `group`, with
/// `material` and `transform`; for the importers.
void add_mesh_shape(SceneDesc& desc, int group, MeshData mesh, const ObjectRef& material,
                    const Transform& transform, const std::string& where);

/// The geometry of a mesh file for glint.mesh{ file = ... }: .obj (all groups merged,
/// materials ignored) or .ply. Throws glint::Error for another extension or a bad file.
MeshData load_mesh_file(const std::string& path);

/// Whether `path` names a model file that `glint render` takes without a Lua script.
bool is_model_file(const std::string& path);

/// A whole scene from a model file alone (`glint render model.glb`): the file's content;
/// its camera, or one framing the bounds of its geometry; a constant white background
/// when the file brings no lights.
SceneDesc load_model_scene(const std::string& path);

}  // namespace glint
