#pragma once
// Where a solid (3D) texture is evaluated. Solid textures read the hit in the shape's own
// space (TextureContext::p_object), so the pattern is carved out of the object and moves,
// turns and scales with it, whether it is placed by its own transform or as an instance.
//
// Pattern coordinates are q = scale * T^-1(p_object): `transform` T places the pattern in
// object space the way a transform places an object in the world (glint.translate(1, 0, 0)
// moves the pattern +1 along x; glint.scale(2) makes its features twice as large), and
// `scale` is a frequency (2 makes the features half as large).
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>

namespace glint {

class SolidMapping {
public:
    SolidMapping() = default;
    SolidMapping(const Transform& placement, const Vec3& scale);

    Vec3 map(const TextureContext& ctx) const { return map_point(ctx.p_object); }
    // Pattern coordinates of an object-space point.
    Vec3 map_point(const Vec3& p_object) const;

private:
    Mat4 m_object_to_pattern{1.0f};
};

// Reads `transform` (default identity) and `scale` (a number or {sx, sy, sz}, not zero;
// default 1).
SolidMapping read_solid_mapping(const Params& params);

}  // namespace glint
