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

// The ray leaving a delta (mirror or smooth glass) bounce at si in direction wi. When the
// incoming ray carried differentials, so does this one: its neighbours are reflected or
// refracted like it (Igehy 1999, as pbrt-v4's SurfaceInteraction::SpawnRay does), so a
// texture seen in a mirror or through glass is filtered by the footprint it really has
// there. The surface is taken as locally flat (no change of normal across the
// footprint): exact for planar mirrors and slabs, an approximation on curved ones. Other
// bounces spawn rays without differentials, and the camera approximates their footprint.
// `eta` is BsdfSample::eta (index of wi's side over wo's side).
inline Ray spawn_specular_ray(SurfaceInteraction& si, const Ray& incoming, const Vec3& wi,
                              bool transmission, float eta) {
    Ray ray = spawn_ray(si, wi);
    if (!footprint_from_differentials(incoming, si)) return ray;
    const Vec3 wo = si.wo;
    const Vec3 n = glm::dot(wo, si.shading.n()) < 0.0f ? -si.shading.n() : si.shading.n();
    const float cos_o = glm::dot(wo, n);
    RayDifferentials& d = ray.differentials;
    d.rx_origin = si.p + si.dpdx;
    d.ry_origin = si.p + si.dpdy;
    auto turned = [&](const Vec3& neighbour_direction) {
        // The change of wo towards the neighbouring ray (both unit length).
        const Vec3 dwo = -glm::normalize(neighbour_direction) - wo;
        const float dcos_o = glm::dot(dwo, n);
        if (!transmission) return wi + (-dwo + 2.0f * dcos_o * n);  // wi = -wo + 2 (wo.n) n
        // wi = -wo / eta + mu n with mu = cos_o / eta - cos_t, cos_t^2 = 1 - (1 - cos_o^2) / eta^2.
        const float cos_t = std::abs(glm::dot(wi, n));
        if (!(cos_t > 1e-6f)) return wi;
        const float dmu = (1.0f / eta - cos_o / (eta * eta * cos_t)) * dcos_o;
        return wi + (-dwo / eta + dmu * n);
    };
    d.rx_direction = turned(incoming.differentials.rx_direction);
    d.ry_direction = turned(incoming.differentials.ry_direction);
    ray.has_differentials = std::isfinite(d.rx_direction.x + d.rx_direction.y + d.rx_direction.z +
                                          d.ry_direction.x + d.ry_direction.y + d.ry_direction.z);
    return ray;
}

// The BSDF at a hit reached by `ray` (nullptr for surfaces that only emit); may change
// si's shading frame (bump and normal maps).
inline const Bsdf* shade(const Scene& scene, const Ray& ray, SurfaceInteraction& si, Arena& arena) {
    if (si.material->uses_textures()) set_texture_footprint(scene.camera(), ray, si);
    return si.material->scatter(si, arena);
}

}  // namespace glint
