#include <glint/core/error.h>
#include <glint/material/material.h>
#include <glint/scene/scene.h>

namespace glint {

void Scene::set_camera(std::unique_ptr<Camera> camera) {
    if (!camera) throw Error("a scene needs a camera");
    camera->set_time_sampled(m_has_motion || camera->is_moving());
    m_camera = std::move(camera);
}

void Scene::fill_instanced(const Ray& ray, const HitRecord& hit, const WorldEntry& entry,
                           SurfaceInteraction& si) const {
    // A moving group stands where it stood at the ray's time, as Embree saw it there.
    if (entry.motion.is_moving()) [[unlikely]]
        fill_instanced_at(ray, hit, entry, entry.motion.at(ray.time), si);
    else
        fill_instanced_at(ray, hit, entry, entry.to_world, si);
}

void Scene::fill_instanced_at(const Ray& ray, const HitRecord& hit, const WorldEntry& entry,
                              const Transform& xf, SurfaceInteraction& si) const {
    const Geometry& geometry = m_group_geometry[entry.group][hit.local_geometry];
    const Transform to_local = xf.inverse();
    const Ray local_ray{to_local.point(ray.origin), to_local.vector(ray.direction), ray.t_min,
                        ray.t_max, ray.time};
    geometry.shape->fill_interaction(local_ray, hit, si);
    si.p = xf.point(si.p);
    si.ng = glm::normalize(xf.normal(si.ng));
    si.dpdu = xf.vector(si.dpdu);
    si.dpdv = xf.vector(si.dpdv);
    si.shading = Frame::from_normal_tangent(glm::normalize(xf.normal(si.shading.n())),
                                            xf.vector(si.shading.s()));
    si.material = geometry.material(si.part);
    si.area_light = entry.lights[hit.local_geometry];
}

bool Scene::is_interface(const SurfaceInteraction& si) {
    return si.material && si.material->is_interface();
}

bool Scene::intersect_past_interfaces(const Ray& ray, SurfaceInteraction& si,
                                      HitRecord& hit) const {
    // A bound against surfaces stacked without end (coincident copies): past it the ray is
    // taken to end there, unseen.
    constexpr int kMaxInterfaceCrossings = 256;
    float t = si.t;  // along `ray`; each leg keeps its direction, so t adds up
    Ray leg = ray;
    for (int crossing = 0; crossing < kMaxInterfaceCrossings; ++crossing) {
        leg.origin = offset_ray_origin(si.p, si.ng, ray.direction);
        leg.t_min = 0.0f;
        leg.t_max = ray.t_max - t;
        if (!(leg.t_max > 0.0f) || !m_accel.intersect(leg, hit)) return false;
        fill_interaction(leg, hit, si);
        t += si.t;
        if (!is_interface(si)) {
            si.t = t;
            return true;
        }
    }
    return false;
}

std::vector<ScenePlacement> Scene::placements() const {
    std::vector<ScenePlacement> result;
    for (unsigned id = 0; id < m_world.size(); ++id) {
        const WorldEntry& entry = m_world[id];
        if (entry.group < 0) {
            if (!entry.geometry.shape) continue;
            result.push_back({entry.geometry.shape, entry.geometry.materials, Transform(),
                              entry.light, id, RTC_INVALID_GEOMETRY_ID});
            continue;
        }
        const std::vector<Geometry>& local = m_group_geometry[entry.group];
        for (unsigned l = 0; l < local.size(); ++l) {
            if (!local[l].shape) continue;
            const Light* light = l < entry.lights.size() ? entry.lights[l] : nullptr;
            result.push_back({local[l].shape, local[l].materials, entry.to_world, light, id, l});
        }
    }
    return result;
}

}  // namespace glint
