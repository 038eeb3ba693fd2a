#pragma once
// The layouts a light probe comes in, and their resampling to the latitude-longitude map that
// EnvironmentLight samples (Debevec's light-probe formats, "Light Probe Image Gallery").
// Each layout maps a direction d of the map's frame (+y up, before any rotation) to image
// coordinates (x right, y down, both in [0, 1)) and back:
//   latlong      EnvironmentLight's own (environment_light.h): the centre column looks along -z.
//   mirror_ball  a mirrored ball photographed from far away along -z (the camera on +z, +y
//                up in the image): the disc's centre reflects +z (towards the camera), its
//                rim -z. For disc coordinates (a, b) in the unit disc (a right, b up), the
//                ball's normal is n = (a, b, sqrt(1 - a^2 - b^2)) and d = 2 n_z n - (0, 0, 1);
//                back: (a, b) = (d_x, d_y) sin(acos(d_z) / 2) / sqrt(d_x^2 + d_y^2).
//   angular      Debevec's angular map: the angle from +z grows linearly with the distance
//                from the disc's centre, pi at the rim: (a, b) = (d_x, d_y) acos(d_z) /
//                (pi sqrt(d_x^2 + d_y^2)). Equal angles get equal radii (unlike the ball).
//   cube_cross   a horizontal cross of six square faces, 4 wide and 3 high, seen from inside:
//                           [+y]
//                      [-x] [-z] [+x] [+z]
//                           [-y]
//                the middle row turns right from -x to -z (ahead) to +x to +z (behind);
//                +y above the face ahead and -y below it, each joined along its shared edge.
// Outside the disc (mirror_ball, angular) and in the cross's empty cells nothing is read.
#include <glint/core/spectrum.h>
#include <glint/math/vector.h>

#include <optional>
#include <string>
#include <vector>

namespace glint {

enum class EnvironmentMapping { kLatLong, kMirrorBall, kAngular, kCubeCross };

/// The mapping named `name` ("latlong", "mirror_ball", "angular", "cube_cross"), or none.
std::optional<EnvironmentMapping> environment_mapping_named(const std::string& name);

/// Image coordinates ((0, 0) the top-left corner, (1, 1) the bottom-right) of the unit
/// direction `d` in `mapping`'s layout (for cube_cross, of an image 4:3).
Vec2 environment_image_point(EnvironmentMapping mapping, const Vec3& d);

/// The unit direction at image coordinates `p`, or none where the layout holds nothing.
std::optional<Vec3> environment_direction(EnvironmentMapping mapping, const Vec2& p);

/// Resamples an image in `mapping`'s layout (`width` x `height`, rows from the top) to a
/// lat-long map (a width of 2 x its height): each lat-long pixel averages 4 x 4 bilinear
/// lookups of the source, spread over the pixel. For latlong the pixels come back as
/// they are. Throws glint::Error for an image whose shape the layout does not allow
/// (mirror_ball and angular: square; cube_cross: 4:3 with whole square faces).
struct LatLongImage {
    std::vector<Spectrum> pixels;
    int width = 0, height = 0;
};
LatLongImage to_latlong(EnvironmentMapping mapping, std::vector<Spectrum> pixels, int width,
                        int height);

}  // namespace glint
