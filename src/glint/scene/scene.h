#pragma once
// The renderable scene: geometry in Embree, materials, lights and the camera. Built once
// from a SceneDesc (scene/build.h); read-only and thread-safe while rendering.
#include <glint/camera/camera.h>
#include <glint/geometry/accel.h>
#include <glint/light/light_sampler.h>
#include <glint/material/material.h>
#include <glint/material/texture/texture_table.h>

#include <memory>
#include <optional>
#include <vector>

namespace glint {

/// A shape as the world places it, for integrators that work on the surfaces themselves
/// (radiosity meshes them): its geometry ids in the Embree world (what a HitRecord names),
/// where it stands and what covers it.
struct ScenePlacement {
    const Shape* shape = nullptr;
    std::vector<const Material*> materials;             ///< one per part of the shape
    Transform to_world;                                 ///< shape space to world space
    const Light* light = nullptr;                       ///< its area light, when it emits
    unsigned top_geometry = 0;                          ///< HitRecord::top_geometry of its hits
    unsigned local_geometry = RTC_INVALID_GEOMETRY_ID;  ///< HitRecord::local_geometry
};

struct SceneStats {
    size_t shapes = 0;     // shape placements in the world
    size_t triangles = 0;  // triangles in the world, counting every placement
    size_t lights = 0;
    size_t groups = 0;
    size_t instances = 0;
    size_t unique_triangles = 0;  // triangles built, each placed group counted once
    size_t mesh_bytes = 0;        // glint's arrays of the shapes (Shape::memory_bytes)
    int64_t embree_bytes = 0;     // Embree's BVHs and buffers after the build
    Bounds3 bounds;
    // What building found suspicious but renderable (e.g. a one-sided light that faces
    // away from everything), each naming the script line; the CLI prints them.
    std::vector<std::string> warnings;
};

class Scene {
public:
    // The closest hit along `ray`, written into `si`; false on a miss (si is then left
    // unspecified). Every field of `si` is written, so one SurfaceInteraction can serve a
    // whole path, bounce after bounce: hot loops should use this form.
    // Inline: the path tracer calls it once per bounce.
    // Surfaces that only bound media (Material::is_interface) are passed through: the hit
    // is the first other surface, with `t` along `ray` (the walks cross interfaces straight
    // on; media attach to them later).
    bool intersect(const Ray& ray, SurfaceInteraction& si) const {
        HitRecord hit;
        if (!m_accel.intersect(ray, hit)) return false;
        fill_interaction(ray, hit, si);
        if (m_has_interfaces && is_interface(si)) [[unlikely]]
            return intersect_past_interfaces(ray, si, hit);
        return true;
    }
    // intersect() for the rays in the lanes set in `active`, traced as one packet (see
    // Accel::intersect_packet); writes si[i] for each lane i that hit and returns those.
    // With `records`, also Embree's record of each lane's hit (as the one-ray form below).
    uint32_t intersect_packet(const PerLane<const Ray*>& rays, uint32_t active,
                              const PerLane<SurfaceInteraction*>& si, bool coherent,
                              PerLane<HitRecord>* records = nullptr) const {
        PerLane<HitRecord> local;
        PerLane<HitRecord>& hits = records ? *records : local;
        uint32_t hit_lanes = m_accel.intersect_packet(rays, active, hits, coherent);
        for_each_lane(hit_lanes,
                      [&](int lane) { fill_interaction(*rays[lane], hits[lane], *si[lane]); });
        if (m_has_interfaces) [[unlikely]] {
            for_each_lane(hit_lanes, [&](int lane) {
                if (is_interface(*si[lane]) &&
                    !intersect_past_interfaces(*rays[lane], *si[lane], hits[lane]))
                    hit_lanes &= ~(1u << lane);
            });
        }
        return hit_lanes;
    }
    // intersect(), also handing back Embree's record of the hit (which geometry, which
    // triangle, where on it): for integrators that keep data per primitive (radiosity).
    bool intersect(const Ray& ray, SurfaceInteraction& si, HitRecord& hit) const {
        if (!m_accel.intersect(ray, hit)) return false;
        fill_interaction(ray, hit, si);
        if (m_has_interfaces && is_interface(si)) [[unlikely]]
            return intersect_past_interfaces(ray, si, hit);
        return true;
    }
    // The same, as a value: a fresh SurfaceInteraction (~200 bytes set up) per call.
    std::optional<SurfaceInteraction> intersect(const Ray& ray) const {
        std::optional<SurfaceInteraction> result(std::in_place);
        if (!intersect(ray, *result)) result.reset();
        return result;
    }
    // The closest hit along `ray` of any surface, interfaces included: for walks that carry
    // a medium, which changes where they cross an interface (volpath).
    bool intersect_surface(const Ray& ray, SurfaceInteraction& si) const {
        HitRecord hit;
        if (!m_accel.intersect(ray, hit)) return false;
        fill_interaction(ray, hit, si);
        return true;
    }
    // intersect_surface() past the interfaces that Embree can skip in the same traversal
    // (Accel::intersect_passing): `si` is the closest other hit (or an interface Embree could
    // not skip), and `passed` the interfaces before it along `ray`, in order; passed_surface()
    // fills in one of them. One traversal where a leg per interface took one each: for walks
    // that carry a medium through the boxes that bound it.
    bool intersect_surface_passing(const Ray& ray, SurfaceInteraction& si,
                                   PassedSurfaces& passed) const {
        HitRecord hit;
        if (!m_accel.intersect_passing(ray, hit, passed)) return false;
        fill_interaction(ray, hit, si);
        return true;
    }
    // intersect_surface_passing() for the rays in the lanes set in `active`, traced together
    // (Accel::intersect_packet_passing): the same surface and crossings per lane as the
    // one-ray form. Returns the lanes that hit.
    uint32_t intersect_surface_packet_passing(const PerLane<const Ray*>& rays, uint32_t active,
                                              const PerLane<SurfaceInteraction*>& si,
                                              PerLane<PassedSurfaces>& passed,
                                              bool coherent) const {
        PerLane<HitRecord> hits;
        const uint32_t hit_lanes =
            m_accel.intersect_packet_passing(rays, active, hits, passed, coherent);
        for_each_lane(hit_lanes,
                      [&](int lane) { fill_interaction(*rays[lane], hits[lane], *si[lane]); });
        return hit_lanes;
    }
    void passed_surface(const Ray& ray, const HitRecord& hit, SurfaceInteraction& si) const {
        fill_interaction(ray, hit, si);
    }
    // What a walk needs of a passed interface: its material, and whether `ray` goes along
    // its geometric normal (as passed_surface() fills them in, without the rest of the
    // interaction).
    struct Crossing {
        const Material* material = nullptr;
        bool along_normal = false;
    };
    Crossing passed_crossing(const Ray& ray, const HitRecord& hit) const {
        const WorldEntry& entry = m_world[hit.top_geometry];
        if (hit.instanced()) {
            SurfaceInteraction si;
            fill_interaction(ray, hit, si);
            return {si.material, glm::dot(ray.direction, si.ng) > 0.0f};
        }
        // Only CSG solids have parts, and Embree passes no user geometry. A plain mesh's side
        // comes from the record (the shape's normal, a virtual call and a load per crossing,
        // was 1 % of the preview in fog, which crosses the fog box twice a ray).
        const Vec3 ng =
            entry.side_from_hit ? hit.normal : entry.geometry.shape->geometric_normal(ray, hit);
        return {entry.geometry.material(0), glm::dot(ray.direction, ng) > 0.0f};
    }
    bool occluded(const Ray& ray) const { return m_accel.occluded(ray); }
    // Whether anything blocks the shadow ray from `si` (its origin offset as spawn_ray's)
    // to just short of `target`.
    bool occluded(const SurfaceInteraction& si, const Vec3& target) const {
        const ShadowRay shadow = shadow_ray(si, target);
        return m_accel.occluded(shadow.origin, shadow.direction, 0.0f, kShadowRayEnd, shadow.time);
    }
    // The shadow ray occluded(si, target) traces: from the offset origin, with the
    // direction reaching `target` at t = 1 (it stops at kShadowRayEnd), at the scene time
    // of the ray that reached si.
    struct ShadowRay {
        Vec3 origin, direction;
        float time = 0.0f;
    };
    static ShadowRay shadow_ray(const SurfaceInteraction& si, const Vec3& target) {
        const Vec3 origin = offset_ray_origin(si.p, si.ng, target - si.p);
        return {origin, target - origin, si.time};
    }
    // The lanes among `active` whose shadow ray (from shadow_ray(), lane i at scene time
    // times[i]) is blocked, traced as one packet.
    uint32_t occluded_packet(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                             const PerLane<float>& times, uint32_t active, bool coherent) const {
        return m_accel.occluded_packet(origins, directions, times, kShadowRayEnd, active, coherent);
    }

    const Camera& camera() const { return *m_camera; }
    /// Replaces the camera (the viewer moves it; see make_camera). Not while a render reads
    /// the scene. Throws glint::Error for a null camera.
    void set_camera(std::unique_ptr<Camera> camera);
    const std::vector<std::unique_ptr<Light>>& lights() const { return m_lights; }
    /// Every material the scene's surfaces use.
    const std::vector<std::unique_ptr<Material>>& materials() const { return m_materials; }
    const LightSampler& light_sampler() const { return m_light_sampler; }
    Spectrum background() const { return m_background.spectrum(); }
    // The scene's light at infinity (an environment map), or nullptr: at most one.
    const Light* environment() const { return m_environment; }
    // Radiance a ray receives when it leaves the scene along `direction` (need not be
    // unit): the environment light's if there is one, else the constant background.
    Spectrum escaped_radiance(const Vec3& direction) const {
        return m_environment ? m_environment->le_escaped(direction) : m_background.spectrum();
    }
    const SceneStats& stats() const { return m_stats; }
    /// Whether a material only bounds media (Material::is_interface): shadow rays then
    /// cross such surfaces (transport/visibility.h); otherwise any hit blocks them.
    bool has_interfaces() const { return m_has_interfaces; }
    // Whether every shape with an interface part is one that Embree skips in a recording
    // query (a triangle mesh placed in the world, all of its parts interfaces): then one
    // any-hit traversal tells a shadow ray's blockers and crossings (Accel::occluded_passing).
    bool interfaces_skippable() const { return m_interfaces_skippable; }
    /// The participating media (glint.medium) the scene holds, in script order.
    const std::vector<std::unique_ptr<Medium>>& media() const { return m_media; }
    /// The medium the camera sits in (glint.camera{ medium = ... }); null: vacuum.
    const Medium* camera_medium() const { return m_camera_medium; }
    /// Whether anything moves over the shutter (a moving group or shape, or the camera):
    /// only then do camera rays draw a time (Camera::sample_ray), so a still scene renders
    /// the same bits with a shutter as without.
    bool has_motion() const { return m_has_motion; }
    /// The folder of the scene's script (or model file): where files the scene names, such
    /// as a radiosity cache, are looked for, and which they must not leave unless trusted().
    const std::string& directory() const { return m_directory; }
    /// Whether the user vouched for the scene (--trusted-scene).
    bool trusted() const { return m_trusted; }
    /// Every placed shape of the world, in world geometry id order (an instance's shapes in
    /// their local id order); built on each call.
    std::vector<ScenePlacement> placements() const;
    // The raw ray-query structure, for benchmarks that measure Embree alone and for
    // visibility queries that need no SurfaceInteraction (radiosity's form factors).
    const Accel& accel() const { return m_accel; }

private:
    friend class SceneBuilder;

    struct Geometry {
        const Shape* shape = nullptr;
        std::vector<const Material*> materials;  // one per part of the shape

        const Material* material(int part) const {
            return static_cast<size_t>(part) < materials.size() ? materials[part]
                                                                : materials.front();
        }
    };
    // One entry per geometry id of the world scene: a root shape or a group instance.
    struct WorldEntry {
        Geometry geometry;  // root shapes
        int group = -1;     // instances: the prototype
        Transform to_world;
        MotionTransform motion;            // instances that move: to_world at each ray's time
        std::vector<const Light*> lights;  // instances: area light per local geometry id
        const Light* light = nullptr;      // root shapes
        // Root shapes whose hit records' normal tells the side as geometric_normal() does.
        bool side_from_hit = false;
    };

    // Turns Embree's hit record into the SurfaceInteraction: the shape fills in its part,
    // and the scene adds material, light and the ray's side. Writes every field of `si`.
    void fill_interaction(const Ray& ray, const HitRecord& hit, SurfaceInteraction& si) const {
        const WorldEntry& entry = m_world[hit.top_geometry];
        // What the shapes may leave unset, reset here, since `si` may hold the previous hit.
        si.part = 0;
        si.primitive = hit.primitive;
        si.dpdx = si.dpdy = Vec3(0.0f);
        si.dudx = si.dvdx = si.dudy = si.dvdy = 0.0f;
        if (hit.instanced()) {
            fill_instanced(ray, hit, entry, si);
        } else {
            entry.geometry.shape->fill_interaction(ray, hit, si);
            si.material = entry.geometry.material(si.part);
            si.area_light = entry.light;
        }
        si.t = hit.t;
        si.time = ray.time;
        si.wo = -glm::normalize(ray.direction);
        si.front_face = glm::dot(si.ng, si.wo) > 0.0f;
    }
    static bool is_interface(const SurfaceInteraction& si);
    // From `si`, an interface hit of `ray`, on along the ray to the first surface that is
    // not an interface, into `si` and `hit`; false when there is none before ray.t_max.
    bool intersect_past_interfaces(const Ray& ray, SurfaceInteraction& si, HitRecord& hit) const;
    // Scene::intersect for a hit inside a group instance: the shape fills `si` in the
    // group's space, and the result is carried to the world.
    void fill_instanced(const Ray& ray, const HitRecord& hit, const WorldEntry& entry,
                        SurfaceInteraction& si) const;
    // fill_instanced with the group placed by `xf` (where it stands at the ray's time).
    void fill_instanced_at(const Ray& ray, const HitRecord& hit, const WorldEntry& entry,
                           const Transform& xf, SurfaceInteraction& si) const;

    Accel m_accel;
    std::vector<std::unique_ptr<Shape>> m_shapes;
    std::unique_ptr<TextureTable> m_textures;      // before the materials that point into it
    std::vector<std::unique_ptr<Medium>> m_media;  // before the materials that point to them
    std::vector<std::unique_ptr<Material>> m_materials;
    std::vector<std::unique_ptr<Light>> m_lights;
    std::vector<std::vector<Geometry>> m_group_geometry;  // per prototype, by local id
    std::vector<WorldEntry> m_world;
    std::unique_ptr<Camera> m_camera;
    LightSampler m_light_sampler;
    SceneColor m_background;
    std::string m_directory = ".";
    bool m_trusted = false;
    const Light* m_environment = nullptr;  // one of m_lights
    SceneStats m_stats;
    bool m_has_interfaces = false;
    bool m_interfaces_skippable = true;
    const Medium* m_camera_medium = nullptr;  // one of m_media
    bool m_has_motion = false;
};

}  // namespace glint
