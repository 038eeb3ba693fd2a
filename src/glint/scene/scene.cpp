#include <glint/scene/scene.h>

namespace glint {

bool Scene::intersect(const Ray& ray, SurfaceInteraction& si) const {
    const std::optional<HitRecord> hit = m_accel.intersect(ray);
    if (!hit) return false;
    const WorldEntry& entry = m_world[hit->top_geometry];
    // What the shapes may leave unset, reset here, since `si` may hold the previous hit.
    si.part = 0;
    si.dpdx = si.dpdy = Vec3(0.0f);
    si.dudx = si.dvdx = si.dudy = si.dvdy = 0.0f;
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
    return true;
}

}  // namespace glint
