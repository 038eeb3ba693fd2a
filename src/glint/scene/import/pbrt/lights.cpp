// pbrt-v4 lights to glint's. pbrt-v4 divides every light's spectrum by its luminance
// (SpectrumToPhotometric) before applying "scale", "power" or "illuminance"; for an RGB
// value only the colour space's illuminant counts, which for sRGB is D65, glint's white: an
// RGB emission keeps its value. A blackbody or spectrum is reduced to the colour of
// luminance 1 (spectra.h). See docs/scene-language.md, "pbrt-v4 files".
#include <glint/core/error.h>
#include <glint/scene/import/pbrt/translator.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {


}  // namespace

Vec3 PbrtTranslator::emission(const PbrtEntity& e, const char* name) {
    const std::optional<PbrtValue> v = colour(e, name, SpectrumUse::Illuminant);
    if (!v) return Vec3(1.0f);  // the colour space's illuminant, of luminance 1
    if (v->is_texture())
        throw Error(fmt::format("{}: \"{}\" cannot be a texture for a light", e.where.str(), name));
    if (glm::any(glm::lessThan(v->constant, Vec3(0.0f))))
        throw Error(fmt::format("{}: \"{}\" must not be negative", e.where.str(), name));
    return v->constant;
}

void PbrtTranslator::light(const PbrtLight& l) {
    const PbrtEntity& e = l.entity;
    const Mat4 to_world = m_target.transform.matrix() * m_mirror * l.to_world;
    auto point = [&](const Vec3& p) { return Vec3(to_world * Vec4(p, 1.0f)); };
    const double scale = e.params.get_float("scale", 1.0) * m_imaging_ratio * m_target.light_scale.value_or(1.0f);
    const double power = e.params.get_float("power", -1.0);
    Params p;
    if (e.type == "point") {
        const Vec3 intensity = emission(e, "I");
        const double k = power > 0.0 ? power / (4.0 * kPi) : 1.0;
        p = Params("point_light", where(e.where));
        p.set("position", numbers_of(point(e.params.get_vec3("from", Vec3(0.0f)))));
        p.set("intensity", numbers_of(intensity * static_cast<float>(scale * k)));
    } else if (e.type == "spot") {
        const Vec3 intensity = emission(e, "I");
        double cone = e.params.get_float("coneangle", 30.0);
        const double delta = e.params.get_float("conedeltaangle", 5.0);
        const double cos_end = std::cos(glm::radians(cone));
        const double cos_start = std::cos(glm::radians(cone - delta));
        const double k =
            power > 0.0 ? power / (2.0 * kPi * ((1.0 - cos_start) + (cos_start - cos_end) / 2.0))
                        : 1.0;
        if (!(cone > 0.0 && cone <= 90.0)) {
            warn(e.where, "LightSource", "spot: \"coneangle\" outside (0, 90] is clamped");
            cone = std::clamp(cone, 1e-3, 90.0);
        }
        p = Params("spot_light", where(e.where));
        p.set("position", numbers_of(point(e.params.get_vec3("from", Vec3(0.0f)))));
        p.set("look_at", numbers_of(point(e.params.get_vec3("to", Vec3(0, 0, 1)))));
        p.set("intensity", numbers_of(intensity * static_cast<float>(scale * k)));
        p.set("cone_angle", cone);
        p.set("falloff_start", std::clamp(cone - delta, 0.0, cone));
    } else if (e.type == "distant") {
        const Vec3 radiance = emission(e, "L");
        const double illuminance = e.params.get_float("illuminance", -1.0);
        const Vec3 from = e.params.get_vec3("from", Vec3(0.0f));
        const Vec3 to = e.params.get_vec3("to", Vec3(0, 0, 1));
        const Vec3 direction(to_world * Vec4(to - from, 0.0f));
        if (glm::length(direction) == 0.0f)
            throw Error(
                fmt::format("{}: distant: \"from\" and \"to\" are the same point", e.where.str()));
        p = Params("directional_light", where(e.where));
        p.set("direction", numbers_of(direction));
        p.set("irradiance",
              numbers_of(radiance *
                         static_cast<float>(scale * (illuminance > 0 ? illuminance : 1.0))));
    } else if (e.type == "infinite") {
        infinite_light(e, to_world, scale);
        check_unused(e, "LightSource");
        return;
    } else {
        warn(e.where, "LightSource",
             fmt::format("light \"{}\" is not supported (ignored)", e.type));
        ++m_skipped["lights"];
        for (const PbrtParam& param : e.params.all()) param.used = true;
        return;
    }
    check_unused(e, "LightSource");
    m_desc.lights.push_back(std::move(p));
}

void PbrtTranslator::infinite_light(const PbrtEntity& e, const Mat4& to_world, double scale) {
    const double illuminance = e.params.get_float("illuminance", -1.0);
    if (e.params.has("portal"))
        warn(e.where, "LightSource", "infinite: \"portal\" is not supported (ignored)");
    const std::string file = e.params.get_string("filename", "");
    if (!file.empty()) {
        environment_map(e, file, to_world, scale);
        if (illuminance > 0)
            warn(e.where, "LightSource",
                 "infinite: \"illuminance\" with an image is not supported");
        return;
    }
    // A constant radiance L gives illuminance pi L on an upward-facing patch.
    const Vec3 radiance =
        emission(e, "L") * static_cast<float>(scale * (illuminance > 0 ? illuminance / kPi : 1.0));
    if (has_infinite_light()) {
        warn(e.where, "LightSource", "a second infinite light is not supported (ignored)");
        ++m_skipped["lights"];
        return;
    }
    Params p("background", where(e.where));
    p.set("radiance", numbers_of(radiance));
    m_desc.background = std::move(p);
}

bool PbrtTranslator::has_infinite_light() const {
    if (m_desc.background) return true;
    for (const Params& p : m_desc.lights)
        if (p.type() == "environment") return true;
    return false;
}

std::optional<ObjectRef> PbrtTranslator::area_light_material(const PbrtEntity& area,
                                                             double area_of_shape) {
    if (area.type != "diffuse") {
        warn(
            area.where, "AreaLightSource",
            fmt::format("area light \"{}\" is not supported (the shape does not emit)", area.type));
        ++m_skipped["area lights"];
        return std::nullopt;
    }
    if (area.params.has("filename")) {
        warn(area.where, "AreaLightSource", "an emission image is not supported (L is used)");
        area.params.find("filename");
    }
    const bool two_sided = area.params.get_bool("twosided", false);
    const double scale =
        area.params.get_float("scale", 1.0) * m_imaging_ratio * m_target.light_scale.value_or(1.0f);
    const double power = area.params.get_float("power", -1.0);
    // pbrt-v4 sets the radiance so that the shape emits `power` watts: pi * area per side.
    const double k = power > 0.0 && area_of_shape > 0.0
                         ? power / ((two_sided ? 2.0 : 1.0) * area_of_shape * kPi)
                         : 1.0;
    Params p("emissive", where(area.where));
    p.set("radiance", numbers_of(emission(area, "L") * static_cast<float>(scale * k)));
    if (two_sided) p.set("two_sided", true);
    check_unused(area, "AreaLightSource");
    m_desc.materials.push_back(std::move(p));
    return ObjectRef{"material", static_cast<int>(m_desc.materials.size()) - 1};
}

}  // namespace glint
