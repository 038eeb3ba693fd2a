#pragma once
// pbrt-v4 scene (PbrtScene, pbrt's names and left-handed world) to glint's SceneDesc.
//
// Handedness: pbrt's camera space has +x to the image's right, +y up and +z forward; glint's
// camera is right-handed (right = forward x up). Mapping pbrt's world into glint's by a
// mirror M = scale(-1, 1, 1) makes the two cameras see the same image, not a mirrored
// one. Every transform becomes M * T (points, directions and normals alike, so what faces
// which way is kept; glint turns a triangle's winding with a mirroring transform, as pbrt
// flips its normals with transformSwapsHandedness). When the file's camera transform is
// itself a mirror (the "Scale -1 1 1" some exporters write before LookAt), the two
// mirrors cancel and M is the identity. See docs/scene-language.md, "pbrt-v4 files".
#include <glint/film/image.h>
#include <glint/scene/import/import.h>
#include <glint/scene/import/pbrt/scene.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>

namespace glint {

/// A colour or float input: a constant, or one of glint's textures.
struct PbrtValue {
    Vec3 constant{0.0f};
    std::optional<ObjectRef> texture;
    bool is_texture() const { return texture.has_value(); }
    ParamValue as_param() const;   ///< the texture, or the constant as {r, g, b}
    ParamValue as_number() const;  ///< the texture, or the constant's first channel
    double grey() const { return (constant.x + constant.y + constant.z) / 3.0; }
};

/// How a spectrum is read (pbrt-v4's SpectrumType).
enum class SpectrumUse { Albedo, Unbounded, Illuminant };

class PbrtTranslator {
public:
    PbrtTranslator(const PbrtScene& scene, SceneDesc& desc, const ImportTarget& target);
    /// Adds everything to desc; returns the bounds of the geometry placed (for a default camera).
    Bounds3 run();

    /// The mirror between pbrt's world and glint's (see the file comment).
    static Mat4 world_mirror(const std::optional<PbrtCamera>& camera);

private:
    // translator.cpp: the camera and the render settings
    void camera();
    void render_settings();
    void check_unused(const PbrtEntity& e, const std::string& directive);
    void warn(const PbrtLocation& where, const std::string& directive, const std::string& what);
    Transform glint_transform(const Mat4& pbrt_to_world) const;
    std::string where(const PbrtLocation& at) const;

    // materials.cpp: colours, textures, materials
    std::optional<PbrtValue> colour(const PbrtEntity& e, const std::string& name, SpectrumUse use);
    std::optional<PbrtValue> scalar(const PbrtEntity& e, const std::string& name);
    std::optional<PbrtValue> texture(const PbrtParam& p, const std::string& kind);
    PbrtValue texture_value(const PbrtTexture& t);
    void image_texture(const PbrtEntity& e, Params& p);
    /// The glint material for a pbrt material; nothing for "interface" (not rendered).
    std::optional<ObjectRef> material(const PbrtMaterialRef& ref, const PbrtLocation& used_at);
    std::optional<ObjectRef> named_material(const std::string& name, const PbrtLocation& used_at,
                                            int depth);
    std::optional<ObjectRef> make_material(const PbrtEntity& e, int depth);
    void conductor(const PbrtEntity& e, Params& p, const std::string& prefix);
    double alpha_of(const PbrtEntity& e, double roughness) const;
    /// glint's roughness (sqrt of the GGX alpha) from pbrt's roughness, uroughness and
    /// vroughness; `anisotropy` (when not null) receives glint's anisotropy for u != v.
    PbrtValue roughness(const PbrtEntity& e, double* anisotropy, const std::string& prefix);

    // lights.cpp
    void light(const PbrtLight& l);
    void infinite_light(const PbrtEntity& e, const Mat4& to_world, double scale);
    /// An emissive material for a shape with an AreaLightSource; `area_of_shape` (world
    /// units) is what "power" divides by.
    std::optional<ObjectRef> area_light_material(const PbrtEntity& area, double area_of_shape);
    Vec3 emission(const PbrtEntity& e, const char* name);
    bool has_infinite_light() const;

    // environment_map.cpp
    void environment_map(const PbrtEntity& e, const std::string& file, const Mat4& to_world,
                         double scale);

    // shapes.cpp
    void shapes();
    void load_ply_files();
    /// Adds shape `s` to group `group` at `transform`; returns its bounds there.
    Bounds3 place_shape(const PbrtShape& s, int group, const Transform& transform);
    std::optional<MeshData> mesh_of(const PbrtShape& s);
    double mean_triangle_area(const MeshData& mesh, const Transform& transform, const PbrtEntity& e,
                              bool warn_if_uneven);
    void instances();
    std::string resolve(const std::string& file) const;

    const PbrtScene& m_scene;
    SceneDesc& m_desc;
    const ImportTarget& m_target;
    Mat4 m_mirror{1.0f};
    double m_imaging_ratio = 1.0;  // film ISO and shutter time, applied to every emitter
    std::map<std::string, ObjectRef> m_float_textures, m_spectrum_textures;
    std::map<std::string, PbrtValue> m_constant_float_textures, m_constant_spectrum_textures;
    std::map<int, std::optional<ObjectRef>> m_anonymous_materials;
    std::map<std::string, std::optional<ObjectRef>> m_named_materials;
    std::set<std::string> m_textures_in_progress;
    std::map<std::string, MeshData> m_ply_meshes;  // by resolved path
    std::map<std::string, int> m_ply_uses;         // shapes yet to take each
    Bounds3 m_bounds;
    std::map<std::string, int> m_skipped;  // what was not rendered, for the summary
};

/// pbrt-v4's equal-area octahedral square (EqualAreaSphereToSquare): a unit direction in
/// the light's space to [0, 1]^2, (0, 0) the image's top-left corner.
Vec2 pbrt_equal_area_square_of(const Vec3& w);

/// A latitude-longitude image in glint's mapping (light/environment_light.cpp) resampled
/// from pbrt-v4's equal-area square `square`; `light_from_world` turns glint's world
/// directions into the light's. `file` names the source in messages.
Image latlong_from_equal_area(const Image& square, const Mat3& light_from_world,
                              const std::string& file);

/// glint.import of a .pbrt file (import_file dispatches here): parses it and translates it.
/// When the file is the scene itself (`glint render scene.pbrt`), its film, sampler,
/// integrator and filter become the render settings; imported into a Lua scene, only its
/// camera is taken (if the script has none) and the script's settings apply.
Bounds3 import_pbrt(SceneDesc& desc, const ImportTarget& target);

}  // namespace glint
