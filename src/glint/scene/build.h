#pragma once
#include <glint/scene/render_settings.h>
#include <glint/scene/scene.h>
#include <glint/scene/scene_desc.h>

#include <memory>

namespace glint {

// Turns a scene description into a renderable Scene: builds shapes, materials, lights,
// the Embree hierarchy and the camera. Throws glint::Error with the script location of
// the offending object.
std::unique_ptr<Scene> build_scene(const SceneDesc& desc, const RenderSettings& settings);

}  // namespace glint
