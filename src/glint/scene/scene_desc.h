#pragma once
// The plain-data description of a scene, as written by a scene script: every object is a
// type name plus checked Params. Nothing here knows about Lua or Embree.
#include <glint/core/params.h>
#include <glint/geometry/mesh.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// Limits on what a scene can nest, so that no walk over it recurses without bound; the
/// loader reports a deeper CSG tree where it is made, the build a deeper placement.
inline constexpr int kMaxCsgDepth = 1000;       ///< CSG nodes from the root down to a primitive
inline constexpr size_t kMaxGroupDepth = 1000;  ///< groups placed inside each other
inline constexpr size_t kMaxPlacements = 1'000'000;  ///< group placements after flattening

// One placement of a group inside another group.
struct InstanceDesc {
    int group = -1;
    Transform transform;
    std::string where;  // script location, for errors
};

struct GroupDesc {
    std::string where;
    std::vector<Params> shapes;  // type: sphere, box, quad, mesh, or solid (a CSG tree)
    std::vector<InstanceDesc> instances;
};

// A solid for CSG: a primitive ("sphere", "quadric", ...) or a node ("union",
// "intersection", "difference") over earlier solids.
struct SolidDesc {
    Params params;
    std::vector<int> children;  // indices into SceneDesc::solids
};

struct SceneDesc {
    std::optional<Params> camera;
    std::optional<Params> render;
    std::optional<Params> background;
    std::vector<Params> textures;                // ObjectRef{"texture", i} indexes this
    std::vector<Params> materials;               // ObjectRef{"material", i} indexes this
    std::vector<Params> media;                   // ObjectRef{"medium", i} indexes this
    std::vector<Params> lights;                  // non-shape lights: point_light, spot_light
    std::vector<SolidDesc> solids;               // ObjectRef{"solid", i} indexes this
    std::vector<GroupDesc> groups{GroupDesc{}};  // groups[0] is the world (root) group
    std::string directory;  // where the script lives; relative file names start here
    bool trusted = false;   // --trusted-scene: the script may reach files outside its folder
    // Geometry read by glint.import: a "mesh" shape with data = ObjectRef{"mesh_data", i}
    // takes meshes[i] (shared, so that a description stays cheap to copy).
    std::vector<std::shared_ptr<const MeshData>> meshes;
    // The camera came from an imported file: a later glint.camera replaces it.
    bool camera_imported = false;
    // Width / height of the imported camera's view (glTF's aspectRatio), when it gives one:
    // `glint render MODEL` sizes its image by it (import.cpp, load_model_scene).
    std::optional<float> camera_aspect;
    // What importers read but could not map (e.g. an MTL statement), each naming the file
    // and line; the CLI prints them.
    std::vector<std::string> warnings;
    // What an importer read and what it left out, in sum (a pbrt file's directives); the
    // CLI prints them as notes.
    std::vector<std::string> notes;
};

}  // namespace glint
