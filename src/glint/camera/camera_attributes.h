#pragma once
// The camera an image was rendered with, as text attributes of its EXR header
// ("glint:camera.eye" and so on; Image::attributes), so that the image can be seen again from
// a nearby viewpoint by its depth (`glint warp`, view/image_warp.h) without its scene.
#include <glint/core/params.h>
#include <glint/math/vector.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glint {

using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

/// Attributes describing glint.camera{...} table `camera` (null: the default camera) for an
/// image of `resolution`: camera.type, camera.eye, camera.look_at, camera.up, camera.fov or
/// camera.scale, camera.resolution. Numbers are written so that they read back exactly.
ImageAttributes camera_attributes(const Params* camera, Vec2i resolution);

/// The camera table those attributes describe, and the resolution; nullopt when `attributes`
/// hold no camera. `where` names the file for errors. Throws glint::Error for a malformed one.
struct StoredCamera {
    Params params;
    Vec2i resolution;
};
std::optional<StoredCamera> camera_from_attributes(const ImageAttributes& attributes,
                                                   const std::string& where);

/// Parses "x,y,z" (three finite numbers); nullopt otherwise.
std::optional<Vec3> parse_vec3(const std::string& text);

}  // namespace glint
