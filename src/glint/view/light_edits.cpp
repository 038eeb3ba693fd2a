#include <glint/light/registry.h>
#include <glint/material/registry.h>
#include <glint/math/transform.h>
#include <glint/view/light_edits.h>

#include <fmt/format.h>

namespace glint {
namespace {

// Scales the spectrum under `key` (1 when the scene left it out).
void scale_power(Params& params, const std::string& key, float scale) {
    if (scale == 1.0f) return;
    // A copy reads the value, so the original's record of used keys stays as it was.
    const Params read = params;
    params.set(key, numbers_of(read.get_rgb(key, Rgb(1.0f)) * scale), params.where_of(key));
}

// The material of a world shape (always a handle after loading), or null: a solid's parts
// carry their own materials, and those are not offered.
const Params* shape_material(const SceneDesc& desc, const Params& shape) {
    if (shape.is_ref("solid", "solid") || !shape.is_ref("material", "material")) return nullptr;
    const Params copy = shape;
    const ObjectRef ref = copy.get_ref("material", "material");
    if (ref.index < 0 || static_cast<size_t>(ref.index) >= desc.materials.size()) return nullptr;
    return &desc.materials[ref.index];
}

// Whether a world shape emits: its material says it emits light (material_emission_key).
bool emissive_shape(const SceneDesc& desc, const Params& shape) {
    const Params* material = shape_material(desc, shape);
    return material && !material_emission_key(material->type()).empty();
}

// "file.lua:12" of a script location, without the directories: the panel is narrow.
std::string short_where(const std::string& where) {
    const size_t slash = where.rfind('/');
    return slash == std::string::npos ? where : where.substr(slash + 1);
}

}  // namespace

LightEdits::LightEdits(const SceneDesc& desc) {
    for (size_t i = 0; i < desc.lights.size(); ++i) {
        const Params& p = desc.lights[i];
        EditableLight light;
        light.name = fmt::format("{} ({})", p.type(), short_where(p.where()));
        light.movable = !light_editing(p.type()).position_keys.empty();
        m_lights.push_back(light);
        m_sources.push_back({false, i});
    }
    const std::vector<Params>& shapes = desc.groups.front().shapes;
    for (size_t i = 0; i < shapes.size(); ++i) {
        if (!emissive_shape(desc, shapes[i])) continue;
        EditableLight light;
        light.name =
            fmt::format("emissive {} ({})", shapes[i].type(), short_where(shapes[i].where()));
        light.movable = true;
        m_lights.push_back(light);
        m_sources.push_back({true, i});
    }
}

SceneDesc LightEdits::apply(const SceneDesc& original) const {
    SceneDesc desc = original;
    for (size_t i = 0; i < m_lights.size(); ++i) {
        const EditableLight& light = m_lights[i];
        const Source& source = m_sources[i];
        const bool moved = light.movable && light.offset != Vec3(0.0f);
        if (!source.shape) {
            Params& p = desc.lights[source.index];
            const LightEditing editing = light_editing(p.type());
            scale_power(p, editing.power_key, light.power_scale);
            if (!moved) continue;
            const Params read = p;
            for (const std::string& key : editing.position_keys) {
                if (read.has(key))
                    p.set(key, numbers_of(read.get_vec3(key) + light.offset), p.where_of(key));
            }
            continue;
        }
        Params& shape = desc.groups.front().shapes[source.index];
        if (light.power_scale != 1.0f) {
            const Params read = shape;
            Params material = desc.materials[read.get_ref("material", "material").index];
            scale_power(material, material_emission_key(material.type()), light.power_scale);
            desc.materials.push_back(material);
            shape.set("material",
                      ObjectRef{"material", static_cast<int>(desc.materials.size() - 1)});
        }
        if (moved) {
            const Params read = shape;
            shape.set("transform",
                      Transform::translate(light.offset) * read.get_transform("transform"));
        }
    }
    return desc;
}

}  // namespace glint
