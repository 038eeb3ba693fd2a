#pragma once
// glTF 2.0 import (.gltf and .glb) through tinygltf: the only file that uses it.
#include <glint/scene/import/import.h>

namespace glint {

/// Brings a glTF file's default scene (or its first) into `desc`: see
/// docs/scene-language.md, "glTF". Returns the world-space bounds of its geometry.
/// Throws glint::Error naming the file for a file tinygltf cannot read or whose content
/// is out of range (an index past its accessor, a non-finite value, ...).
Bounds3 import_gltf(SceneDesc& desc, const ImportTarget& target);

}  // namespace glint
