#pragma once
// What a pbrt-v4 file describes, as plain data: the parser (parser.h) fills it from the
// directives, keeping pbrt's own names, units and (left-handed) coordinates; the translator
// (translate.h) turns it into glint's SceneDesc. Transforms are pbrt's object-to-world
// matrices as glm matrices (column vectors).
#include <glint/math/vector.h>
#include <glint/scene/import/pbrt/params.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// A directive with a type and parameters: Camera "perspective" ..., Shape "sphere" ...
struct PbrtEntity {
    std::string type;
    PbrtParams params;
    PbrtLocation where;
};

struct PbrtCamera {
    PbrtEntity entity;
    Mat4 camera_to_world{1.0f};  ///< pbrt's camera space: +x right, +y up, +z forward
};

struct PbrtTexture {
    std::string name;
    std::string value_kind;  ///< "float" or "spectrum"
    PbrtEntity entity;       ///< type: "imagemap", "checkerboard", ...
    Mat4 to_world{1.0f};
};

/// A material used by a shape: an anonymous one (Material) by index, or a named one
/// (NamedMaterial) by name, resolved after the whole file is read as pbrt-v4 does.
struct PbrtMaterialRef {
    int index = -1;
    std::string name;
};

struct PbrtShape {
    PbrtEntity entity;
    Mat4 to_world{1.0f};  ///< object to world (inside ObjectBegin: to the object's space)
    PbrtMaterialRef material;
    std::optional<PbrtEntity> area_light;
    bool reverse_orientation = false;
};

struct PbrtLight {
    PbrtEntity entity;
    Mat4 to_world{1.0f};
};

/// ObjectBegin/ObjectEnd: shapes placed by ObjectInstance.
struct PbrtObject {
    std::string name;
    PbrtLocation where;
    std::vector<PbrtShape> shapes;
};

struct PbrtInstance {
    std::string object;
    Mat4 to_world{1.0f};
    PbrtLocation where;
};

struct PbrtScene {
    std::string directory;  ///< the main file's folder: pbrt resolves every file name there
    std::optional<PbrtCamera> camera;
    std::optional<PbrtEntity> film, sampler, integrator, filter;
    std::vector<PbrtTexture> textures;
    std::vector<PbrtEntity> materials;  ///< Material directives, by PbrtMaterialRef::index
    std::map<std::string, PbrtEntity> named_materials;
    std::vector<PbrtShape> shapes;
    std::vector<PbrtLight> lights;
    std::vector<PbrtObject> objects;
    std::vector<PbrtInstance> instances;
    std::map<std::string, int> directive_counts;  ///< every directive read, for glint info
    std::vector<std::string> warnings;            ///< each "file:line: Directive: what"
};

}  // namespace glint
