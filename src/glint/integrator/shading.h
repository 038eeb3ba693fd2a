#pragma once
// What every integrator does at a surface hit before it scatters: the texture footprint
// (from the ray's differentials, or the camera's approximation after a bounce, as
// pbrt-v4 does), then the material's bump or normal map and its BSDF.
#include <glint/scene/scene.h>

namespace glint {

// Footprint of a pixel at si from the ray's differentials: the neighbouring rays meet the
// tangent plane at p + dpdx and p + dpdy.
inline bool footprint_from_differentials(const Ray& ray, SurfaceInteraction& si) {
    if (!ray.has_differentials) return false;
    const Vec3& n = si.ng;
    const float plane = glm::dot(n, si.p);
    const RayDifferentials& d = ray.differentials;
    const float denom_x = glm::dot(n, d.rx_direction), denom_y = glm::dot(n, d.ry_direction);
    if (denom_x == 0.0f || denom_y == 0.0f) return false;
    const float tx = (plane - glm::dot(n, d.rx_origin)) / denom_x;
    const float ty = (plane - glm::dot(n, d.ry_origin)) / denom_y;
    if (!std::isfinite(tx) || !std::isfinite(ty)) return false;
    si.set_footprint(d.rx_origin + tx * d.rx_direction - si.p,
                     d.ry_origin + ty * d.ry_direction - si.p);
    return true;
}

inline void set_texture_footprint(const Camera& camera, const Ray& ray, SurfaceInteraction& si) {
    if (footprint_from_differentials(ray, si)) return;
    Vec3 dpdx, dpdy;
    camera.approximate_footprint(si.p, si.ng, dpdx, dpdy);
    si.set_footprint(dpdx, dpdy);
}

// The BSDF at a hit reached by `ray` (nullptr for surfaces that only emit); may change
// si's shading frame (bump and normal maps).
inline const Bsdf* shade(const Scene& scene, const Ray& ray, SurfaceInteraction& si, Arena& arena) {
    if (si.material->uses_textures()) set_texture_footprint(scene.camera(), ray, si);
    return si.material->scatter(si, arena);
}

}  // namespace glint
