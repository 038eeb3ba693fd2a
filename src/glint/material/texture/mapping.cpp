#include <glint/material/texture/mapping.h>

namespace glint {

Vec2 TextureMapping2D::project(const Vec3& p) const {
    const Vec3 d = p - m_center;
    switch (m_kind) {
        case Kind::kPlanar:
            return Vec2(glm::dot(d, m_s_axis), glm::dot(d, m_t_axis));
        case Kind::kSpherical: {
            const float r = glm::length(d);
            if (!(r > 0.0f)) return Vec2(0.0f);
            const float phi = std::atan2(d.z, d.x);
            const float theta = std::acos(std::clamp(d.y / r, -1.0f, 1.0f));
            return Vec2((phi < 0.0f ? phi + 2.0f * kPi : phi) * kInv2Pi, 1.0f - theta * kInvPi);
        }
        case Kind::kCylindrical: {
            const float phi = std::atan2(d.z, d.x);
            return Vec2((phi < 0.0f ? phi + 2.0f * kPi : phi) * kInv2Pi, d.y);
        }
        case Kind::kUv:
            break;
    }
    return Vec2(0.0f);
}

TexCoord2D TextureMapping2D::map(const TextureContext& ctx) const {
    TexCoord2D tc;
    if (m_kind == Kind::kUv) {
        tc.st = ctx.uv;
        tc.dsdx = ctx.dudx;
        tc.dsdy = ctx.dudy;
        tc.dtdx = ctx.dvdx;
        tc.dtdy = ctx.dvdy;
    } else {
        tc.st = project(ctx.p_object);
        // Finite differences over the footprint; angles wrap, so take the short way round.
        auto delta = [&](const Vec3& dp) {
            Vec2 d = project(ctx.p_object + dp) - tc.st;
            if (m_kind != Kind::kPlanar) d.x -= std::round(d.x);
            return d;
        };
        const Vec2 dx = delta(ctx.dpdx), dy = delta(ctx.dpdy);
        tc.dsdx = dx.x;
        tc.dtdx = dx.y;
        tc.dsdy = dy.x;
        tc.dtdy = dy.y;
    }
    tc.st = tc.st * m_scale + m_offset;
    tc.dsdx *= m_scale.x;
    tc.dsdy *= m_scale.x;
    tc.dtdx *= m_scale.y;
    tc.dtdy *= m_scale.y;
    return tc;
}

TextureMapping2D read_mapping_2d(const Params& params) {
    const std::string name = params.get_string("mapping", "uv");
    TextureMapping2D::Kind kind;
    if (name == "uv")
        kind = TextureMapping2D::Kind::kUv;
    else if (name == "planar")
        kind = TextureMapping2D::Kind::kPlanar;
    else if (name == "spherical")
        kind = TextureMapping2D::Kind::kSpherical;
    else if (name == "cylindrical")
        kind = TextureMapping2D::Kind::kCylindrical;
    else
        params.fail(
            "'mapping' must be \"uv\", \"planar\", \"spherical\" or \"cylindrical\", not \"" +
            name + "\"");

    Vec2 scale(1.0f);
    if (params.has("scale")) {
        const std::vector<double> values = params.get_numbers("scale");
        if (values.size() == 1)
            scale = Vec2(static_cast<float>(values[0]));
        else if (values.size() == 2)
            scale = Vec2(values[0], values[1]);
        else
            params.fail("'scale' must be a number or {su, sv}");
        if (scale.x == 0.0f || scale.y == 0.0f) params.fail("'scale' must not be zero");
    }
    Vec2 offset(0.0f);
    if (params.has("offset")) {
        const std::vector<double> values = params.get_numbers("offset");
        if (values.size() != 2) params.fail("'offset' must be {s, t}");
        offset = Vec2(values[0], values[1]);
    }
    Vec3 center(0.0f), s_axis(1, 0, 0), t_axis(0, 0, 1);
    if (kind != TextureMapping2D::Kind::kUv) center = params.get_vec3("center", Vec3(0.0f));
    if (kind == TextureMapping2D::Kind::kPlanar) {
        s_axis = params.get_vec3("s_axis", s_axis);
        t_axis = params.get_vec3("t_axis", t_axis);
        if (glm::length(glm::cross(s_axis, t_axis)) <= 0.0f)
            params.fail("'s_axis' and 't_axis' must be non-zero and not parallel");
    }
    return TextureMapping2D(kind, scale, offset, center, s_axis, t_axis);
}

}  // namespace glint
