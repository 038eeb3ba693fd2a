#pragma once
// 3D image warping (image-based rendering): a rendered image seen from a nearby viewpoint by
// its depth. The source pixels' centres, lifted to their scene points, form a mesh of two
// triangles per 2x2 block; each triangle is projected by the new camera and rasterised into
// the new image with a depth buffer (nearer wins), its colour interpolated. A triangle
// across a depth discontinuity would stretch a foreground edge over what lies behind it: it
// is dropped instead, and the new pixels nothing covers are disocclusions, which the source
// never saw, painted a flat colour and counted. Each source pixel is also drawn as a point
// (behind the triangles) so that edge pixels, whose depth blends both sides, are kept.
#include <glint/core/rgb.h>
#include <glint/film/image.h>

#include <cstdint>
#include <vector>

namespace glint {

class Camera;

struct WarpSettings {
    /// Neighbouring depths further apart than this fraction are a discontinuity.
    float depth_discontinuity = 0.1f;
    /// Projected triangles wider or taller than this many pixels are dropped (a point that
    /// came close to the new eye).
    float max_triangle_pixels = 32.0f;
    Rgb hole_colour{1.0f, 0.0f, 1.0f};  ///< magenta
};

struct WarpResult {
    Image image;                ///< R, G, B at the new viewpoint, holes in the hole colour
    std::vector<uint8_t> hole;  ///< per pixel, 1 where disoccluded
    int64_t holes = 0;          ///< how many
};

/// `source` (channels R, G, B and depth.Z: distance along each pixel's camera ray, 0 or
/// infinite where it escaped; escaped pixels warp by their direction, as a far background) seen by
/// `source_camera` (made for its size), warped to `target_camera`'s width x height film.
/// Runs on one thread (the rasteriser writes a shared depth buffer). Throws glint::Error
/// when the source lacks a channel.
WarpResult warp_image(const Image& source, const Camera& source_camera, const Camera& target_camera,
                      int width, int height, const WarpSettings& settings = {});

}  // namespace glint
