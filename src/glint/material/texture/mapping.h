#pragma once
// How a surface point becomes 2D texture coordinates (s, t), with their derivatives per
// pixel for filtering. Every image texture and 2D procedural texture has one:
//   "uv"          the shape's own uv (sphere: longitude/latitude, box: per face, mesh: from
//                 the OBJ file or the scene, quad: its corners), the default;
//   "planar"      projection of the object-space point onto two axes;
//   "spherical"   longitude/latitude of the object-space point around a centre;
//   "cylindrical" angle around the y axis and height.
// All then apply `scale` (tiling: 4 repeats the texture four times) and `offset`.
// Projections take their derivatives from the world-space footprint, which is exact for
// shapes placed by rotations, translations and uniform scales.
#include <glint/core/params.h>
#include <glint/material/texture/texture.h>

namespace glint {

struct TexCoord2D {
    Vec2 st;
    float dsdx = 0.0f, dsdy = 0.0f, dtdx = 0.0f, dtdy = 0.0f;
};

class TextureMapping2D {
public:
    enum class Kind { kUv, kPlanar, kSpherical, kCylindrical };

    TextureMapping2D() = default;
    TextureMapping2D(Kind kind, const Vec2& scale, const Vec2& offset, const Vec3& center,
                     const Vec3& s_axis, const Vec3& t_axis)
        : m_kind(kind),
          m_scale(scale),
          m_offset(offset),
          m_center(center),
          m_s_axis(s_axis),
          m_t_axis(t_axis) {}

    TexCoord2D map(const TextureContext& ctx) const;
    Kind kind() const { return m_kind; }

private:
    // (s, t) of an object-space point before scale and offset.
    Vec2 project(const Vec3& p) const;

    Kind m_kind = Kind::kUv;
    Vec2 m_scale{1.0f};
    Vec2 m_offset{0.0f};
    Vec3 m_center{0.0f};
    Vec3 m_s_axis{1, 0, 0}, m_t_axis{0, 0, 1};
};

// Reads `mapping` ("uv", "planar", "spherical", "cylindrical"), `scale` (a number or
// {su, sv}), `offset` ({s, t}), and for projections `center`, and for planar `s_axis` and
// `t_axis` (default x and z: a floor).
TextureMapping2D read_mapping_2d(const Params& params);

}  // namespace glint
