#pragma once
// What a ray hit: position, geometric and shading frames, surface parameterisation, and
// the material and area light attached to the surface.
#include <glint/core/ray.h>
#include <glint/math/frame.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace glint {

class Material;
class Light;

struct SurfaceInteraction {
    // Every member has an initialiser and the constructor is user-provided, so that making
    // one (a local, `optional::emplace()`) sets each member once: value-initialising a type
    // with an implicit constructor first zeroes all ~200 bytes, with a slow `rep stos`.
    SurfaceInteraction() noexcept {}

    Vec3 p{0.0f};         // world-space hit point
    Vec3 p_object{0.0f};  // the hit in the shape's own space (before its transform and placement)
    Vec3 ng{0.0f};        // geometric normal, unit length, pointing to the shape's outside
    Frame shading;        // shading frame, normal on the same side as ng
    Vec2 uv{0.0f};
    Vec3 dpdu{0.0f}, dpdv{0.0f};
    float t = 0.0f;          // ray parameter of the hit
    float time = 0.0f;       // the ray's scene time (Ray::time), which rays leaving here keep
    Vec3 wo{0.0f};           // direction towards the ray origin, unit length
    bool front_face = true;  // the ray arrived on the side ng points to
    int part = 0;  // which part of the shape was hit (CSG primitives have their own materials)
    uint32_t primitive = 0;  // the hit's primitive in its shape (a mesh's triangle; HitRecord)
    const Material* material = nullptr;
    const Light* area_light = nullptr;  // set when the surface emits

    // Texture footprint: how p and uv change from one pixel to the next on the image.
    // Zero until set_footprint() is called (integrators do so for materials with textures).
    Vec3 dpdx{0.0f}, dpdy{0.0f};
    float dudx = 0.0f, dvdx = 0.0f, dudy = 0.0f, dvdy = 0.0f;

    // Stores the footprint and derives the uv derivatives by least squares (pbrt-v4).
    void set_footprint(const Vec3& dp_dx, const Vec3& dp_dy);

    Vec3 to_local(const Vec3& w) const { return shading.to_local(w); }
    Vec3 to_world(const Vec3& w) const { return shading.to_world(w); }
};

// Moves `p` off the surface along the geometric normal by a few ulps of its own magnitude
// (Wächter & Binder, Ray Tracing Gems ch. 6), so new rays neither re-hit the surface they
// leave (acne) nor start behind a neighbouring surface (leaks), at any scene scale.
inline void SurfaceInteraction::set_footprint(const Vec3& dp_dx, const Vec3& dp_dy) {
    dpdx = dp_dx;
    dpdy = dp_dy;
    // Solve dp = dpdu du + dpdv dv in the least-squares sense.
    const float ata00 = glm::dot(dpdu, dpdu), ata01 = glm::dot(dpdu, dpdv);
    const float ata11 = glm::dot(dpdv, dpdv);
    const float det = ata00 * ata11 - ata01 * ata01;
    const float inv_det = std::abs(det) > 1e-20f ? 1.0f / det : 0.0f;
    auto solve = [&](const Vec3& dp, float& du, float& dv) {
        const float atb0 = glm::dot(dpdu, dp), atb1 = glm::dot(dpdv, dp);
        du = (ata11 * atb0 - ata01 * atb1) * inv_det;
        dv = (ata00 * atb1 - ata01 * atb0) * inv_det;
        // Clamp, so that a footprint seen edge-on cannot ask for the whole texture at once.
        du = std::isfinite(du) ? std::clamp(du, -1e8f, 1e8f) : 0.0f;
        dv = std::isfinite(dv) ? std::clamp(dv, -1e8f, 1e8f) : 0.0f;
    };
    solve(dpdx, dudx, dvdx);
    solve(dpdy, dudy, dvdy);
}

inline Vec3 offset_ray_origin(const Vec3& p, const Vec3& ng, const Vec3& direction) {
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    // The three axes in the lanes of one SSE register (GCC/Clang vector extension): the
    // same operations as axis by axis, so the same bits, in fewer instructions.
    using F32x4 = float __attribute__((vector_size(16)));
    using I32x4 = int32_t __attribute__((vector_size(16)));
    const Vec3 n = glm::dot(ng, direction) < 0.0f ? -ng : ng;
    const F32x4 pv = {p.x, p.y, p.z, 0.0f};
    const F32x4 nv = {n.x, n.y, n.z, 0.0f};
    // Move p by a few ulps away from the surface: add the offset to its bits, negated
    // where p is negative, since a float's bits grow with its magnitude.
    const I32x4 offset = __builtin_convertvector(kIntScale * nv, I32x4);
    const I32x4 negative = pv < 0.0f;  // all ones where p < 0
    // The sum in unsigned lanes, which wrap: the bits of -0.0 are INT_MIN as signed, and
    // moving them down would overflow (that lane is near the origin, so its sum is unused).
    using U32x4 = uint32_t __attribute__((vector_size(16)));
    const I32x4 moved = reinterpret_cast<I32x4>(
        reinterpret_cast<U32x4>(pv) + reinterpret_cast<U32x4>((offset ^ negative) - negative));
    // Near the origin ulps are tiny, so there p moves by a fixed small distance instead.
    // |p| < kOrigin on the bits: for magnitudes the order of the bits is that of the floats.
    const I32x4 magnitude = reinterpret_cast<I32x4>(pv) & 0x7fffffff;
    const I32x4 near_origin = magnitude < std::bit_cast<int32_t>(kOrigin);
    const I32x4 nudged = reinterpret_cast<I32x4>(pv + kFloatScale * nv);
    const F32x4 result = reinterpret_cast<F32x4>((nudged & near_origin) | (moved & ~near_origin));
    return Vec3(result[0], result[1], result[2]);
}

inline Ray spawn_ray(const SurfaceInteraction& si, const Vec3& direction) {
    return Ray{offset_ray_origin(si.p, si.ng, direction), direction, 0.0f, kInfinity, si.time};
}

// spawn_ray written over `ray` in place, for a path that carries one ray from bounce to
// bounce: building a whole new Ray (84 bytes with its unused differentials) and copying it
// over the old one costs more than setting the fields that change.
inline void respawn_ray(Ray& ray, const SurfaceInteraction& si, const Vec3& direction) {
    ray.origin = offset_ray_origin(si.p, si.ng, direction);
    ray.direction = direction;
    ray.t_min = 0.0f;
    ray.t_max = kInfinity;
    ray.time = si.time;
    ray.has_differentials = false;
}

// Shadow rays run from the offset origin towards a target point and stop this fraction of
// the way, so the surface at the target (a light) does not occlude itself. See
// Scene::occluded.
constexpr float kShadowRayEnd = 1.0f - 1e-4f;

}  // namespace glint
