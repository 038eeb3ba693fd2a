#pragma once
// The lights a viewer user can move and dim, found in a SceneDesc, and the scene
// description with those edits made. The viewer rebuilds the scene from it (build_scene):
// quick for example-sized scenes, seconds for large meshes.
#include <glint/math/vector.h>
#include <glint/scene/scene_desc.h>

#include <string>
#include <vector>

namespace glint {

/// One light of the scene and what the user did to it.
struct EditableLight {
    std::string name;          ///< for the panel: its type and script line
    bool movable = false;      ///< point and spot lights and emissive shapes; not directional
                               ///< lights or the environment
    Vec3 offset{0.0f};         ///< moved by, in scene units (only when movable)
    float power_scale = 1.0f;  ///< factor on its intensity, irradiance or radiance (>= 0)
};

class LightEdits {
public:
    /// The lights of `desc`: every glint.*_light{...} and environment, then every shape of
    /// the world (not inside groups) with an emissive material.
    explicit LightEdits(const SceneDesc& desc);

    std::vector<EditableLight>& lights() { return m_lights; }
    const std::vector<EditableLight>& lights() const { return m_lights; }

    /// `desc` (the one given to the constructor) with every light moved and scaled. An
    /// emissive shape gets a copy of its material of its own, so dimming it leaves other
    /// shapes that share the material alone.
    SceneDesc apply(const SceneDesc& desc) const;

private:
    struct Source {
        bool shape = false;  // a world shape (index into groups[0].shapes), else desc.lights
        size_t index = 0;
    };
    std::vector<EditableLight> m_lights;
    std::vector<Source> m_sources;  // parallel to m_lights
};

}  // namespace glint
