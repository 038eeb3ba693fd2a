#pragma once
// The first visible surface at each pixel's centre, for reprojecting earlier frames
// (reprojection.h) and for the real-time denoiser's edge-stopping (denoise/svgf.h). Traced
// by one camera ray per pixel centre: noise-free, and exactly what Camera::project inverts,
// unlike the film's depth AOV, which averages the jittered samples of a pixel.
#include <glint/core/rgb.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <vector>

namespace glint {

class Camera;
class Scene;

struct GeometryBuffer {
    /// The value of object_id where the ray escapes.
    static constexpr uint32_t kMiss = 0xffffffffu;

    int width = 0, height = 0;
    /// Per pixel, row-major, top row first. depth: distance along the camera ray (as the
    /// film's depth AOV and FilmProjection::depth), 0 where the ray escapes.
    std::vector<float> depth;
    std::vector<Vec3> normal;  ///< world-space shading normal, facing the camera; 0 on a miss
    std::vector<Rgb> albedo;   ///< the material's albedo; 1 on a miss (nothing to demodulate)
    /// Which object was hit (the scene's geometry id, mixed with the instance's), kMiss
    /// on a miss: history from another object is never reused, even at the same depth.
    std::vector<uint32_t> object_id;
    /// 1 where the surface emits light (a lamp seen directly): its pixels are exact, and far
    /// brighter than their surroundings, so the denoiser leaves them out.
    std::vector<uint8_t> emitter;

    std::size_t size() const { return static_cast<std::size_t>(width) * height; }
    bool hit(std::size_t i) const { return object_id[i] != kMiss; }
};

/// Traces one ray per pixel centre of a width x height film seen by `camera` (made for
/// that resolution), in parallel (TBB); the same buffer for any thread count.
GeometryBuffer trace_geometry_buffer(const Scene& scene, const Camera& camera, int width,
                                     int height);

}  // namespace glint
