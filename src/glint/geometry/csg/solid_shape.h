#pragma once
// Puts a Solid (a primitive or a whole CSG tree) into the scene as an Embree user
// geometry. The first boundary crossing after the ray's start is the hit; its part index
// selects the material of the primitive whose surface it is.
#include <glint/geometry/csg/solid.h>
#include <glint/geometry/shape.h>

#include <optional>

namespace glint {

class SolidShape final : public Shape {
public:
    // Throws glint::Error when the solid is unbounded.
    SolidShape(std::shared_ptr<const Solid> solid, std::string name);

    std::string name() const override { return m_name; }
    Bounds3 bounds() const override { return m_bounds; }
    RTCGeometry create_embree_geometry(RTCDevice device) const override;
    void fill_interaction(const Ray& ray, const HitRecord& hit,
                          SurfaceInteraction& si) const override;
    std::unique_ptr<ShapeSampler> make_sampler(const Transform& to_world) const override;

    const Solid& solid() const { return *m_solid; }
    // The first crossing of `ray` after ray.t_min and before ray.t_max, if any.
    std::optional<Crossing> first_hit(const Ray& ray) const;
    bool any_hit(const Ray& ray) const;

private:
    std::shared_ptr<const Solid> m_solid;
    std::string m_name;
    Bounds3 m_bounds;
};

}  // namespace glint
