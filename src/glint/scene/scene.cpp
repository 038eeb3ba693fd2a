#include <glint/scene/scene.h>

namespace glint {

std::optional<SurfaceInteraction> Scene::intersect(const Ray& ray) const {
    // Filled where it is returned (one named result, so the compiler builds it in the
    // caller's storage): copying a freshly written SurfaceInteraction reads it back in wider
    // pieces than it was stored in, which stalls the CPU at every hit.
    std::optional<SurfaceInteraction> result;
    const std::optional<HitRecord> hit = m_accel.intersect(ray);
    if (!hit) return result;
    const WorldEntry& entry = m_world[hit->top_geometry];
    SurfaceInteraction& si = result.emplace();
    if (hit->instanced()) {
        const Geometry& geometry = m_group_geometry[entry.group][hit->local_geometry];
        const Transform to_local = entry.to_world.inverse();
        const Ray local_ray{to_local.point(ray.origin), to_local.vector(ray.direction), ray.t_min,
                            ray.t_max};
        geometry.shape->fill_interaction(local_ray, *hit, si);
        const Transform& xf = entry.to_world;
        si.p = xf.point(si.p);
        si.ng = glm::normalize(xf.normal(si.ng));
        si.dpdu = xf.vector(si.dpdu);
        si.dpdv = xf.vector(si.dpdv);
        si.shading = Frame::from_normal_tangent(glm::normalize(xf.normal(si.shading.n())),
                                                xf.vector(si.shading.s()));
        si.material = geometry.material(si.part);
        si.area_light = entry.lights[hit->local_geometry];
    } else {
        entry.geometry.shape->fill_interaction(ray, *hit, si);
        si.material = entry.geometry.material(si.part);
        si.area_light = entry.light;
    }
    si.t = hit->t;
    si.wo = -glm::normalize(ray.direction);
    si.front_face = glm::dot(si.ng, si.wo) > 0.0f;
    return result;
}

}  // namespace glint
