#include <glint/core/error.h>
#include <glint/scene/scene.h>

namespace glint {

void Scene::set_camera(std::unique_ptr<Camera> camera) {
    if (!camera) throw Error("a scene needs a camera");
    m_camera = std::move(camera);
}

void Scene::fill_instanced(const Ray& ray, const HitRecord& hit, const WorldEntry& entry,
                           SurfaceInteraction& si) const {
    const Geometry& geometry = m_group_geometry[entry.group][hit.local_geometry];
    const Transform to_local = entry.to_world.inverse();
    const Ray local_ray{to_local.point(ray.origin), to_local.vector(ray.direction), ray.t_min,
                        ray.t_max};
    geometry.shape->fill_interaction(local_ray, hit, si);
    const Transform& xf = entry.to_world;
    si.p = xf.point(si.p);
    si.ng = glm::normalize(xf.normal(si.ng));
    si.dpdu = xf.vector(si.dpdu);
    si.dpdv = xf.vector(si.dpdv);
    si.shading = Frame::from_normal_tangent(glm::normalize(xf.normal(si.shading.n())),
                                            xf.vector(si.shading.s()));
    si.material = geometry.material(si.part);
    si.area_light = entry.lights[hit.local_geometry];
}

}  // namespace glint
