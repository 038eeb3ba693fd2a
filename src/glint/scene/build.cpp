#include <glint/core/error.h>
#include <glint/geometry/shape_table.h>
#include <glint/light/area_light.h>
#include <glint/light/registry.h>
#include <glint/material/registry.h>
#include <glint/material/texture/registry.h>
#include <glint/medium/registry.h>
#include <glint/scene/build.h>
#include <glint/scene/import/import.h>
#include <glint/scene/solids.h>

#include <fmt/format.h>

#include <algorithm>

namespace glint {

class SceneBuilder {
public:
    SceneBuilder(const SceneDesc& desc, const RenderSettings& settings)
        : m_desc(desc), m_settings(settings), m_scene(std::make_unique<Scene>()) {}

    std::unique_ptr<Scene> build() {
        m_scene->m_directory = m_desc.directory.empty() ? "." : m_desc.directory;
        m_scene->m_trusted = m_desc.trusted;
        for (const Params& p : m_desc.media)
            m_scene->m_media.push_back(make_medium(p, m_desc.directory));
        build_camera();
        m_scene->m_textures =
            std::make_unique<TextureTable>(m_desc.directory, m_settings.mipmapping);
        for (const Params& p : m_desc.textures)
            m_scene->m_textures->add(make_texture(p, *m_scene->m_textures));
        for (const Params& p : m_desc.materials) {
            const MediumInterface media = attached_media(p);
            m_scene->m_materials.push_back(make_material(p, *m_scene->m_textures));
            m_scene->m_materials.back()->set_media(media);
            m_scene->m_has_interfaces |= m_scene->m_materials.back()->is_interface();
        }
        build_lights();
        if (m_desc.background) {
            const Rgb radiance = m_desc.background->get_rgb("radiance", Rgb(0.0f));
            if (radiance.min_value() < 0.0f) {
                m_desc.background->fail("'radiance' must not be negative");
            }
            m_scene->m_background = SceneColor(radiance, RgbRole::illuminant);
            m_desc.background->check_all_used();
        }
        build_groups();
        place_root();
        m_scene->m_accel.commit();
        set_up_motion();
        for (const auto& shape : m_scene->m_shapes) {
            m_scene->m_stats.unique_triangles += shape->triangle_count();
            m_scene->m_stats.mesh_bytes += shape->memory_bytes();
        }
        m_scene->m_stats.embree_bytes = m_scene->m_accel.embree_bytes();
        warn_of_lights_facing_away();
        const Bounds3& bounds = m_scene->m_stats.bounds;
        const Vec3 center = bounds.is_empty() ? Vec3(0.0f) : bounds.center();
        const float radius =
            bounds.is_empty() ? 1.0f : std::max(1e-3f, 0.5f * glm::length(bounds.extent()));
        for (auto& light : m_scene->m_lights) light->preprocess(center, radius);
        m_scene->m_light_sampler =
            LightSampler(m_scene->m_lights, light_selection_named(m_settings.light_sampler));
        m_scene->m_stats.lights = m_scene->m_lights.size();
        return std::move(m_scene);
    }

private:
    // The lights that are not shapes; at most one environment, which replaces the
    // constant background.
    void build_lights() {
        const Params* environment = nullptr;
        for (const Params& p : m_desc.lights) {
            m_scene->m_lights.push_back(make_light(p, m_desc.directory));
            if (!m_scene->m_lights.back()->is_infinite()) continue;
            if (environment) {
                p.fail(fmt::format("a scene has at most one environment light; the first is at {}",
                                   environment->where()));
            }
            environment = &p;
            m_scene->m_environment = m_scene->m_lights.back().get();
        }
        if (environment && m_desc.background) {
            m_desc.background->fail(
                fmt::format("a scene with an environment light (at {}) has no background: "
                            "escaped rays see the environment",
                            environment->where()));
        }
    }

    // The medium a parameter names (a glint.medium handle), or null when it is not given.
    const Medium* medium_param(const Params& p, const char* name) const {
        if (!p.has(name)) return nullptr;
        return m_scene->m_media.at(p.get_ref(name, "medium").index).get();
    }

    // A surface's `interior` and `exterior` media: the sides its geometric normal points
    // away from and to. A dielectric's `absorption` is a medium of its own: not both.
    MediumInterface attached_media(const Params& p) const {
        const MediumInterface media{medium_param(p, "interior"), medium_param(p, "exterior")};
        if (media.is_transition() && p.has("absorption"))
            p.fail("give either 'absorption' or 'interior'/'exterior' media, not both");
        return media;
    }

    // The material of shape `p`: material `index` itself, or, when the shape names its own
    // `interior`/`exterior` media, a copy of it bounding those.
    const Material* shape_material(const Params& p, int index) {
        const MediumInterface media{medium_param(p, "interior"), medium_param(p, "exterior")};
        if (!media.is_transition()) return m_scene->m_materials.at(index).get();
        const Params& material_params = m_desc.materials.at(index);
        if (material_params.has("absorption"))
            p.fail("a dielectric with 'absorption' takes no 'interior'/'exterior' media");
        auto copy = make_material(material_params, *m_scene->m_textures);
        copy->set_media(media);
        m_scene->m_has_interfaces |= copy->is_interface();
        m_scene->m_materials.push_back(std::move(copy));
        return m_scene->m_materials.back().get();
    }

    void build_camera() {
        if (m_desc.camera) m_scene->m_camera_medium = medium_param(*m_desc.camera, "medium");
        const Params fallback("camera", "default camera");
        m_scene->m_camera = make_camera(m_desc.camera ? *m_desc.camera : fallback,
                                        Vec2i(m_settings.width, m_settings.height));
        m_scene->m_camera->set_samples_per_pixel(m_settings.spp);
        if (!m_desc.camera_motion.empty())
            m_scene->m_camera->set_motion(MotionTransform(m_desc.camera_motion));
    }

    // Camera rays draw a time only when something moves (Scene::has_motion).
    void set_up_motion() {
        m_scene->m_has_motion |= m_scene->m_camera->is_moving();
        m_scene->m_camera->set_time_sampled(m_scene->m_has_motion);
    }

    // Shapes of every group, built once however often the group is placed.
    void build_groups() {
        m_group_shapes.resize(m_desc.groups.size());
        m_prototype.assign(m_desc.groups.size(), -1);
        for (size_t g = 0; g < m_desc.groups.size(); ++g) {
            for (const Params& p : m_desc.groups[g].shapes) {
                if (p.type() == "solid") {
                    BuiltSolid built = build_solid(m_desc, p.get_ref("solid", "solid").index, p,
                                                   m_scene->m_materials, m_settings.csg_shortcuts);
                    m_group_shapes[g].push_back(
                        {built.shape.get(), std::move(built.part_materials), &p});
                    m_scene->m_shapes.push_back(std::move(built.shape));
                    continue;
                }
                const ObjectRef ref = p.get_ref("material", "material");
                const Material* material = shape_material(p, ref.index);
                auto shape = make_shape(p, {m_desc.directory, &m_desc.meshes, load_mesh_file});
                m_group_shapes[g].push_back({shape.get(), {material}, &p});
                m_scene->m_shapes.push_back(std::move(shape));
            }
        }
    }

    void place_root() {
        std::vector<int> path{0};
        for (const ShapeUse& use : m_group_shapes[0]) {
            const unsigned id = m_scene->m_accel.add_shape(-1, *use.shape);
            if (only_bounds_media(use)) m_scene->m_accel.set_pass_through(id);
            if (has_interface_part(use) &&
                !(only_bounds_media(use) && use.shape->triangle_count() > 0))
                m_scene->m_interfaces_skippable = false;
            Scene::WorldEntry& entry = world_entry(id);
            entry.geometry = {use.shape, use.materials};
            entry.side_from_hit = use.shape->hit_normal_sides_as_geometric();
            note_deformation(use, "");
            entry.light = make_area_light(use, Transform());
            count_shape(use, Transform());
        }
        for (const InstanceDesc& instance : m_desc.groups[0].instances)
            place(instance, MotionTransform(), path);
    }

    // Where a placement puts its group: parent * transform * motion keys, keywise.
    static MotionTransform placement(const InstanceDesc& instance, const MotionTransform& parent) {
        if (!parent.is_moving() && instance.motion.empty())
            return MotionTransform(parent.key(0) * instance.transform);
        std::vector<Transform> keys = instance.motion;
        if (keys.empty()) keys.push_back(Transform());
        for (Transform& key : keys) key = instance.transform * key;
        try {
            return parent * MotionTransform(std::move(keys));
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}", instance.where, e.what()));
        }
    }

    // Places group `instance.group` at `parent * instance.transform` (moving with its motion
    // keys and its parent's), then its own children. Embree supports one instance level, so
    // nested placements are flattened here.
    void place(const InstanceDesc& instance, const MotionTransform& parent,
               std::vector<int>& path) {
        const int g = instance.group;
        // The walk recurses once per level: a bounded depth keeps it off the stack's end.
        if (path.size() > kMaxGroupDepth) {
            throw Error(fmt::format("{}: groups are placed inside each other more than {} deep",
                                    instance.where, kMaxGroupDepth));
        }
        if (++m_placements > kMaxPlacements) {
            throw Error(
                fmt::format("{}: the scene places groups more than {} times in all (a "
                            "group placed twice in a group placed twice, ... doubles "
                            "each level)",
                            instance.where, kMaxPlacements));
        }
        if (std::find(path.begin(), path.end(), g) != path.end())
            throw Error(fmt::format("{}: a group cannot contain itself", instance.where));
        const MotionTransform motion = placement(instance, parent);
        const Transform& to_world = motion.key(0);
        if (!m_group_shapes[g].empty()) {
            const unsigned id = motion.is_moving()
                                    ? m_scene->m_accel.add_instance(prototype_of(g), motion)
                                    : m_scene->m_accel.add_instance(prototype_of(g), to_world);
            Scene::WorldEntry& entry = world_entry(id);
            entry.group = m_prototype[g];
            entry.to_world = to_world;
            if (motion.is_moving()) {
                entry.motion = motion;
                m_scene->m_has_motion = true;
            }
            for (const ShapeUse& use : m_group_shapes[g]) {
                // Embree skips interfaces in the world scene only.
                if (has_interface_part(use)) m_scene->m_interfaces_skippable = false;
                if (motion.is_moving() && is_emitter(use)) {
                    use.params->fail(
                        fmt::format("an emitting shape cannot move (placed moving at {}): "
                                    "area lights stand still in glint",
                                    instance.where));
                }
                note_deformation(use, instance.where);
                entry.lights.push_back(make_area_light(use, to_world));
                count_shape(use, motion);
            }
            ++m_scene->m_stats.instances;
        }
        path.push_back(g);
        for (const InstanceDesc& child : m_desc.groups[g].instances) place(child, motion, path);
        path.pop_back();
    }

    struct ShapeUse {
        const Shape* shape;
        std::vector<const Material*> materials;  // per part
        const Params* params;
    };

    // A shape all of whose parts are interfaces: walks that carry a medium pass it in the
    // traversal that finds what lies beyond (Scene::intersect_surface_passing).
    static bool only_bounds_media(const ShapeUse& use) {
        return !use.materials.empty() &&
               std::all_of(use.materials.begin(), use.materials.end(),
                           [](const Material* m) { return m && m->is_interface(); });
    }

    static bool has_interface_part(const ShapeUse& use) {
        return std::any_of(use.materials.begin(), use.materials.end(),
                           [](const Material* m) { return m && m->is_interface(); });
    }

    int prototype_of(int group) {
        if (m_prototype[group] >= 0) return m_prototype[group];
        const int id = m_scene->m_accel.add_prototype();
        m_scene->m_group_geometry.emplace_back();
        for (const ShapeUse& use : m_group_shapes[group]) {
            const unsigned local = m_scene->m_accel.add_shape(id, *use.shape);
            auto& geometry = m_scene->m_group_geometry[id];
            if (geometry.size() <= local) geometry.resize(local + 1);
            geometry[local] = {use.shape, use.materials};
        }
        ++m_scene->m_stats.groups;
        return m_prototype[group] = id;
    }

    Scene::WorldEntry& world_entry(unsigned id) {
        if (m_scene->m_world.size() <= id) m_scene->m_world.resize(id + 1);
        return m_scene->m_world[id];
    }

    // A deforming shape makes the scene one that moves (rays draw times); an emitting one
    // is refused, as a moving emitter is. `placed_at`: the placement's line, if any.
    void note_deformation(const ShapeUse& use, const std::string& placed_at) {
        if (!use.shape->deforms()) return;
        if (is_emitter(use)) {
            use.params->fail(
                fmt::format("an emitting shape cannot deform{}: area lights keep "
                            "their form in glint",
                            placed_at.empty() ? "" : " (placed at " + placed_at + ")"));
        }
        m_scene->m_has_motion = true;
    }

    static bool is_emitter(const ShapeUse& use) {
        return std::any_of(use.materials.begin(), use.materials.end(),
                           [](const Material* m) { return m->is_emissive(); });
    }

    const Light* make_area_light(const ShapeUse& use, const Transform& to_world) {
        const Material* emitter = nullptr;
        for (const Material* m : use.materials) {
            if (m->is_emissive()) emitter = m;
        }
        if (!emitter) return nullptr;
        std::unique_ptr<ShapeSampler> sampler;
        try {
            sampler = use.shape->make_sampler(to_world);
        } catch (const Error& e) {
            use.params->fail(e.what());
        }
        if (!emitter->emits_two_sided())
            m_one_sided_lights.push_back({sampler.get(), use.params->where()});
        m_scene->m_lights.push_back(std::make_unique<AreaLight>(
            std::move(sampler), emitter->emission(), emitter->emits_two_sided()));
        return m_scene->m_lights.back().get();
    }

    // A one-sided emitter lights only what lies in front of it; one wound the wrong way
    // (a quad whose corners go round clockwise seen from the room) lights nothing and
    // renders black without an error. Warned of when the whole scene's box lies behind
    // the emitter's tangent plane at every one of a few points on it (so a closed
    // emitter, a sphere, which has the scene on both sides of some tangent plane, never
    // is).
    void warn_of_lights_facing_away() {
        const Bounds3& bounds = m_scene->m_stats.bounds;
        if (bounds.is_empty()) return;
        for (const OneSidedLight& light : m_one_sided_lights) {
            bool faces_something = false;
            for (int i = 0; i < 4 && !faces_something; ++i) {
                const Vec2 u(0.25f + 0.5f * static_cast<float>(i & 1),
                             0.25f + 0.5f * static_cast<float>(i >> 1));
                const ShapeSample point = light.sampler->sample_area(u, 0.5f);
                for (int corner = 0; corner < 8; ++corner) {
                    const Vec3 c((corner & 1) ? bounds.max.x : bounds.min.x,
                                 (corner & 2) ? bounds.max.y : bounds.min.y,
                                 (corner & 4) ? bounds.max.z : bounds.min.z);
                    const float scale = 1e-4f * glm::length(bounds.extent());
                    if (glm::dot(c - point.p, point.n) > scale) faces_something = true;
                }
            }
            if (!faces_something) {
                m_scene->m_stats.warnings.push_back(fmt::format(
                    "{}: this one-sided emitter faces away from the whole scene and lights "
                    "nothing (reverse its winding, or make it two-sided)",
                    light.where));
            }
        }
    }

    struct OneSidedLight {
        const ShapeSampler* sampler;  // owned by the light
        std::string where;            // the script line that made it
    };
    std::vector<OneSidedLight> m_one_sided_lights;

    void count_shape(const ShapeUse& use, const Transform& to_world) {
        SceneStats& stats = m_scene->m_stats;
        ++stats.shapes;
        stats.triangles += use.shape->triangle_count();
        stats.bounds.expand(use.shape->bounds().transformed(to_world));
    }
    void count_shape(const ShapeUse& use, const MotionTransform& to_world) {
        if (!to_world.is_moving()) return count_shape(use, to_world.key(0));
        SceneStats& stats = m_scene->m_stats;
        ++stats.shapes;
        stats.triangles += use.shape->triangle_count();
        stats.bounds.expand(to_world.bounds_of_keys(use.shape->bounds()));
    }

    const SceneDesc& m_desc;
    const RenderSettings& m_settings;
    std::unique_ptr<Scene> m_scene;
    std::vector<std::vector<ShapeUse>> m_group_shapes;
    std::vector<int> m_prototype;
    size_t m_placements = 0;
};

std::unique_ptr<Scene> build_scene(const SceneDesc& desc, const RenderSettings& settings) {
    return SceneBuilder(desc, settings).build();
}

}  // namespace glint
