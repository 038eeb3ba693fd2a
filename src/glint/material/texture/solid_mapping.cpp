#include <glint/material/texture/solid_mapping.h>

namespace glint {

SolidMapping::SolidMapping(const Transform& placement, const Vec3& scale)
    : m_object_to_pattern(Transform::scale(scale).matrix() * placement.inverse_matrix()) {}

Vec3 SolidMapping::map_point(const Vec3& p_object) const {
    return Vec3(m_object_to_pattern * Vec4(p_object, 1.0f));
}

SolidMapping read_solid_mapping(const Params& params) {
    const Transform placement = params.get_transform("transform");
    Vec3 scale(1.0f);
    if (params.has("scale")) {
        const std::vector<double> values = params.get_numbers("scale");
        if (values.size() == 1)
            scale = Vec3(static_cast<float>(values[0]));
        else if (values.size() == 3)
            scale = Vec3(values[0], values[1], values[2]);
        else
            params.fail("'scale' must be a number or {sx, sy, sz}");
        if (!is_finite(scale) || scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f)
            params.fail("'scale' must be finite and not zero");
    }
    return SolidMapping(placement, scale);
}

}  // namespace glint
