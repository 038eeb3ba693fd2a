#include <glint/camera/camera_attributes.h>
#include <glint/core/error.h>
#include <glint/core/strict_number.h>

#include <fmt/format.h>

#include <cstdio>

namespace glint {
namespace {

std::string vec3_text(const Vec3& v) {
    return fmt::format("{:.9g},{:.9g},{:.9g}", v.x, v.y, v.z);
}

const std::string* find(const ImageAttributes& attributes, const std::string& name) {
    for (const auto& [key, value] : attributes)
        if (key == name) return &value;
    return nullptr;
}

}  // namespace

std::optional<Vec3> parse_vec3(const std::string& text) {
    Vec3 v;
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t end = i < 2 ? text.find(',', start) : text.size();
        if (end == std::string::npos) return std::nullopt;
        const std::optional<double> value = parse_finite(text.substr(start, end - start));
        if (!value) return std::nullopt;
        v[i] = static_cast<float>(*value);
        start = end + 1;
    }
    return v;
}

ImageAttributes camera_attributes(const Params* camera, Vec2i resolution) {
    // The defaults are make_camera's.
    const Params defaults("camera", "default camera");
    const Params& p = camera ? *camera : defaults;
    const std::string type = p.get_string("type", "perspective");
    ImageAttributes attributes = {
        {"camera.type", type},
        {"camera.eye", vec3_text(p.get_vec3("eye", Vec3(0, 0, 0)))},
        {"camera.look_at", vec3_text(p.get_vec3("look_at", Vec3(0, 0, -1)))},
        {"camera.up", vec3_text(p.get_vec3("up", Vec3(0, 1, 0)))},
        {"camera.resolution", fmt::format("{}x{}", resolution.x, resolution.y)}};
    if (type == "orthographic")
        attributes.emplace_back("camera.scale", fmt::format("{:.9g}", p.get_float("scale", 2.0f)));
    else
        attributes.emplace_back("camera.fov", fmt::format("{:.9g}", p.get_float("fov", 45.0f)));
    return attributes;
}

std::optional<StoredCamera> camera_from_attributes(const ImageAttributes& attributes,
                                                   const std::string& where) {
    const std::string* type = find(attributes, "camera.type");
    if (!type) return std::nullopt;
    auto bad = [&](const std::string& what) {
        return Error(fmt::format("{}: the attribute glint:camera.{} is malformed", where, what));
    };
    StoredCamera stored{Params("camera", where), Vec2i(0)};
    stored.params.set("type", *type);
    for (const char* name : {"eye", "look_at", "up"}) {
        const std::string* text = find(attributes, fmt::format("camera.{}", name));
        const std::optional<Vec3> v = text ? parse_vec3(*text) : std::nullopt;
        if (!v) throw bad(name);
        stored.params.set(name, numbers_of(*v));
    }
    const char* size_name = *type == "orthographic" ? "scale" : "fov";
    const std::string* size = find(attributes, fmt::format("camera.{}", size_name));
    const std::optional<double> size_value = size ? parse_finite(*size) : std::nullopt;
    if (!size_value) throw bad(size_name);
    stored.params.set(size_name, *size_value);
    const std::string* resolution = find(attributes, "camera.resolution");
    if (!resolution ||
        std::sscanf(resolution->c_str(), "%dx%d", &stored.resolution.x, &stored.resolution.y) !=
            2 ||
        stored.resolution.x <= 0 || stored.resolution.y <= 0)
        throw bad("resolution");
    return stored;
}

}  // namespace glint
